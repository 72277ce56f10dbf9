# lm.mk — Levenberg–Marquardt and the fitting interface (issue 4).
#
#   check-lm   the `tissuefit lm-strd` command line (good, CRLF and LF files,
#              missing and damaged files, bad --start); the 54 NIST StRD runs
#              and the 53 MGH runs themselves are the unit tests
#              tests/unit/numerics/test_lm_nist.c and test_lm_mgh.c (check-unit)
#   bench-lm   the 54 NIST runs and the 53 Moré–Garbow–Hillstrom runs with
#              tissuefit and with GSL multifit_nlinear, side by side (GSL is
#              needed only here: DEBS_BENCH)
#   lm-table   the NIST and Moré–Garbow–Hillstrom tables and studies of
#              docs/lm.md, as Markdown

LM_T := $(B)/tests/lm
DEBS_BENCH += libgsl-dev

.PHONY: check-lm bench-lm lm-table
CHECKS += check-lm
BENCHES += bench-lm

# Missing NIST data is a failure, not a skip: both tests are first run
# against a directory that does not exist and must fail saying so.
check-lm: $(B)/bin/tissuefit $(T)/unit/numerics/test_lm_nist
	@echo "== lm-strd command line =="
	@if NIST_DIR=$(B)/no-nist tests/lm/cli_lm.sh $(B)/bin/tissuefit >$(B)/no-nist.log 2>&1 || \
	    ! grep -q "no-nist is absent" $(B)/no-nist.log; then \
	  echo "cli_lm.sh did not fail on a missing NIST directory:"; cat $(B)/no-nist.log; exit 1; fi
	@if TF_NIST_DIR=$(B)/no-nist $(T)/unit/numerics/test_lm_nist >$(B)/no-nist.log 2>&1 || \
	    ! grep -q "no-nist is absent" $(B)/no-nist.log; then \
	  echo "test_lm_nist did not fail on a missing NIST directory:"; cat $(B)/no-nist.log; exit 1; fi
	@echo "without the NIST files both tests fail: ok"
	@tests/lm/cli_lm.sh $(B)/bin/tissuefit

$(LM_T)/strd_table: tests/lm/strd_table.c $(B)/native/libtissuefit-host.a | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_CFLAGS) -O2 $< $(B)/native/libtissuefit-host.a $(HOST_LIBS) -o $@

$(LM_T)/mgh_table: tests/lm/mgh_table.c $(B)/native/libtissuefit-host.a | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_CFLAGS) -O2 $< $(B)/native/libtissuefit-host.a $(HOST_LIBS) -o $@

lm-table: $(LM_T)/strd_table $(LM_T)/mgh_table
	@$<
	@echo
	@$< --finite-diff --summary
	@$< --central-diff --summary
	@for f in 0.01 0.1 10 100; do $< --factor $$f --summary; done
	@echo
	@$(LM_T)/mgh_table
	@echo
	@for s in up down alternate; do $(LM_T)/mgh_table --scale $$s --summary; done

$(LM_T)/bench_gsl: tests/lm/bench_gsl.c tests/lm/bench_time.c $(B)/native/libtissuefit-host.a | deps-bench
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_CFLAGS) -O2 $< tests/lm/bench_time.c $(B)/native/libtissuefit-host.a -lgsl $(HOST_LIBS) -o $@

$(LM_T)/bench_mgh_gsl: tests/lm/bench_mgh_gsl.c tests/lm/bench_time.c $(B)/native/libtissuefit-host.a | deps-bench
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_CFLAGS) -O2 $< tests/lm/bench_time.c $(B)/native/libtissuefit-host.a -lgsl $(HOST_LIBS) -o $@

bench-lm: $(LM_T)/bench_gsl $(LM_T)/bench_mgh_gsl
	@echo "== LM: tissuefit against GSL multifit_nlinear, NIST StRD (54 runs) =="
	@$(LM_T)/bench_gsl
	@echo "== LM: tissuefit against GSL multifit_nlinear, Moré-Garbow-Hillstrom (53 runs) =="
	@$(LM_T)/bench_mgh_gsl
