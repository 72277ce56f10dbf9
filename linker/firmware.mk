# firmware.mk — firmware images for Cortex-M (issue 6).
#
#   make firmware    cross-builds libtfit and the haptic-loop example for
#                    STM32F407 (Cortex-M4F) and STM32H743 (Cortex-M7) with
#                    every shipped header; prints flash/RAM per image and
#                    the worst-case stack of each public function
#   check-qemu       golden vectors (float and Q31) of every shipped header on
#                    the QEMU boards mps2-an386 (M4F) and mps2-an500 (M7), and
#                    the Q31 ones on mps2-an385 (M3) and microbit (M0, Armv6-M
#                    like the M0+): bit-exact or the check fails; the startup
#                    FPU check must reject a flush-to-zero / default-NaN FPU
#   check-q31        the Q31 libraries for M3 and M0+ need nothing from
#                    outside (nm -u: no soft float, no libgcc) and have no
#                    mutable state
#
# "Shipped headers": coeffs/*.h (without *_golden.h) plus the test headers
# below (generated ones, and tests/resonant/block48_dyn.h, a fitted header
# that is not shipped: tests/resonant.mk), so that real headers are picked
# up as they land.  The organ
# headers (ORGAN_HEADERS, coeffs.mk) run on the M4F only, in check-organs
# (tests/organs.mk): their golden sets exceed the micro:bit's flash.

FW := $(B)/firmware
FW_SHIPPED := $(filter-out %_golden.h $(ORGAN_HEADERS),$(wildcard coeffs/*.h))
FW_HEADERS := $(FW_SHIPPED) $(T)/gen/demo.h $(T)/gen/families.h $(T)/gen/haptic.h $(T)/gen/resonant.h \
              $(T)/gen/shapes.h $(T)/gen/modal_ranks.h $(T)/gen/block48_dyn.h
# The headers of contact sites: the haptic-loop example, the stability
# invariants and the benches evaluate their forward and contact models; a
# contact region's law and surface (REGION_HEADERS, coeffs.mk) run their
# golden vectors here and have their own tests (tests/region_target.mk).
FW_POINT_HEADERS := $(filter-out $(REGION_HEADERS),$(FW_HEADERS))
fw_name = $(basename $(notdir $(1)))

FW_CFLAGS := $(STRICT) -ffreestanding -O2 -g -ffunction-sections -fdata-sections \
             -Itarget/include -Ilinker -Itarget/examples
FW_LDFLAGS := -nostdlib -nostartfiles -Wl,--gc-sections -Wl,--no-undefined -Llinker
FW_STARTUP := linker/startup.c linker/startup.h
FW_SEMIHOST := linker/semihost.c linker/semihost.h

# Per core: compiler flags, library, QEMU board and its linker script.
# m3 and m0 have no FPU: they run the Q31 evaluator only.
FW_FLAGS_m4f := $(M4F_FLAGS)
FW_FLAGS_m7 := $(M7_FLAGS)
FW_FLAGS_m3 := $(M3_FLAGS)
FW_FLAGS_m0 := $(M0P_FLAGS)
FW_LIB_m4f := $(B)/cortex-m4f/libtfit.a
FW_LIB_m7 := $(B)/cortex-m7/libtfit.a
FW_LIB_m3 := $(B)/cortex-m3/libtfit_q31.a
FW_LIB_m0 := $(B)/cortex-m0plus/libtfit_q31.a
FW_QEMU_m4f := mps2-an386
FW_QEMU_m7 := mps2-an500
FW_QEMU_m3 := mps2-an385
FW_QEMU_m0 := microbit
FW_LD_m4f := mps2-an386.ld
FW_LD_m7 := mps2-an500.ld
FW_LD_m3 := mps2-an386.ld
FW_LD_m0 := microbit.ld
FW_SCRATCH_m0 := -DSCRATCH_WORDS=1536u
FW_CORES := m4f m7
FW_Q31_CORES := m3 m0
# The same boards with other builds of the float library: the portable C
# path (the reference for the assembly, tfit_degree1_armv7em.c) and the
# assembly compiled at -O0, -Os and -O3.  Golden vectors only (check-qemu).
FW_VARIANTS := m4f-c m7-c m4f-O0 m4f-Os m4f-O3
FW_LIB_m4f-c := $(B)/cortex-m4f-portable/libtfit.a
FW_LIB_m7-c := $(B)/cortex-m7-portable/libtfit.a
FW_LIB_m4f-O0 := $(B)/cortex-m4f-O0/libtfit.a
FW_LIB_m4f-Os := $(B)/cortex-m4f-Os/libtfit.a
FW_LIB_m4f-O3 := $(B)/cortex-m4f-O3/libtfit.a
$(foreach v,m4f-c m4f-O0 m4f-Os m4f-O3,$(eval FW_FLAGS_$(v) := $(M4F_FLAGS))$(eval FW_QEMU_$(v) := mps2-an386)$(eval FW_LD_$(v) := mps2-an386.ld))
FW_FLAGS_m7-c := $(M7_FLAGS)
FW_QEMU_m7-c := mps2-an500
FW_LD_m7-c := mps2-an500.ld
FW_TAG_m4f-c := (C)
FW_TAG_m7-c := (C)
FW_TAG_m4f-O0 := (-O0)
FW_TAG_m4f-Os := (-Os)
FW_TAG_m4f-O3 := (-O3)

DEBS_CHECK += qemu-system-arm

# The block48-shaped test header (tests/firmware/gen_haptic.c).
$(T)/gen_haptic: tests/firmware/gen_haptic.c $(B)/native/libtissuefit-host.a $(B)/native/libtest-support.a $(B)/native/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) $< $(call host_test_link,native) -o $@
$(T)/gen/haptic.h: $(T)/gen_haptic
	@mkdir -p $(@D)
	$(call say,GEN)
	$(Q)$< $@
$(T)/gen/shapes.h: $(T)/gen_haptic
	@mkdir -p $(@D)
	$(call say,GEN)
	$(Q)$< shapes $@

# --- golden vectors under QEMU --------------------------------------------------
# $(call fw_golden,HEADER,CORE)
define fw_golden
$(FW)/$(2)/golden-$(call fw_name,$(1)).elf: tests/firmware/qemu_golden.c $(1) $(FW_STARTUP) \
    $(FW_SEMIHOST) $(FW_LIB_$(2)) linker/$(FW_LD_$(2)) linker/sections.ld | deps-check
	@mkdir -p $$(@D)
	$$(call say,LINK)
	$(Q)$(ARM)gcc $(FW_CFLAGS) $(FW_FLAGS_$(2)) $(FW_SCRATCH_$(2)) -I$(dir $(1)) \
	  -DGOLDEN_H='"$(call fw_name,$(1))_golden.h"' \
	  $(if $(filter m3 m0,$(2)),,-DGOLDEN_SETS=TFIT_$(call upper,$(call fw_name,$(1)))_GOLDEN_SETS) \
	  $(if $(filter $(REGION_HEADERS),$(1)),-DGOLDEN_PAIR=TFIT_$(call upper,$(call fw_name,$(1)))_GOLDEN_PAIR) \
	  -DGOLDEN_Q31_SETS=TFIT_$(call upper,$(call fw_name,$(1)))_GOLDEN_Q31_SETS \
	  -DTFIT_$(call upper,$(call fw_name,$(1)))_IMPLEMENTATION \
	  -DLABEL='"$(call fw_name,$(1))/$(FW_QEMU_$(2))$(FW_TAG_$(2))"' \
	  $$(filter %.c,$$^) $(FW_LIB_$(2)) $(FW_LDFLAGS) -T $(FW_LD_$(2)) \
	  -Wl,-Map=$$(@:.elf=.map) -o $$@
endef
$(foreach h,$(FW_HEADERS),$(foreach c,$(FW_CORES) $(FW_Q31_CORES) $(FW_VARIANTS),$(eval $(call fw_golden,$(h),$(c)))))
# The headers each build runs: every header on the two FPU cores the
# headers state cycles for (M4F, M7); on the other builds (the Q31 cores,
# the C path, -O0/-Os/-O3) every header under make check-full, and in make
# check the test header that holds a model of every family (families.h),
# so that each build's every form still runs in both lengths.
fw_headers_on = $(if $(filter $(FW_CORES),$(1)),$(FW_HEADERS),$(call check_len,$(FW_HEADERS),$(T)/gen/families.h))
FW_GOLDEN_IMAGES = $(foreach c,$(FW_CORES) $(FW_Q31_CORES) $(FW_VARIANTS),$(foreach h,$(call fw_headers_on,$(c)),$(FW)/$(c)/golden-$(call fw_name,$(h)).elf))

# The startup code must refuse flush-to-zero (FPSCR) and default-NaN (FPDSCR).
$(FW)/m4f/fpscr_reject.elf $(FW)/m4f/fpdscr_reject.elf: $(FW)/m4f/%_reject.elf: \
    tests/firmware/fpscr_reject.c $(FW_STARTUP) $(FW_SEMIHOST) linker/mps2-an386.ld linker/sections.ld \
    | deps-check
	@mkdir -p $(@D)
	$(call say,LINK)
	$(Q)$(ARM)gcc $(FW_CFLAGS) $(M4F_FLAGS) $(if $(filter fpdscr,$*),-DPOKE_FPDSCR) \
	  $(filter %.c,$^) $(FW_LDFLAGS) -T mps2-an386.ld -o $@

.PHONY: check-qemu
CHECKS += check-qemu
check-qemu: $(FW_GOLDEN_IMAGES) $(FW)/m4f/fpscr_reject.elf $(FW)/m4f/fpdscr_reject.elf
	@echo "== golden vectors under QEMU: M4F (mps2-an386), M7 (mps2-an500); Q31 also on M3 (mps2-an385), M0 (microbit); the C path and -O0/-Os/-O3 builds on M4F/M7$(call check_len,, (these four and M3/M0: families.h; make check-full: every header)) =="
	@# the runs $(NPROC) at a time (one core each), their outputs in this order
	@printf 'tests/firmware/qemu_run.sh %s %s\n' $(foreach c,$(FW_CORES) $(FW_Q31_CORES) $(FW_VARIANTS),\
	  $(foreach h,$(call fw_headers_on,$(c)),$(FW_QEMU_$(c)) $(FW)/$(c)/golden-$(call fw_name,$(h)).elf)) | \
	  tests/run_lines.sh $(NPROC) $(FW)/qemu-golden
	@tests/firmware/qemu_run.sh mps2-an386 $(FW)/m4f/fpscr_reject.elf 3 "startup: FPSCR is not" \
	  >/dev/null && echo "startup rejects FPSCR.FZ = 1: ok"
	@tests/firmware/qemu_run.sh mps2-an386 $(FW)/m4f/fpdscr_reject.elf 3 "startup: FPDSCR" \
	  >/dev/null && echo "startup rejects FPDSCR.DN = 1: ok"
	@echo "ok: golden vectors pass under QEMU on every core; startup rejects a wrong FPSCR/FPDSCR"

# --- Q31 libraries for cores without an FPU --------------------------------------
.PHONY: check-q31
CHECKS += check-q31
check-q31: $(FW_LIB_m3) $(FW_LIB_m0)
	@echo "== Q31 evaluator for Cortex-M3 and Cortex-M0+: freestanding, no soft float =="
	@set -e; for c in cortex-m3:"$(M3_FLAGS)" cortex-m0plus:"$(M0P_FLAGS)"; do \
	  lib=$(B)/$${c%%:*}/libtfit_q31.a; \
	  und=$$($(ARM)nm -u $$lib | awk 'NF == 2 { print $$2 }'); \
	  if [ -n "$$und" ]; then echo "$$lib needs: $$und"; exit 1; fi; \
	  state=$$($(ARM)size -A $$lib | awk '$$1 ~ /^\.(data|bss)/ && $$2 > 0'); \
	  if [ -n "$$state" ]; then echo "$$lib has mutable state: $$state"; exit 1; fi; \
	  $(ARM)gcc $${c#*:} -nostdlib -nostartfiles -Wl,--no-undefined -Wl,-e,tfit_displacements_q31 \
	    -Wl,-u,tfit_contact_force_q31 -Wl,-u,tfit_model_check_q31 -Wl,-u,tfit_golden_run_q31 \
	    $$lib -o $(B)/$${c%%:*}/q31-image.elf; \
	  echo "$${c%%:*}: libtfit_q31.a needs no symbol from outside (no __aeabi_* soft float or" \
	    "division), no .data/.bss, links with -nostdlib; .text $$($(ARM)size -A $$lib | \
	    awk '$$1 ~ /^\.text/ { t += $$2 } END { print t }') bytes"; done
	@echo "ok: the Q31 libraries for Cortex-M3 and Cortex-M0+ are freestanding, without soft float"

# --- cycle model: static loop mixes and traced instruction mixes -------------
# check-cycles proves, on both cores, that the cycle model (host/cost/, each
# form's blocks in host/model/forms/) describes the compiled evaluator: (1)
# the loop bodies of the evaluation functions in the linked library have
# exactly the instruction mixes the model assumes (objdump), and (2) for every golden set of every header, every input
# executed the same instructions under QEMU, and exactly the mix the model
# predicts from the model's shape (so the header's cycle estimates are sums
# over the real instruction stream).
FW_TOOL_SRC := tests/firmware/insn_class.c
FW_EVAL_FUNCS := tfit_displacements tfit_contact_force evaluate tfit_input_map tfit_basis \
                 tfit_degree1_asm tfit_degree1_one_asm tfit_degree1_rows_asm \
                 tfit_modal_rows_asm tfit_modal_rows_r1 tfit_modal_rows_r2 tfit_modal_rows_r3 \
                 tfit_modal_rows_r4 tfit_modal_rows_r5 tfit_modal_rows_r6 tfit_modal_rows_r7 \
                 tfit_modal_rows_r8 \
                 tfit_eval_nodal tfit_eval_modal tfit_eval_zhou2017 tfit_prony_step tfit_prony_filter \
                 tfit_resonant_step tfit_resonant_filter tfit_stateful_step tfit_stateful_eval \
                 tfit_stateful_static \
                 tfit_displacements_cut tfit_cut_progress tfit_cut_rows \
                 tfit_eval_modal_q15 tfit_q15_amp_asm tfit_q15_rows_asm \
                 tfit_region_monomials tfit_region_dot tfit_region_blend tfit_region_amplitudes \
                 tfit_region_rows tfit_region_near

$(T)/insn_mix $(T)/trace_mix: $(T)/%: tests/firmware/%.c $(FW_TOOL_SRC) tests/firmware/insn_class.h \
    host/cost/cycles.h $(B)/native/libtissuefit-host.a $(B)/native/libtest-support.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) $< $(FW_TOOL_SRC) $(call host_test_link,native) -o $@
$(T)/check_cycle_model: tests/firmware/check_cycle_model.c $(B)/native/libtissuefit-host.a $(B)/native/libtest-support.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) $< $(call host_test_link,native) -o $@

# The libraries alone, linked (addresses resolved), for the static check and
# the stack table: every function of the one merged object is kept.
$(FW)/%/libtfit.elf: $(B)/cortex-%/libtfit.a
	@mkdir -p $(@D)
	$(call say,LINK)
	$(Q)$(ARM)gcc $(FW_FLAGS_$*) -nostdlib -nostartfiles -Wl,--no-undefined -Wl,-e,tfit_displacements \
	  $< -o $@
define fw_q31_elf
$(FW)/$(1)/libtfit_q31.elf: $(FW_LIB_$(1))
	@mkdir -p $$(@D)
	$$(call say,LINK)
	$(Q)$(ARM)gcc $(FW_FLAGS_$(1)) -nostdlib -nostartfiles -Wl,--no-undefined \
	  -Wl,-e,tfit_displacements_q31 $$< -o $$@
endef
$(foreach c,$(FW_Q31_CORES),$(eval $(call fw_q31_elf,$(c))))

# Traced mixes of one golden image: $(FW)/CORE/trace-NAME.txt
$(FW)/%.dis: $(FW)/%.elf
	$(Q)$(ARM)objdump -d --no-show-raw-insn $< >$@
define fw_trace
$(FW)/$(2)/trace-$(call fw_name,$(1)).txt: $(FW)/$(2)/golden-$(call fw_name,$(1)).elf \
    $(FW)/$(2)/golden-$(call fw_name,$(1)).dis $(T)/trace_mix
	$$(call say,TRACE)
	$(Q)timeout 300 qemu-system-arm -M $(FW_QEMU_$(2)) -display none -monitor none -serial none \
	  -semihosting-config enable=on,target=native -kernel $$< \
	  -d in_asm,exec,nochain -D $$(@:.txt=.log) >/dev/null 2>&1 || { echo "$$<: run failed"; exit 1; }
	$(Q)$(T)/trace_mix $$(word 2,$$^) $$(@:.txt=.log) >$$@.tmp || { cat $$@.tmp; rm -f $$@.tmp; exit 1; }
	$(Q)rm -f $$(@:.txt=.log) && mv $$@.tmp $$@
endef
$(foreach h,$(FW_HEADERS),$(foreach c,$(FW_CORES) $(FW_Q31_CORES),$(eval $(call fw_trace,$(h),$(c)))))
FW_TRACES = $(foreach c,$(FW_CORES) $(FW_Q31_CORES),$(foreach h,$(call fw_headers_on,$(c)),$(FW)/$(c)/trace-$(call fw_name,$(h)).txt))

.PHONY: check-cycles
CHECKS += check-cycles
check-cycles: $(T)/insn_mix $(T)/check_cycle_model $(FW_TRACES) \
    $(foreach c,$(FW_CORES),$(FW)/$(c)/libtfit.elf $(FW)/$(c)/libtfit.dis)
	@echo "== cycle model: loop mixes (objdump) and executed mixes (QEMU trace) =="
	@set -e; for c in $(FW_CORES); do \
	  $(T)/insn_mix $(FW_EVAL_FUNCS) <$(FW)/$$c/libtfit.dis | grep ' loop ' | sort >$(FW)/$$c/loops.txt; \
	  $(T)/check_cycle_model loops $$c | sort >$(FW)/$$c/loops-model.txt; \
	  if ! diff $(FW)/$$c/loops-model.txt $(FW)/$$c/loops.txt >$(FW)/$$c/loops.diff; then \
	    echo "$$c: compiled loops differ from the cycle model (< model, > objdump):"; \
	    cat $(FW)/$$c/loops.diff; exit 1; fi; \
	  echo "$$c: $$(wc -l <$(FW)/$$c/loops.txt) loop bodies match the cycle model"; done
	@set -e; $(foreach c,$(FW_CORES) $(FW_Q31_CORES),for h in $(call fw_headers_on,$(c)); do \
	  n=$$(basename $$h .h); \
	  $(T)/check_cycle_model $(c) $$h $(FW)/$(c)/trace-$$n.txt | sed "s|^|$(c) |"; done;)
	@echo "ok: the cycle model's loop mixes and executed mixes match the compiled evaluator"

# --- haptic-loop example: STM32 images, QEMU and native runs ------------------
FW_EXAMPLE := target/examples/haptic_loop.c target/examples/haptic_loop.h target/examples/board.h
FW_SCRIPT := target/examples/haptic_script.c target/examples/haptic_script.h
FW_STM32_LD_m4f := stm32f407.ld
FW_STM32_LD_m7 := stm32h743.ld
FW_CORE_DEF_m4f := -DHAPTIC_CORE_M4F
FW_CORE_DEF_m7 := -DHAPTIC_CORE_M7

$(FW)/cfg/%/haptic_config.h: tests/firmware/haptic_config.sh
	@mkdir -p $(@D)
	$(Q)$< $(filter %.h,$^) >$@.tmp && mv $@.tmp $@

# $(call fw_haptic,HEADER,CORE): the STM32 image and the QEMU image
define fw_haptic
$(FW)/cfg/$(call fw_name,$(1))/haptic_config.h: $(1)
$(FW)/$(2)/haptic-$(call fw_name,$(1)).elf: $(FW_EXAMPLE) target/examples/board_stm32.c \
    $(FW)/cfg/$(call fw_name,$(1))/haptic_config.h $(FW_STARTUP) $(FW_LIB_$(2)) \
    linker/$(FW_STM32_LD_$(2)) linker/sections.ld | deps-check
	@mkdir -p $$(@D)
	$$(call say,LINK)
	$(Q)$(ARM)gcc $(FW_CFLAGS) $(FW_FLAGS_$(2)) $(FW_CORE_DEF_$(2)) \
	  -I$(FW)/cfg/$(call fw_name,$(1)) -I$(dir $(1)) \
	  $$(filter %.c,$$^) $(FW_LIB_$(2)) $(FW_LDFLAGS) -T $(FW_STM32_LD_$(2)) \
	  -Wl,-Map=$$(@:.elf=.map) -o $$@
$(FW)/$(2)/haptic-qemu-$(call fw_name,$(1)).elf: $(FW_EXAMPLE) $(FW_SCRIPT) target/examples/board_qemu.c \
    $(FW)/cfg/$(call fw_name,$(1))/haptic_config.h $(FW_STARTUP) $(FW_SEMIHOST) $(FW_LIB_$(2)) \
    linker/$(FW_QEMU_$(2)).ld linker/sections.ld | deps-check
	@mkdir -p $$(@D)
	$$(call say,LINK)
	$(Q)$(ARM)gcc $(FW_CFLAGS) $(FW_FLAGS_$(2)) $(FW_CORE_DEF_$(2)) \
	  -I$(FW)/cfg/$(call fw_name,$(1)) -I$(dir $(1)) \
	  $$(filter %.c,$$^) $(FW_LIB_$(2)) $(FW_LDFLAGS) -T $(FW_QEMU_$(2)).ld -o $$@
endef
# `make firmware HEADER=path/to/NAME.h`: the images and tables for a user's
# own generated header instead of the shipped ones (its NAME must not be a
# shipped header's unless it is that header: the images are named by it).
ifneq ($(HEADER),)
$(if $(filter %.h,$(HEADER)),,$(error HEADER=$(HEADER): expected a generated header, NAME.h))
$(if $(wildcard $(HEADER)),,$(error HEADER=$(HEADER): no such file))
$(if $(filter-out $(HEADER),$(filter %/$(notdir $(HEADER)),$(FW_POINT_HEADERS))),\
  $(error HEADER=$(HEADER): $(notdir $(HEADER)) is also $(filter %/$(notdir $(HEADER)),$(FW_POINT_HEADERS)); give your header another name))
endif
FW_USER_HEADERS := $(filter-out $(FW_POINT_HEADERS),$(HEADER))
$(foreach h,$(FW_POINT_HEADERS) $(FW_USER_HEADERS),$(foreach c,$(FW_CORES),$(eval $(call fw_haptic,$(h),$(c)))))
FW_HAPTIC_IMAGES := $(foreach c,$(FW_CORES),$(foreach h,$(FW_POINT_HEADERS),$(FW)/$(c)/haptic-$(call fw_name,$(h)).elf))
FW_FIRMWARE_IMAGES := $(foreach c,$(FW_CORES),$(foreach h,$(or $(HEADER),$(FW_POINT_HEADERS)),$(FW)/$(c)/haptic-$(call fw_name,$(h)).elf))
FW_HAPTIC_QEMU := $(foreach c,$(FW_CORES),$(foreach h,$(FW_POINT_HEADERS),$(FW)/$(c)/haptic-qemu-$(call fw_name,$(h)).elf))

# Native build of the same loop (the fitting issue's `make demo` runs it over
# its header): $(FW)/native/haptic-NAME
define fw_haptic_native
$(FW)/native/haptic-$(call fw_name,$(1)): $(FW_EXAMPLE) $(FW_SCRIPT) target/examples/board_native.c \
    $(FW)/cfg/$(call fw_name,$(1))/haptic_config.h $(B)/lib/libtfit.a
	@mkdir -p $$(@D)
	$$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O2 -Itarget/include -Itarget/examples \
	  -I$(FW)/cfg/$(call fw_name,$(1)) -I$(dir $(1)) $$(filter %.c,$$^) $(B)/lib/libtfit.a -o $$@
endef
$(foreach h,$(FW_POINT_HEADERS),$(eval $(call fw_haptic_native,$(h))))

# Worst-case stack of the public functions: -fstack-usage frames of the
# library build along its call graph (tests/freestanding/callgraph.c).
FW_PUBLIC := tfit_model_check tfit_model_crc32 tfit_displacements tfit_contact_force tfit_golden_run
FW_PUBLIC_Q31 := tfit_model_check_q31 tfit_model_crc32_q31 tfit_displacements_q31 \
                 tfit_contact_force_q31 tfit_golden_run_q31 tfit_prony_reset_q31 tfit_prony_step_q31
FW_STACK_LIBS := $(foreach c,$(FW_CORES),$(FW)/$(c)/libtfit.elf) \
                 $(foreach c,$(FW_Q31_CORES),$(FW)/$(c)/libtfit_q31.elf)
fw_stack_tables = linker/stack_table.sh $(T)/callgraph "$(FW_PUBLIC)" \
	  m4f:$(FW)/m4f/libtfit.elf:$(B)/cortex-m4f/obj m7:$(FW)/m7/libtfit.elf:$(B)/cortex-m7/obj && \
	linker/stack_table.sh $(T)/callgraph "$(FW_PUBLIC_Q31)" \
	  m4f:$(FW)/m4f/libtfit.elf:$(B)/cortex-m4f/obj m7:$(FW)/m7/libtfit.elf:$(B)/cortex-m7/obj \
	  m3:$(FW)/m3/libtfit_q31.elf:$(B)/cortex-m3/obj m0+:$(FW)/m0/libtfit_q31.elf:$(B)/cortex-m0plus/obj

.PHONY: firmware check-firmware
firmware: $(FW_FIRMWARE_IMAGES) $(T)/callgraph $(FW_STACK_LIBS) | deps-check
	@echo "== firmware images: haptic loop x $(or $(HEADER),shipped headers), STM32F407 (M4F) and STM32H743 (M7) =="
	@linker/size_table.sh $(FW_FIRMWARE_IMAGES)
	@echo
	@echo "== worst-case stack of each public function (bytes; -fstack-usage along the call graph) =="
	@$(fw_stack_tables)

CHECKS += check-firmware
check-firmware: $(FW_HAPTIC_IMAGES) $(FW_HAPTIC_QEMU) $(FW)/native/haptic-haptic $(FW)/cfg/haptic/haptic_config.h \
    $(T)/callgraph $(FW_STACK_LIBS) $(B)/bin/tissuefit
	@echo "== haptic-loop firmware: links for M4F and M7 with every header, no heap =="
	@set -e; for f in $(FW_HAPTIC_IMAGES); do \
	  if grep -qE '\b(_sbrk|malloc|free|calloc|realloc)\b' $${f%.elf}.map; then \
	    echo "$$f: the map file mentions a heap function"; exit 1; fi; done; \
	  echo "$(words $(FW_HAPTIC_IMAGES)) images linked with --no-undefined; no _sbrk/malloc in any map"
	@set -e; for c in $(FW_CORES); do \
	  case $$c in m4f) m=$(FW_QEMU_m4f);; m7) m=$(FW_QEMU_m7);; esac; \
	  for h in $(foreach h,$(FW_POINT_HEADERS),$(call fw_name,$(h))); do \
	    printf '%-9s %-11s ' $$h $$m; \
	    tests/firmware/qemu_run.sh $$m $(FW)/$$c/haptic-qemu-$$h.elf; done; done
	@$(FW)/native/haptic-haptic
	@if $(ARM)gcc $(FW_CFLAGS) $(M4F_FLAGS) -DHAPTIC_CORE_M4F -DHAPTIC_SERVO_HZ=20000u \
	    -I$(FW)/cfg/haptic -I$(T)/gen -fsyntax-only target/examples/haptic_loop.c 2>$(FW)/budget.err; then \
	  echo "the servo budget check accepted haptic.h at 20 kHz on the M4F"; exit 1; fi; \
	  grep -q "exceed the servo budget" $(FW)/budget.err && \
	  echo "servo budget: haptic.h fits 1 kHz on both cores; 20 kHz on the M4F is refused at compile time"
	@if linker/stack_table.sh false "$(FW_PUBLIC)" m4f:$(FW)/m4f/libtfit.elf:$(B)/cortex-m4f/obj \
	    >/dev/null 2>&1; then echo "stack_table.sh ignored a failing call-graph checker"; exit 1; fi
	@{ $(fw_stack_tables); } >/dev/null && echo "stack: every frame static, no recursion, every public function bounded"
	@# a user's own header (a name no shipped header has), and one that is not there
	@mkdir -p $(FW)/user && $(B)/bin/tissuefit -q fit tests/solver/block48_seed.yaml -o $(FW)/user/seed48.h
	@$(MAKE) --no-print-directory firmware HEADER=$(FW)/user/seed48.h >$(FW)/user/firmware.log 2>&1 || \
	  { cat $(FW)/user/firmware.log; exit 1; }
	@for c in m4f m7; do grep -q "^$$c/haptic-seed48 " $(FW)/user/firmware.log || \
	  { cat $(FW)/user/firmware.log; echo "make firmware HEADER=: no size row for $$c/haptic-seed48"; exit 1; }; done
	@if $(MAKE) --no-print-directory -n firmware HEADER=$(FW)/user/none.h >$(FW)/user/none.log 2>&1 || \
	  ! grep -q "HEADER=$(FW)/user/none.h: no such file" $(FW)/user/none.log; then \
	  cat $(FW)/user/none.log; echo "make firmware HEADER= accepted a missing header"; exit 1; fi
	@# the library's sources compiled into the image: placed as from libtfit.a, or refused
	@$(foreach c,$(FW_CORES),CFLAGS="$(FW_CFLAGS) $(FW_FLAGS_$(c)) $(FW_CORE_DEF_$(c)) -I$(FW)/cfg/block48 -Icoeffs" \
	  LDFLAGS="$(FW_LDFLAGS)" tests/firmware/placement.sh $(FW)/placement/$(c) $(FW_STM32_LD_$(c)) &&) true
	@echo "ok: every shipped image heap-free and run under QEMU; stack bounded; make firmware HEADER= builds a user's header and refuses a missing one; the library's sources compiled into an image keep its fast-memory placement or stop the link"


# --- a build that contracts a*b + c (issue 19) --------------------------------
# GCC's GNU modes (the default -std=gnu11) and -ffp-contract=fast fuse a*b + c
# into VFMA on the M4F, which changes bits.  The library's sources ask GCC
# and Clang for no contraction themselves and refuse GCC's fast-math mode
# (tfit_internal.h).  check-contract shows (1) that the unmodified sources
# built with -std=gnu11 or -ffp-contract=fast contain no fused multiply-add
# and (2) that fast-math stops the build (tests/firmware/refuse_fast_math.sh),
# then (3) that a library whose compiler ignored the pragma (removed here from a copy of the sources) is
# caught at boot: on mps2-an386 every float model whose golden vectors come
# out with other bits fails tfit_model_check() with TFIT_ERR_ARITH.  That
# library is the C path (-DTFIT_PORTABLE): the degree-1 assembly cannot be
# contracted.
FW_CONTRACT := $(FW)/contract
FW_CONTRACT_PRAGMA := \#pragma GCC optimize("fp-contract=off")

$(FW_CONTRACT)/gnu11/libtfit.a: $(TARGET_SRC) $(TARGET_HDR) tests/firmware/contract_lib.sh | deps-check
	$(call say,AR)
	$(Q)tests/firmware/contract_lib.sh $@ target/src -std=gnu11
$(FW_CONTRACT)/fast/libtfit.a: $(TARGET_SRC) $(TARGET_HDR) tests/firmware/contract_lib.sh | deps-check
	$(call say,AR)
	$(Q)tests/firmware/contract_lib.sh $@ target/src -std=c11 -ffp-contract=fast
$(FW_CONTRACT)/unguarded/libtfit.a: $(TARGET_SRC) $(TARGET_HDR) tests/firmware/contract_lib.sh | deps-check
	$(call say,AR)
	$(Q)rm -rf $(@D)/src && mkdir -p $(@D)/src && cp target/src/*.c target/src/*.h $(@D)/src/
	$(Q)grep -qxF '$(FW_CONTRACT_PRAGMA)' $(@D)/src/tfit_internal.h || \
	  { echo "tfit_internal.h no longer has the line this test removes"; exit 1; }
	$(Q)grep -vxF '$(FW_CONTRACT_PRAGMA)' target/src/tfit_internal.h >$(@D)/src/tfit_internal.h
	$(Q)tests/firmware/contract_lib.sh $@ $(@D)/src -std=gnu11 -DTFIT_PORTABLE

define fw_contract_image
$(FW_CONTRACT)/contract-$(call fw_name,$(1)).elf: tests/firmware/qemu_contract.c $(1) $(FW_STARTUP) \
    $(FW_SEMIHOST) $(FW_CONTRACT)/unguarded/libtfit.a | deps-check
	$$(call say,LINK)
	$(Q)$(ARM)gcc $(FW_CFLAGS) $(M4F_FLAGS) -I$(dir $(1)) -DGOLDEN_H='"$(call fw_name,$(1))_golden.h"' \
	  -DGOLDEN_SETS=TFIT_$(call upper,$(call fw_name,$(1)))_GOLDEN_SETS \
	  -DTFIT_$(call upper,$(call fw_name,$(1)))_IMPLEMENTATION \
	  -DLABEL='"$(call fw_name,$(1))/mps2-an386, contracted"' $$(filter %.c,$$^) \
	  $(FW_CONTRACT)/unguarded/libtfit.a $(FW_LDFLAGS) -T mps2-an386.ld -o $$@
endef
$(foreach h,$(FW_HEADERS),$(eval $(call fw_contract_image,$(h))))

.PHONY: check-contract
CHECKS += check-contract
check-contract: $(foreach v,gnu11 fast unguarded,$(FW_CONTRACT)/$(v)/libtfit.a) \
    $(foreach h,$(FW_HEADERS),$(FW_CONTRACT)/contract-$(call fw_name,$(h)).elf)
	@echo "== a build that contracts a*b+c: no VFMA from the sources, fast-math refused, the boot check catches the rest (M4F, QEMU) =="
	@set -e; for v in gnu11 fast; do \
	  n=$$($(ARM)objdump -d $(FW_CONTRACT)/$$v/libtfit.a | grep -cE '\svf(n?m[as])\.' || true); \
	  if [ "$$n" != 0 ]; then echo "the $$v build has $$n fused multiply-adds"; exit 1; fi; done; \
	  echo "-std=gnu11 and -ffp-contract=fast builds of target/src: 0 fused multiply-adds (the sources' pragma)"
	@tests/firmware/refuse_fast_math.sh $(ARM)gcc $(FW_CONTRACT)/fast-math.err $(M4F_FLAGS)
	@n=$$($(ARM)objdump -d $(FW_CONTRACT)/unguarded/libtfit.a | grep -cE '\svf(n?m[as])\.' || true); \
	  if [ "$$n" = 0 ]; then echo "the build without the pragma did not contract: the test shows nothing"; exit 1; fi; \
	  echo "without the pragma, -std=gnu11 contracts: $$n fused multiply-adds in the library"
	@set -e; for h in $(foreach h,$(FW_HEADERS),$(call fw_name,$(h))); do \
	  tests/firmware/qemu_run.sh mps2-an386 $(FW_CONTRACT)/contract-$$h.elf; done
	@echo "ok: no contraction from the sources, fast-math refused, a contracted library caught at boot"
