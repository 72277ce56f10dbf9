# q15.mk — issue 14 acceptance 1 (docs/tradeoff.md §5, docs/firmware.md §5.6)
#
#   q15-study    where block48_nh-shaped forward models spend their M4F
#                cycles (rows, amplitudes and the rest) in the float modal
#                family and in modal_q15, from the cycle model that
#                check-cycles holds equal to QEMU's traces: writes
#                docs/reports/block48_nh_q15.md

Q15_T := $(T)/q15

$(Q15_T)/q15_study: tests/q15/q15_study.c $(B)/native/libtissuefit-host.a \
    $(B)/native/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) $< $(call host_test_link,native) -o $@

.PHONY: q15-study
q15-study: $(Q15_T)/q15_study
	@{ echo "# block48_nh-shaped forward models: where the M4F cycles go"; echo; \
	  echo "Written by \`make q15-study\` (tests/q15.mk, tests/q15/q15_study.c): the cycle"; \
	  echo "model (host/cost/cycles.c, upper bound at 168 MHz) at 121 output points; see"; \
	  echo "docs/tradeoff.md §5 and docs/firmware.md §5.6."; echo; \
	  $(Q15_T)/q15_study; } >docs/reports/block48_nh_q15.md.tmp
	@mv docs/reports/block48_nh_q15.md.tmp docs/reports/block48_nh_q15.md
	@echo "wrote docs/reports/block48_nh_q15.md"
