# nonlinear.mk — the nonlinear and viscoelastic Galerkin solver (issue 13):
# studies behind their own targets, with committed results.
#
#   nonlinear-validation   docs/validation/nonlinear/: the homogeneous tests
#                          against closed forms (RPIM and EFG), the EFG patch
#                          test and cantilever, the weak boundary conditions
#                          compared; tables and plots of docs/validation.md §8
# Unit tests (tests/unit/solvers/test_{nonlinear,weak_bc,homogeneous}.c,
# tests/unit/problem/test_history.c) run with
# check-unit and check-sanitize.

NL_TOOLS := $(T)/solver/homogeneous $(T)/solver/block48_curves $(T)/solver/bench_nonlinear

$(T)/solver/homogeneous: tests/solver/homogeneous.c tests/support/homogeneous.c $(B)/native/libtissuefit-host.a | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -O2 $(filter %.c,$^) $(B)/native/libtissuefit-host.a $(HOST_LIBS) -o $@

.PHONY: nonlinear-validation
nonlinear-validation: $(B)/bin/tissuefit $(NL_TOOLS) | deps-validation
	@tests/solver/nonlinear_validation.sh $(B)/bin/tissuefit $(T)/solver docs/validation/nonlinear

.PHONY: check-nonlinear-cli
CHECKS += check-nonlinear-cli
check-nonlinear-cli: $(B)/bin/tissuefit
	@echo "== tissuefit solve with nonlinear laws and load histories =="
	@tests/solver/nonlinear_cli.sh $(B)/bin/tissuefit

# make bench: Newton iterations per load step and time per nonlinear case at
# the seed's grid and at 41 x 41 x 9, against one linear solve in the same run
# (NL_GRIDS: GRID:REPS[:cases=N] entries; 41 x 41 x 9 takes minutes).
NL_GRIDS ?= 11,11,3:3 41,41,9:1:cases=2
.PHONY: bench-nonlinear
BENCHES += bench-nonlinear
bench-nonlinear: $(T)/solver/bench_nonlinear
	@echo "== nonlinear solver: block48 cases from rest (issue 13: 3 N neo-Hookean at 41x41x9 <= 3 x one linear solve) =="
	@for g in $(NL_GRIDS); do $(T)/solver/bench_nonlinear $${g//:/ } || exit 1; done

# The Newton tangent strategies (solver.newton.tangent) on the 3 N
# neo-Hookean case, each in its own process with its own linear solve
# (NL_TANGENT_GRIDS; results in docs/validation.md §13).
NL_TANGENT_GRIDS ?= 21,21,5 41,41,9
.PHONY: bench-nonlinear-tangents
bench-nonlinear-tangents: $(T)/solver/bench_nonlinear
	@echo "== nonlinear solver: full Newton, modified Newton, BFGS, Krylov on the 3 N neo-Hookean case =="
	@for g in $(NL_TANGENT_GRIDS); do for t in full modified bfgs krylov; do \
	  echo "-- $$g, tangent $$t"; \
	  $(T)/solver/bench_nonlinear $$g 1 cases=2 solver.newton.tangent=$$t || exit 1; done; done

# CHOLMOD's fill-reducing orderings on the linear stiffness (METIS twice: the
# same hash shows it is deterministic).
.PHONY: bench-ordering
BENCHES += bench-ordering
bench-ordering: $(T)/solver/bench_ordering
	@echo "== CHOLMOD orderings on block48 (analysis, factorisation, fill, flops, memory, same solution) =="
	@$(T)/solver/bench_ordering 21,21,5 amd metis nesdis metis
	@$(T)/solver/bench_ordering 41,41,9 amd metis nesdis
