# mpi.mk — issue 18: the fit spread over MPI ranks (host/dist/, docs/scaling.md).
#
#   check-mpi   tissuefit-mpi on 1, 2 and 3 ranks (oversubscribed) writes the
#               serial tool's bytes: for a nonlinear scene (neo-Hookean
#               block48, a few cases, the real tools), and for a scene whose
#               cases are all solved one by one by a solver variant whose
#               answer depends on where each case starts
#               (tests/mpi/variant_solver.c), with the counter-tests below;
#               the comparison is shown a one-ulp change on one rank first; a
#               rank that fails, and a case that fails, stop the run (exit 1,
#               case and rank named, nothing written); dist/ keeps no global
#               state.
#   bench-mpi   (make bench) speed-up of 2 ranks against 1 on the same scene.

MPI_T := $(T)/mpi
# The solver variant wraps tf_solver_create in test builds of both tools.
VARIANT_LINK := -Wl,--wrap=tf_solver_create

$(MPI_T)/variant_solver.o: tests/mpi/variant_solver.c $(HOST_HDR) | deps-build
	@mkdir -p $(@D)
	$(call say,CC)
	$(Q)$(CC) $(HOST_CFLAGS) -O2 -c $< -o $@

$(MPI_T)/tissuefit-variant: $(B)/native/host/cli/main.o $(MPI_T)/variant_solver.o \
    $(B)/native/libtissuefit-host.a $(B)/native/libtfit.a
	$(call say,LINK)
	$(Q)$(CC) $(VARIANT_LINK) $^ $(HOST_LIBS) -o $@

$(MPI_T)/tissuefit-mpi-variant: $(DIST_OBJ) $(MPI_T)/variant_solver.o \
    $(B)/native/libtissuefit-host.a $(B)/native/libtfit.a | deps-mpi
	$(call say,LINK)
	$(Q)$(CC) $(VARIANT_LINK) $^ $(HOST_LIBS) $(MPI_LIBS) -o $@

# block48 with few cases: 12 training, 6 held-out, 3 x 12 single-axis and
# 15 seed-table cases, 69 in all, every one solved.
MPI_SCENE := tests/solver/block48_seed.yaml
MPI_SETS := --set fit.train=12 --set fit.heldout=6 --set fit.max_degree=2 --set fit.max_rank=4
# The same scene with the neo-Hookean law (the Newton solver): every case a
# nonlinear solve, continued from its nearest solved case.  Without the
# self-measured discretisation (six Newton solves on each of three clouds,
# 3.4 s a fit, none of them spread over ranks): the linear run above states
# it, and must give the serial tool's bytes on every rank count with it.
MPI_NL_SETS := --set material.law=neo-hookean --set fit.train=8 --set fit.heldout=4 \
  --set fit.max_degree=1 --set fit.max_rank=3 --no-discretisation

.PHONY: check-mpi
CHECKS += check-mpi
check-mpi: $(B)/bin/tissuefit $(B)/bin/tissuefit-mpi $(MPI_T)/tissuefit-variant \
    $(MPI_T)/tissuefit-mpi-variant | deps-mpi
	@echo "== tissuefit-mpi: the serial tool's bytes on 1, 2 and 3 ranks; failures stop the run =="
	@tests/layers/check_globals.sh $(DIST_OBJ)
	@OMP_NUM_THREADS=1 tests/mpi/mpi_fit.sh $(B)/bin/tissuefit $(B)/bin/tissuefit-mpi \
	  $(MPI_SCENE) $(MPI_NL_SETS)
	@VARIANT=1 OMP_NUM_THREADS=1 tests/mpi/mpi_fit.sh $(MPI_T)/tissuefit-variant \
	  $(MPI_T)/tissuefit-mpi-variant $(MPI_SCENE) $(MPI_SETS)

# Speed-up on a scene of 53 nonlinear cases: neo-Hookean block48 at the
# seed's grid, 8 training and 6 held-out cases.  --bind-to none: on this
# shared 2-core machine mpirun's default binding starved one rank
# (docs/scaling.md §2).
MPI_BENCH_SETS := --set material.law=neo-hookean --set fit.train=8 --set fit.heldout=6 \
                  --set fit.max_degree=3 --set fit.max_rank=4
.PHONY: bench-mpi
BENCHES += bench-mpi
bench-mpi: $(B)/bin/tissuefit $(B)/bin/tissuefit-mpi | deps-mpi
	@echo "== fit spread over MPI ranks: 2 ranks against 1 (one thread each), medians =="
	@MPIRUN="mpirun --bind-to none" tests/mpi/bench_mpi.sh $(B)/bin/tissuefit \
	  $(B)/bin/tissuefit-mpi $(MPI_SCENE) $(MPI_BENCH_SETS)
