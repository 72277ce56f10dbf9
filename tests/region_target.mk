# region_target.mk — the region models on the device (docs/header-format.md
# §5.10-§5.12, docs/firmware.md §12): the law over a region, the surface for
# the current contact, two instruments.
#
#   check-bitexact-region    random regions (laws of degree 2-4, surfaces of
#                            degree 1-3, the two-instrument sequences) x the
#                            bit-exact compiler matrix: target == host reference;
#                            a contracted (FMA) build must mismatch and fail its
#                            self-test
#   check-insncount-region   callgrind: one instruction count per tick of
#                            tfit_region_force, per call of tfit_region_surface,
#                            tfit_region_pair and tfit_region_surface_pair
#   check-region-properties  continuity, passivity, finiteness and the stuck
#                            law on a block-like and a curved region (margins)
#   check-qemu-region        golden and two-instrument vectors on Cortex-M4F and
#                            M7 under QEMU, and the instructions and cycles of a
#                            block48-sized law and liver-sized surfaces

RG := $(T)/region

$(RG)/gen_region $(RG)/properties: $(RG)/%: tests/region/%.c $(B)/native/libtissuefit-host.a \
    $(B)/native/libtest-support.a $(B)/native/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -Itests/region $< $(call host_test_link,native) -o $@

$(RG)/regions.bundle: $(RG)/gen_region
	$(call say,GEN)
	$(Q)$< bundle 300 20261206 $@

REGION_RUNNER := tests/region/run_region.c tests/region/region_read.h tests/region/region_bundle.h
$(RG)/run_region-fma: $(REGION_RUNNER) $(T)/fma/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O1 -Itarget/include -Itests/region $< $(T)/fma/libtfit.a -o $@
$(RG)/run_region-%: $(REGION_RUNNER) $(B)/bitexact-%/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O1 -Itarget/include -Itests/region $< $(B)/bitexact-$*/libtfit.a -o $@

.PHONY: check-bitexact-region check-insncount-region check-region-properties check-qemu-region
CHECKS += check-bitexact-region check-insncount-region check-region-properties check-qemu-region

check-bitexact-region: $(RG)/regions.bundle $(BITEXACT_CONFIGS:%=$(RG)/run_region-%) \
    $(RG)/run_region-fma
	@echo "== bit-exact: random region models (law, surface, two instruments), $(words $(BITEXACT_CONFIGS)) compiler configurations =="
	@set -e; for c in $(BITEXACT_CONFIGS); do $(RG)/run_region-$$c $$c $(RG)/regions.bundle; done
	@if $(RG)/run_region-fma fma-contracted $(RG)/regions.bundle >$(RG)/fma.log 2>&1; then \
	  tail -n 1 $(RG)/fma.log; echo "the FMA-contracted library matched every region word"; exit 1; fi; \
	tail -n 1 $(RG)/fma.log; \
	n=$$(sed -n 's/.* \([0-9][0-9]*\) mismatches.*/\1/p' $(RG)/fma.log); \
	k=$$(sed -n 's/.* \([0-9][0-9]*\) failed checks.*/\1/p' $(RG)/fma.log); \
	[ "$${n:-0}" -gt 0 ] || { echo "the FMA build gave no mismatching region word"; exit 1; }; \
	[ "$${k:-0}" -gt 0 ] || { echo "the FMA build passed every region self-test"; exit 1; }
	@echo "ok: 300 random regions bit-exact in $(words $(BITEXACT_CONFIGS)) compiler configurations; a contracted build mismatches and fails its self-test"

# --- one instruction count per call (callgrind) ----------------------------------
$(RG)/probe_region: tests/region/probe_region.c tests/region/region_read.h \
    tests/region/region_bundle.h $(B)/native/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O1 -Itarget/include -Itests/region $< $(B)/native/libtfit.a -o $@
$(RG)/probe.bundle: $(RG)/gen_region
	$(call say,GEN)
	$(Q)$< bundle 12 20261207 $@ >/dev/null

# One path per tick over a long random palpation (tests/region/tick_paths.c):
# libtfit with GCC's basic-block hooks, TICK_PATHS ticks shared among the
# shipped block48 region and the probe bundle's twelve regions.
TICK_PATHS ?= 1000000
$(eval $(call tfit_lib,tracepc,$(CC),-O2 -fsanitize-coverage=trace-pc,,check))
$(RG)/tick_paths: tests/region/tick_paths.c tests/region/tick_control.c tests/region/region_read.h \
    tests/region/region_bundle.h coeffs/block48_region.h coeffs/block48_region_golden.h \
    $(B)/tracepc/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O2 -fsanitize-coverage=trace-pc -c tests/region/tick_control.c \
	  -o $(RG)/tick_control.o
	$(Q)$(CC) $(HOST_STRICT) -O1 -Itarget/include -Itests/region -Icoeffs \
	  -DTFIT_BLOCK48_REGION_IMPLEMENTATION $< $(RG)/tick_control.o $(B)/tracepc/libtfit.a -lm -o $@

check-insncount-region: $(RG)/probe_region $(RG)/probe.bundle $(RG)/tick_paths
	@echo "== instructions per call of the region entry points (callgrind), every golden input and state =="
	@tests/region/insncount.sh $(RG)/probe_region $(RG)/probe.bundle $(RG)/insncount
	@echo "== one sequence of basic blocks per call over $(TICK_PATHS) ticks of a random palpation =="
	@$(RG)/tick_paths $(RG)/probe.bundle $(TICK_PATHS) 20261207
	@echo "ok: one instruction count per region model and entry point, whatever the tip, force and state; one path per tick over $(TICK_PATHS) ticks"

# --- on the device: QEMU (M4F, M7 and the other builds of check-qemu) --------------
$(RG)/gen/regions.h: $(RG)/gen_region
	@mkdir -p $(@D)
	$(call say,GEN)
	$(Q)$< header 20261208 $@ $(RG)/gen/regions-mix.txt >/dev/null
$(RG)/gen/regions-mix.txt: $(RG)/gen/regions.h

REGION_FW_CORES := m4f m7 m4f-c m7-c m4f-O0 m4f-Os m4f-O3
# $(call region_fw,CORE,NAME,FLAGS): $(FW)/CORE/NAME.elf.  The traced image
# (region-trace.elf, -DREGION_TRACE) starts each group of calls with a marker
# instead of a model check (qemu_region.c): the CRCs of the checks were more
# than half of the blocks QEMU logged, 43 s of CPU to trace on the M4F
# against 10 s without them.
define region_fw
$(FW)/$(1)/$(2).elf: tests/region/qemu_region.c $(RG)/gen/regions.h $(FW_STARTUP) $(FW_SEMIHOST) \
    $(FW_LIB_$(1)) linker/$(FW_LD_$(1)) linker/sections.ld | deps-check
	@mkdir -p $$(@D)
	$$(call say,LINK)
	$(Q)$(ARM)gcc $(FW_CFLAGS) $(FW_FLAGS_$(1)) $(3) -I$(RG)/gen -DREGION_H='"regions.h"' \
	  -DLABEL='"regions/$(FW_QEMU_$(1))$(FW_TAG_$(1))"' $$(filter %.c,$$^) $(FW_LIB_$(1)) \
	  $(FW_LDFLAGS) -T $(FW_LD_$(1)) -o $$@
endef
$(foreach c,$(REGION_FW_CORES),$(eval $(call region_fw,$(c),region)))
$(foreach c,m4f m7,$(eval $(call region_fw,$(c),region-trace,-DREGION_TRACE)))

# The executed instruction mix of every call (trace_mix: one mix per group of
# calls, or DIFFERENT), and its cycles by the cycle model's per-class costs
# (host/cost/cycles.c: the Cortex-M4 TRM's table; M7 a dual-issue estimate).
$(FW)/%/region-trace.txt: $(FW)/%/region-trace.elf $(FW)/%/region-trace.dis $(T)/trace_mix
	$(call say,TRACE)
	$(Q)timeout 600 qemu-system-arm -M $(FW_QEMU_$*) -display none -monitor none -serial none \
	  -semihosting-config enable=on,target=native -kernel $< \
	  -d in_asm,exec,nochain -D $(@:.txt=.log) >/dev/null 2>&1 || { echo "$<: run failed"; exit 1; }
	$(Q)$(T)/trace_mix $(word 2,$^) $(@:.txt=.log) >$@.tmp || { cat $@.tmp; rm -f $@.tmp; exit 1; }
	$(Q)rm -f $(@:.txt=.log) && mv $@.tmp $@
$(FW)/%/region-cycles.txt: $(FW)/%/region-trace.txt $(T)/check_cycle_model
	$(Q)$(T)/check_cycle_model cost $* $< >$@

# The cycle models are the header's last two cases (gen_region.c): case 5 =
# groups 20-23 (the block48-sized law, the rank-20 surface, their pairs),
# case 6 = groups 24-27 (the law again, the rank-40 surface, their pairs).
REGION_BUDGET_LAW := 5040
REGION_BUDGET_SURFACE := 50400
check-qemu-region: $(foreach c,$(REGION_FW_CORES),$(FW)/$(c)/region.elf) \
    $(FW)/m4f/region-cycles.txt $(FW)/m7/region-cycles.txt $(RG)/gen/regions-mix.txt
	@echo "== region models under QEMU: golden and two-instrument vectors on M4F and M7 (and the C path, -O0/-Os/-O3), one instruction mix per call, cycles =="
	@printf 'tests/firmware/qemu_run.sh %s %s\n' $(foreach c,$(REGION_FW_CORES),$(FW_QEMU_$(c)) $(FW)/$(c)/region.elf) | \
	  tests/run_lines.sh $(NPROC) $(FW)/qemu-region
	@for c in m4f m7; do echo "$$c: $$(grep -c identical $(FW)/$$c/region-trace.txt) groups of calls, each one instruction mix"; done
	@set -e; for c in m4f m7; do awk -v core=$$c ' \
	  { split($$0, w, ":"); s = substr(w[1], 5) + 0 } \
	  s == 20 { printf "%s tfit_region_force, block48-sized law (P = 2, 17 x 17 sites): %s\n", core, substr($$0, index($$0, ":") + 2) } \
	  s == 21 { printf "%s tfit_region_surface, 400 outputs, rank 20: %s\n", core, substr($$0, index($$0, ":") + 2) } \
	  s == 25 { printf "%s tfit_region_surface, 400 outputs, rank 40: %s\n", core, substr($$0, index($$0, ":") + 2) } \
	  s == 22 { printf "%s tfit_region_pair (two ticks and the coupling, rank 20): %s\n", core, substr($$0, index($$0, ":") + 2) } \
	  s == 26 { printf "%s tfit_region_pair (two ticks and the coupling, rank 40): %s\n", core, substr($$0, index($$0, ":") + 2) } \
	  s == 23 { printf "%s tfit_region_surface_pair, rank 20: %s\n", core, substr($$0, index($$0, ":") + 2) }' \
	  $(FW)/$$c/region-cycles.txt; done
	@set -e; for c in m4f m7; do \
	  grep "^$$c set " $(RG)/gen/regions-mix.txt | sed "s/^$$c //" | sort >$(FW)/$$c/region-mix-model.txt; \
	  sed -n 's/^\(set [0-9]*\) ([a-z_]*): .* mix: \(.*\)$$/\1: \2/p' $(FW)/$$c/region-trace.txt | \
	    awk -F': ' 'NR == FNR { k[$$1] = 1; next } ($$1 in k)' $(FW)/$$c/region-mix-model.txt - | \
	    sort >$(FW)/$$c/region-mix-traced.txt; \
	  if ! diff $(FW)/$$c/region-mix-model.txt $(FW)/$$c/region-mix-traced.txt >$(FW)/$$c/region-mix.diff; then \
	    echo "$$c: the region forms' cycle model differs from the traced calls (< model, > trace):"; \
	    cat $(FW)/$$c/region-mix.diff; exit 1; fi; \
	  echo "$$c: $$(wc -l <$(FW)/$$c/region-mix-model.txt) law and surface sets: the cycle model's mix is the traced one"; done
	@law=$$(awk '/^set 20:/ { print $$6 }' $(FW)/m4f/region-cycles.txt); \
	[ -n "$$law" ] && [ "$$law" -le $(REGION_BUDGET_LAW) ] || \
	  { echo "the law's tick takes $$law M4F cycles, beyond its budget of $(REGION_BUDGET_LAW)"; exit 1; }; \
	echo "law tick: $$law M4F cycles, within the budget of $(REGION_BUDGET_LAW) (30 us at 168 MHz)"
	@echo "ok: region models bit-exact under QEMU on every build; every call of an entry point executes one instruction mix"
.SECONDARY: $(foreach c,m4f m7,$(FW)/$(c)/region-trace.txt $(FW)/$(c)/region-trace.dis)

# --- properties of the contact (tests/region/properties.c) -------------------------
check-region-properties: $(RG)/properties
	@echo "== region law properties: continuity, closed-path work, passivity with friction, finiteness, stuck contact =="
	@$<
	@echo "ok: the region law is continuous, conservative without friction and passive with it, finite for every input and state, and the site law when stuck"

# --- the shipped contact regions' headers: golden vectors natively --------------
# coeffs.mk's REGION_HEADERS: no native haptic loop runs them, so check-golden
# (tests.mk) runs their golden vectors in every bit-exact configuration too
# (check-qemu runs them on the cores with every coeffs/ header).
GOLDEN_REGIONS := $(basename $(notdir $(REGION_HEADERS)))
define golden_runner_shipped
$(T)/golden-$(1)-%: tests/header/run_golden.c coeffs/$(1).h coeffs/$(1)_golden.h $(B)/bitexact-%/libtfit.a
	$$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O1 -Itarget/include -Icoeffs -DGOLDEN_H='"$(1)_golden.h"' \
	  -DGOLDEN_SETS=TFIT_$(call upper,$(1))_GOLDEN_SETS -DGOLDEN_PAIR=TFIT_$(call upper,$(1))_GOLDEN_PAIR \
	  -DTFIT_$(call upper,$(1))_IMPLEMENTATION $$< $(B)/bitexact-$$*/libtfit.a -o $$@
endef
$(foreach h,$(GOLDEN_REGIONS),$(eval $(call golden_runner_shipped,$(h))))
check-golden: $(foreach h,$(GOLDEN_REGIONS),$(BITEXACT_CONFIGS:%=$(T)/golden-$(h)-%))
