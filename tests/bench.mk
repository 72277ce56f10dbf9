# bench.mk — `make bench`: speed of every shipped model (native timing,
# instructions per call, firmware estimates); numbers are printed, never
# asserted (GUIDE §7).  Headers: linker/firmware.mk's FW_POINT_HEADERS.
BENCH_CALLS ?= 100000
DEBS_BENCH += valgrind

# $(call bench_binary,HEADER)
define bench_binary
$(B)/bench/bench-$(call fw_name,$(1)): tests/bench/bench_eval.c $(1) $(B)/lib/libtfit.a | deps-bench
	@mkdir -p $$(@D)
	$$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O2 -Itarget/include -I$(dir $(1)) \
	  -DGOLDEN_H='"$(call fw_name,$(1))_golden.h"' \
	  -DGOLDEN_SETS=TFIT_$(call upper,$(call fw_name,$(1)))_GOLDEN_SETS \
	  -DGOLDEN_Q31_SETS=TFIT_$(call upper,$(call fw_name,$(1)))_GOLDEN_Q31_SETS \
	  -DTFIT_$(call upper,$(call fw_name,$(1)))_IMPLEMENTATION $$< $(B)/lib/libtfit.a -o $$@
endef
$(foreach h,$(FW_POINT_HEADERS),$(eval $(call bench_binary,$(h))))

.PHONY: bench-eval
BENCHES += bench-eval
bench-eval: $(foreach h,$(FW_POINT_HEADERS),$(B)/bench/bench-$(call fw_name,$(h)))
	@echo "== evaluation cost per model; seed: 0.1509 s per evaluation (Zhou et al. 2017) =="
	@set -e; $(foreach h,$(FW_POINT_HEADERS),tests/bench/run.sh $(B)/bench/bench-$(call fw_name,$(h)) $(h) $(BENCH_CALLS);)
