# solver.mk — scene files and the RPIM Galerkin solver (issue 3): checks,
# benchmarks and the validation report.
#
#   check-solver-cli      tissuefit solve / verify: outputs, exit statuses,
#                         nothing written on bad input
#   check-solver-calculix block48 against the CalculiX reference: the
#                         comparison's self-test, then with the defaults
#                         11x11x3 -> 21x21x5 -> 31x31x7 -> 41x41x9: node 61
#                         within 1 % at 41x41x9 in every case, the RMS error
#                         over the 121 points falling level by level
#                         (issue 21, acceptance 1)
#   bench-solver          speed of block48 at three grids (medians), the
#                         time split and peak memory; 150 load cases
#   bench-accuracy        time to bring block48's node 61 within 1 % and
#                         0.3 % of the reference: tissuefit (best cloud)
#                         against CalculiX C3D20R, and the ratio (minutes:
#                         CalculiX runs at two mesh levels)
#   solver-validation     regenerates docs/validation/ (tables and PNG plots
#                         for docs/validation.md); not part of make check
#   accuracy-study        the shape-parameter, support and grading study of
#                         docs/validation.md §7 (docs/validation/accuracy/,
#                         about an hour; ACCURACY_PARTS=... runs some parts)
# Unit tests (tests/unit/{scene,meshfree,materials,problem,solvers,verify}/)
# run with check-unit and check-sanitize.

SOLVER_TOOLS := $(T)/solver/calculix_compare $(T)/solver/bench_solver $(T)/solver/node61
DEBS_VALIDATION := $(DEBS_BUILD) gnuplot-nox

.PHONY: check-solver-cli check-solver-calculix bench-solver bench-accuracy solver-validation \
        deps-validation \
        accuracy-study
CHECKS += check-solver-cli check-solver-calculix
BENCHES += bench-solver bench-accuracy

deps-validation: ; $(call ensure_debs,$(DEBS_VALIDATION))

$(T)/solver/%: tests/solver/%.c $(B)/native/libtissuefit-host.a | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -O2 $< $(B)/native/libtissuefit-host.a $(HOST_LIBS) -o $@

check-solver-cli: $(B)/bin/tissuefit
	@echo "== tissuefit solve and verify on the command line =="
	@tests/solver/cli.sh $(B)/bin/tissuefit

check-solver-calculix: $(B)/bin/tissuefit $(T)/solver/calculix_compare
	@echo "== block48 against the CalculiX reference: four levels, node 61 within 1 % at 41x41x9 =="
	@tests/solver/compare_selftest.sh $(B)/bin/tissuefit $(T)/solver/calculix_compare
	@$(T)/solver/calculix_compare --levels "11,11,3;21,21,5;31,31,7;41,41,9" --max-err61 0.01
	@echo "ok: block48 within 1 % of the CalculiX reference at 41x41x9, RMS error falling over four levels"

bench-solver: $(T)/solver/bench_solver
	@echo "== solver speed: block48 (targets: <= 0.5 s at 11x11x3, <= 30 s at 41x41x9) =="
	@$(T)/solver/bench_solver 11,11,3 7
	@$(T)/solver/bench_solver 21,21,5 5
	@$(T)/solver/bench_solver 41,41,9 3

bench-accuracy: $(T)/solver/calculix_compare $(B)/calculix/block48_deck | deps-calculix
	@echo "== block48: time to 1 % and 0.3 % at node 61 in every case, tissuefit against CalculiX C3D20R =="
	@tests/solver/bench_accuracy.sh $(T)/solver/calculix_compare $(B)/calculix/block48_deck \
	  $(B)/bench/accuracy

solver-validation: $(B)/bin/tissuefit $(SOLVER_TOOLS) | deps-validation
	@tests/solver/validation.sh $(B)/bin/tissuefit $(T)/solver docs/validation

ACCURACY_PARTS ?=
accuracy-study: $(B)/bin/tissuefit $(T)/solver/calculix_compare | deps-validation
	@tests/solver/accuracy_study.sh $(B)/bin/tissuefit $(T)/solver/calculix_compare \
	  docs/validation/accuracy $(ACCURACY_PARTS)
