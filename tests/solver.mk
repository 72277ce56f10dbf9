# solver.mk — scene files and the RPIM Galerkin solver (issue 3): checks,
# benchmarks and the validation report.
#
#   check-solver-cli      tissuefit solve / verify: outputs, exit statuses,
#                         nothing written on bad input
#   check-solver-calculix block48 against the CalculiX reference: the
#                         comparison's self-test, then 11x11x3 -> 21x21x5 ->
#                         41x41x9 (node 61 within 3 % at the finest level)
#   bench-solver          speed of block48 at three grids (medians), the
#                         time split and peak memory; 150 load cases
#   solver-validation     regenerates docs/validation/ (tables and PNG plots
#                         for docs/validation.md); not part of make check
# Unit tests (tests/unit/{scene,meshfree,materials,solvers,verify}/) run
# with check-unit and check-sanitize.

SOLVER_TOOLS := $(T)/solver/calculix_compare $(T)/solver/bench_solver $(T)/solver/node61
DEBS_VALIDATION := $(DEBS_BUILD) gnuplot-nox

.PHONY: check-solver-cli check-solver-calculix bench-solver solver-validation deps-validation
CHECKS += check-solver-cli check-solver-calculix
BENCHES += bench-solver

deps-validation: ; $(call ensure_debs,$(DEBS_VALIDATION))

$(T)/solver/%: tests/solver/%.c $(B)/native/libtissuefit-host.a | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -O2 $< $(B)/native/libtissuefit-host.a $(HOST_LIBS) -o $@

check-solver-cli: $(B)/bin/tissuefit
	@echo "== tissuefit solve and verify on the command line =="
	@tests/solver/cli.sh $(B)/bin/tissuefit

check-solver-calculix: $(B)/bin/tissuefit $(T)/solver/calculix_compare
	@echo "== block48 against the CalculiX reference =="
	@tests/solver/compare_selftest.sh $(B)/bin/tissuefit $(T)/solver/calculix_compare
	@$(T)/solver/calculix_compare
	@echo "ok: block48 converges to the CalculiX reference under refinement"

bench-solver: $(T)/solver/bench_solver
	@echo "== solver speed: block48 (GUIDE §7: <= 0.5 s at 11x11x3, <= 30 s at 41x41x9) =="
	@$(T)/solver/bench_solver 11,11,3 7
	@$(T)/solver/bench_solver 21,21,5 5
	@$(T)/solver/bench_solver 41,41,9 3

solver-validation: $(B)/bin/tissuefit $(SOLVER_TOOLS) | deps-validation
	@tests/solver/validation.sh $(B)/bin/tissuefit $(T)/solver docs/validation
