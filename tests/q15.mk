# q15.mk — issue 14 acceptance 1: the Q15 modal reconstruction, as a
# prototype outside libtfit (tests/q15/, docs/reports/block48_nh_q15.md).
#
#   check-q15    the prototype's Armv7E-M assembly (SMUAD/SMLAD rows, the
#                fused float-to-Q15 amplitude step) against its C reference,
#                bit for bit, under QEMU on the M4F and the M7 (seconds)
#   q15-study    where block48_nh's 85 us go (the cycle model), the error a
#                Q15 reconstruction adds to the shipped model (a priori bound
#                and 200,000 sampled forces), and the M4F cycles it would
#                take from the prototype's instruction mixes (objdump):
#                writes docs/reports/block48_nh_q15.md

Q15_T := $(T)/q15
Q15_SRC := tests/q15/q15_rows.c tests/q15/q15_rows.h
Q15_MIXES := $(Q15_T)/mixes.txt

$(foreach c,m4f m7,$(FW)/$(c)/q15_qemu.elf): $(FW)/%/q15_qemu.elf: tests/q15/q15_qemu.c $(Q15_SRC) \
    target/src/tfit_internal.h $(FW_STARTUP) $(FW_SEMIHOST) | deps-check
	@mkdir -p $(@D)
	$(call say,LINK)
	$(Q)$(ARM)gcc $(FW_CFLAGS) $(FW_FLAGS_$*) -Itests/q15 -Itarget/src \
	  $(filter %.c,$^) $(FW_LDFLAGS) -T $(FW_LD_$*) -o $@

.PHONY: check-q15 q15-study
CHECKS += check-q15
check-q15: $(FW)/m4f/q15_qemu.elf $(FW)/m7/q15_qemu.elf
	@echo "== Q15 modal rows prototype: assembly against C, bit for bit, under QEMU (M4F, M7) =="
	@tests/firmware/qemu_run.sh $(FW_QEMU_m4f) $(FW)/m4f/q15_qemu.elf 0 "all bit-identical"
	@tests/firmware/qemu_run.sh $(FW_QEMU_m7) $(FW)/m7/q15_qemu.elf 0 "all bit-identical"
	@echo "ok: Q15 rows and amplitude step bit-identical to C on M4F and M7"

$(Q15_MIXES): $(FW)/m4f/q15_qemu.elf $(T)/insn_mix
	@mkdir -p $(@D)
	$(Q)$(ARM)objdump -d --no-show-raw-insn $< | $(T)/insn_mix q15_rows_asm q15_amp_asm >$@.tmp
	@mv $@.tmp $@

$(Q15_T)/q15_study: tests/q15/q15_study.c coeffs/block48_nh.h $(B)/native/libtissuefit-host.a \
    $(B)/native/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -Itarget/src -Icoeffs $< $(call host_test_link,native) -o $@

q15-study: $(Q15_T)/q15_study $(Q15_MIXES)
	@{ echo "# block48_nh: the cycles of its forward model, and a Q15 reconstruction"; echo; \
	  echo "Written by \`make q15-study\` (tests/q15.mk, tests/q15/q15_study.c); see"; \
	  echo "docs/tradeoff.md §5 for what it means."; echo; \
	  $(Q15_T)/q15_study $(Q15_MIXES); echo; \
	  echo "Prototype instruction mixes (objdump of the M4F image, tests/firmware/insn_mix.c):"; echo; \
	  sed 's/^/    /' $(Q15_MIXES); } >docs/reports/block48_nh_q15.md.tmp
	@mv docs/reports/block48_nh_q15.md.tmp docs/reports/block48_nh_q15.md
	@echo "wrote docs/reports/block48_nh_q15.md"
