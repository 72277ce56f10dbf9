# stability.mk — issue 7, "stability at the extremes" (docs/stability.md).
#
#   check-stability-basis      item 1: raw-mm and normalised monomials against
#                              the target's Chebyshev basis in float32/float64,
#                              orders 1-8; prints the tables and asserts that
#                              the target's basis (both forms, evaluated by
#                              the target's code) loses < 1 digit in float32
#                              up to order 8 (docs/stability.md §1), and that
#                              the assertion fails on coefficients perturbed
#                              by 2^-20
#   check-stability-extremes   item 2: zero, subnormal, boundary, 10x and
#                              1e30x beyond, FLT_MAX, NaN, +-Inf on every
#                              model of every header, float32 and Q31
#   check-stability-random     item 5: 10^6 seeded random inputs per model
#                              and form, same invariants
#   check-stability-sanitize   the extremes and 20000 random inputs again,
#                              runner and library under ASan + UBSan
#   check-stability-models     the same invariants on STAB_MODELS random
#                              models of every family (tests/support), beyond
#                              the shipped headers
#   stability-plot             docs/stability_basis.png and the tables
#   bench-stability            (make bench) native ns per evaluation by kind
#                              of input: inside, subnormal, far, NaN
#
# Headers: linker/firmware.mk's FW_POINT_HEADERS (coeffs/*.h without *_golden.h
# and the contact regions', plus the generated test headers), so real headers
# are covered as they land.

STAB_T := $(T)/stability
# The checks and inputs every stability program links (each has its own main).
STAB_CHECK_SRC := tests/stability/invariants_float.c tests/stability/invariants_q31.c \
                  tests/stability/inputs_extreme.c tests/stability/inputs_random.c \
                  tests/stability/report.c
STAB_INV_HDR := tests/stability/invariants.h tests/stability/inputs.h host/base/rng.h
STAB_BASIS_SRC := tests/stability/basis_study.c tests/stability/basis_forms.c
# Random inputs per model and form: 10^6 in make check-full, 2 x 10^5 in
# make check (each model's 10^6 took 0.2 to 3 s, 77 s of the check's 85).
STAB_RANDOM_N := $(call check_len,1000000,200000)
STAB_SANITIZE_N := 20000
STAB_SEED := 20260707
STAB_MODELS := 200
STAB_MODELS_N := 2000
STAB_PERTURB := 20
STAB_NAMES := $(foreach h,$(FW_POINT_HEADERS),$(call fw_name,$(h)))

# $(call stab_runner,HEADER,VARIANT,FLAGS[,PROGRAM,MAIN]): run_invariants (or
# PROGRAM from MAIN) for one header, linked with build/VARIANT/libtfit.a.
define stab_runner
$(STAB_T)/$(2)/$(or $(4),run_invariants)-$(call fw_name,$(1)): $(or $(5),tests/stability/run_invariants.c) \
    $(STAB_CHECK_SRC) $(STAB_INV_HDR) $(1) $(B)/$(2)/libtfit.a | deps-check
	@mkdir -p $$(@D)
	$$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) $(3) -Itarget/include -Ihost -Itests/stability -I$(dir $(1)) \
	  -DGOLDEN_H='"$(call fw_name,$(1))_golden.h"' \
	  -DGOLDEN_SETS=TFIT_$(call upper,$(call fw_name,$(1)))_GOLDEN_SETS \
	  -DGOLDEN_Q31_SETS=TFIT_$(call upper,$(call fw_name,$(1)))_GOLDEN_Q31_SETS \
	  -DTFIT_$(call upper,$(call fw_name,$(1)))_IMPLEMENTATION \
	  $(or $(5),tests/stability/run_invariants.c) $(STAB_CHECK_SRC) $(B)/$(2)/libtfit.a -lm -o $$@
endef
$(foreach h,$(FW_POINT_HEADERS),$(eval $(call stab_runner,$(h),native,-O2)))
$(foreach h,$(FW_POINT_HEADERS),$(eval $(call stab_runner,$(h),native,-O2,bench_inputs,tests/stability/bench_inputs.c)))
$(foreach h,$(FW_POINT_HEADERS),$(eval $(call stab_runner,$(h),asan,-O1 $(TEST_G) $(SANITIZE))))

.PHONY: check-stability check-stability-basis check-stability-extremes check-stability-random \
        check-stability-sanitize check-stability-models stability-plot \
        $(STAB_NAMES:%=stability-extremes-%) $(STAB_NAMES:%=stability-random-%)
CHECKS += check-stability
check-stability: check-stability-basis check-stability-extremes check-stability-random \
                 check-stability-sanitize check-stability-models
	@echo "ok: stability: basis, extremes, random inputs, sanitizers and random models"

# One target per header, so that make -j2 runs two at a time.
$(STAB_NAMES:%=stability-extremes-%): stability-extremes-%: $(STAB_T)/native/run_invariants-%
	@$< -l $* extremes
$(STAB_NAMES:%=stability-random-%): stability-random-%: $(STAB_T)/native/run_invariants-%
	@$< -l $* random $(STAB_RANDOM_N) $(STAB_SEED)

check-stability-extremes: $(STAB_NAMES:%=stability-extremes-%)
	@echo "== stability: extreme inputs, every model of every header, float32 and Q31: ok =="
check-stability-random: $(STAB_NAMES:%=stability-random-%)
	@echo "== stability: $(STAB_RANDOM_N) random inputs per model and form: ok =="

check-stability-sanitize: $(STAB_NAMES:%=$(STAB_T)/asan/run_invariants-%)
	@echo "== stability: extremes and $(STAB_SANITIZE_N) random inputs under ASan + UBSan =="
	@set -e; for n in $(STAB_NAMES); do \
	  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	    $(STAB_T)/asan/run_invariants-$$n -l $$n extremes >/dev/null; \
	  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	    $(STAB_T)/asan/run_invariants-$$n -l $$n random $(STAB_SANITIZE_N) $(STAB_SEED) >/dev/null; \
	  echo "$$n: no report"; done

$(STAB_T)/random_models: tests/stability/random_models.c $(STAB_CHECK_SRC) $(STAB_INV_HDR) \
    $(B)/native/libtissuefit-host.a $(B)/native/libtest-support.a $(B)/native/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -O2 -Itests/stability $< $(STAB_CHECK_SRC) $(call host_test_link,native) -o $@

check-stability-models: $(STAB_T)/random_models
	@echo "== stability: $(STAB_MODELS) random models, extremes and $(STAB_MODELS_N) random inputs each =="
	@$< $(STAB_MODELS) $(STAB_SEED) $(STAB_MODELS_N)

.PHONY: bench-stability
BENCHES += bench-stability
bench-stability: $(STAB_NAMES:%=$(STAB_T)/native/bench_inputs-%)
	@echo "== native ns per evaluation by kind of input (median of batches of 64 calls) =="
	@set -e; for n in $(STAB_NAMES); do $(STAB_T)/native/bench_inputs-$$n | sed "s|^|$$n |"; done

# --- item 1: basis conditioning --------------------------------------------
# Links the target library: the float32 Chebyshev columns are the target's
# own code (tfit_cheb, tfit_basis, tfit_row), not a copy that could drift.
$(STAB_T)/basis_study: $(STAB_BASIS_SRC) tests/stability/basis_forms.h target/src/tfit_internal.h \
    $(B)/native/libtissuefit-host.a $(B)/native/libtfit.a | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_CFLAGS) -O2 $(STAB_BASIS_SRC) $(B)/native/libtissuefit-host.a \
	  $(B)/native/libtfit.a $(HOST_LIBS) -o $@

check-stability-basis: $(STAB_T)/basis_study
	@echo "== stability: polynomial basis in float32/float64, digits lost per order =="
	@$<
	@echo "target's Chebyshev basis: < 1 digit lost in float32 up to order 8: ok"
	@if $< --perturb $(STAB_PERTURB) >/dev/null 2>&1; then \
	  echo "basis_study accepted coefficients perturbed by 2^-$(STAB_PERTURB): the assertion is blind"; \
	  exit 1; fi
	@echo "coefficients perturbed by 2^-$(STAB_PERTURB): rejected, as they must be"

DEBS_STABILITY_PLOT := $(DEBS_BUILD) gnuplot-nox
.PHONY: deps-stability-plot
deps-stability-plot: ; $(call ensure_debs,$(DEBS_STABILITY_PLOT))

stability-plot: $(STAB_T)/basis_study tests/stability/basis_plot.gp | deps-stability-plot
	@$< --data $(STAB_T)/basis.dat
	@gnuplot -e "data='$(STAB_T)/basis.dat'; out='docs/stability_basis.png'" tests/stability/basis_plot.gp
	@echo "wrote docs/stability_basis.png"
