# stability.mk — issue 7, "stability at the extremes" (docs/stability.md).
#
#   check-stability-extremes   item 2: zero, subnormal, boundary, 10x and
#                              1e30x beyond, FLT_MAX, NaN, +-Inf on every
#                              model of every header, float32 and Q31
#   check-stability-random     item 5: 10^6 seeded random inputs per model
#                              and form, same invariants
#   check-stability-sanitize   the extremes and 20000 random inputs again,
#                              runner and library under ASan + UBSan
#
# Headers: linker/firmware.mk's FW_HEADERS (coeffs/*.h without *_golden.h,
# plus the generated test headers), so real headers are covered as they land.

STAB_T := $(T)/stability
STAB_INV_SRC := tests/stability/invariants_float.c tests/stability/invariants_q31.c \
                tests/stability/inputs_extreme.c tests/stability/inputs_random.c \
                tests/stability/report.c tests/stability/run_invariants.c
STAB_INV_HDR := tests/stability/invariants.h tests/stability/inputs.h host/rng.h
STAB_RANDOM_N := 1000000
STAB_SANITIZE_N := 20000
STAB_SEED := 20260707
STAB_NAMES := $(foreach h,$(FW_HEADERS),$(call fw_name,$(h)))

# $(call stab_runner,HEADER,VARIANT,EXTRA-FLAGS): run_invariants for one
# header, linked with build/VARIANT/libtfit.a.
define stab_runner
$(STAB_T)/$(2)/run_invariants-$(call fw_name,$(1)): $(STAB_INV_SRC) $(STAB_INV_HDR) $(1) \
    $(B)/$(2)/libtfit.a | deps-check
	@mkdir -p $$(@D)
	$$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) $(3) -Itarget/include -Ihost -Itests/stability -I$(dir $(1)) \
	  -DGOLDEN_H='"$(call fw_name,$(1))_golden.h"' \
	  -DGOLDEN_SETS=TFIT_$(call fw_upper,$(call fw_name,$(1)))_GOLDEN_SETS \
	  -DGOLDEN_Q31_SETS=TFIT_$(call fw_upper,$(call fw_name,$(1)))_GOLDEN_Q31_SETS \
	  -DTFIT_$(call fw_upper,$(call fw_name,$(1)))_IMPLEMENTATION \
	  $(STAB_INV_SRC) $(B)/$(2)/libtfit.a -lm -o $$@
endef
$(foreach h,$(FW_HEADERS),$(eval $(call stab_runner,$(h),native,-O2)))
$(foreach h,$(FW_HEADERS),$(eval $(call stab_runner,$(h),asan,-O1 -g $(SANITIZE))))

.PHONY: check-stability check-stability-extremes check-stability-random check-stability-sanitize \
        $(STAB_NAMES:%=stability-extremes-%) $(STAB_NAMES:%=stability-random-%)
CHECKS += check-stability
check-stability: check-stability-extremes check-stability-random \
                 check-stability-sanitize

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
