# q15.mk — issue 14 acceptance 1 (docs/tradeoff.md §5, docs/firmware.md §5.6)
#
#   q15-study    where block48_nh-shaped forward models spend their M4F
#                cycles (rows, amplitudes and the rest) in the float modal
#                family and in modal_q15, from the cycle model that
#                check-cycles holds equal to QEMU's traces; and the
#                error/time front of block48_nh's sweep (make tradeoff's
#                docs/reports/block48_nh_sweep.csv) in M4F microseconds
#                (tests/q15/m4f_front.awk): writes docs/reports/block48_nh_q15.md

Q15_T := $(T)/q15

$(Q15_T)/q15_study: tests/q15/q15_study.c $(B)/native/libtissuefit-host.a $(B)/native/libtest-support.a \
    $(B)/native/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) $< $(call host_test_link,native) -o $@

.PHONY: q15-study
q15-study: $(Q15_T)/q15_study tests/q15/m4f_front.awk docs/reports/block48_nh_sweep.csv coeffs/block48_nh.h
	@peak=$$(sed -n 's/.*largest displacement of the training cases: \([0-9.]*\) mm.*/\1/p' coeffs/block48_nh.h); \
	[ -n "$$peak" ] || { echo "coeffs/block48_nh.h states no largest displacement"; exit 1; }; \
	{ echo "# block48_nh-shaped forward models: where the M4F cycles go"; echo; \
	  echo "Written by \`make q15-study\` (tests/q15.mk, tests/q15/q15_study.c): the cycle"; \
	  echo "model (host/cost/cycles.c, upper bound at 168 MHz) at 121 output points; see"; \
	  echo "docs/tradeoff.md §5 and docs/firmware.md §5.6."; echo; \
	  $(Q15_T)/q15_study; echo; \
	  echo "## The sweep's front in M4F microseconds"; echo; \
	  echo "block48_nh_sweep.csv's float32 forward candidates (tests/q15/m4f_front.awk): no"; \
	  echo "other is as fast on the M4F (upper bound) and as accurate (held-out max),"; \
	  echo "and better in one.  % of the $$peak mm peak (coeffs/block48_nh.h)."; echo; \
	  echo "| model | M4F us | held-out max | % |"; echo "|---|---|---|---|"; \
	  awk -v PEAK=$$peak -f tests/q15/m4f_front.awk docs/reports/block48_nh_sweep.csv | sort | \
	    sed 's/^[^|]*|/|/; s/$$/ |/'; } >docs/reports/block48_nh_q15.md.tmp
	@mv docs/reports/block48_nh_q15.md.tmp docs/reports/block48_nh_q15.md
	@echo "wrote docs/reports/block48_nh_q15.md"
