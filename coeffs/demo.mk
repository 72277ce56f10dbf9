# demo.mk — `make demo`: the main job end to end on block48 (README.md).
#
#   1. tissuefit fit: solve the scene (one factorisation), fit every family,
#      emit build/demo/block48.h + golden vectors + report with plots;
#   2. compile the native haptic loop (target/examples) against that header
#      and the target library;
#   3. run it over the scripted 1,000-tick force trajectory: per-tick time
#      (median, worst);
#   4. tissuefit replay: solve every tick's force and report the largest
#      deviation of the firmware's outputs; PNG of the deformed surface.

DEMO := $(B)/demo
DEMO_LOOP := target/examples/haptic_loop.c target/examples/haptic_script.c \
             target/examples/board_native.c

.PHONY: demo
demo: $(B)/bin/tissuefit $(B)/lib/libtfit.a | deps-demo
	@mkdir -p $(DEMO)
	@echo "== 1. solve and fit coeffs/block48.yaml =="
	$(B)/bin/tissuefit fit coeffs/block48.yaml -o $(DEMO)/block48.h --report $(DEMO)
	@echo "== 2. native haptic loop against $(DEMO)/block48.h and libtfit.a =="
	$(Q)tests/firmware/haptic_config.sh $(DEMO)/block48.h >$(DEMO)/haptic_config.h
	$(Q)$(CC) $(HOST_STRICT) -O2 -Itarget/include -Itarget/examples -I$(DEMO) $(DEMO_LOOP) \
	  $(B)/lib/libtfit.a -o $(DEMO)/haptic
	@echo "== 3. 1,000 ticks: press, sweep, release, a push beyond the envelope, a NaN =="
	$(Q)HAPTIC_CSV=$(DEMO)/ticks.csv $(DEMO)/haptic
	@echo "== 4. every tick against a true solve =="
	$(Q)$(B)/bin/tissuefit -q replay coeffs/block48.yaml --ticks $(DEMO)/ticks.csv \
	  --png $(DEMO)/deformed.png
	@echo "report: $(DEMO)/block48.md (plots beside it)"

# demo-nh: the same loop on block48_nh (neo-Hookean, 2.1 N envelope): the
# shipped coeffs/block48_nh.h, the script's forces scaled by 2.1,
# every tick against a true nonlinear solve: each distinct force once (839
# of the 1,000 ticks), continuing from the previous one (tissuefit replay;
# about 20 minutes here on the 2,205-node cloud).  Results committed to
# docs/reports/block48_nh_demo.txt and .png (docs/fitting.md §7.8).  check-demo-nh (make check): the same loop,
# its first NH_CHECK_TICKS ticks replayed, held to NH_CHECK_BOUND, and the
# deviation must exceed a tenth of that bound (one replay); a replay of 5
# ticks at 1e-9 mm must be refused.
DEMO_NH := $(DEMO)/nh
# $(call demo_results,DIR,NAME): a demo's haptic-loop summary (without this
# machine's timings) and replay, and the replay's picture, committed as
# docs/reports/NAME.txt and NAME.png.
demo_results = mkdir -p $(REPORTS) && sed -n '1p' $(1)/haptic.txt | sed 's/; [0-9]* ns per tick.*//' | \
  cat - $(1)/replay.txt | sed 's|$(1)/deformed.png|$(REPORTS)/$(2).png|' > $(REPORTS)/$(2).txt && \
  cp $(1)/deformed.png $(REPORTS)/$(2).png && echo "results: $(REPORTS)/$(2).txt and .png"
NH_CHECK_TICKS := 100
# one tick in two of them (50 solves along the same press to 0.56 N, 25 s
# here against 40 for all 100; make check-full all 100): measured 0.00516
# mm of a peak 1.33 mm at tick 99 either way; a regression bound, which a
# deviation under a tenth of it would make too loose to fail
NH_CHECK_EVERY := $(call check_len,1,2)
NH_CHECK_BOUND := 0.01

$(DEMO_NH)/haptic: coeffs/block48_nh.h $(B)/lib/libtfit.a $(DEMO_LOOP) | deps-demo
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)tests/firmware/haptic_config.sh coeffs/block48_nh.h >$(@D)/haptic_config.h
	$(Q)$(CC) $(HOST_STRICT) -O2 -DHAPTIC_FORCE_SCALE=2.1f -Itarget/include -Itarget/examples \
	  -Icoeffs -I$(@D) $(DEMO_LOOP) $(B)/lib/libtfit.a -o $@

.PHONY: demo-nh check-demo-nh
demo-nh: $(B)/bin/tissuefit $(DEMO_NH)/haptic | deps-demo
	@echo "== 1. native haptic loop against coeffs/block48_nh.h (the shipped header) =="
	@echo "== 2. 1,000 ticks: press 1.68 N, sweep, release, a push beyond the envelope, a NaN =="
	$(Q)HAPTIC_CSV=$(DEMO_NH)/ticks.csv $(DEMO_NH)/haptic | tee $(DEMO_NH)/haptic.txt
	@echo "== 3. every tick against a true nonlinear solve (continuation) =="
	$(Q)$(B)/bin/tissuefit -q replay coeffs/block48_nh.yaml --ticks $(DEMO_NH)/ticks.csv \
	  --png $(DEMO_NH)/deformed.png | tee $(DEMO_NH)/replay.txt
	$(Q)$(call demo_results,$(DEMO_NH),block48_nh_demo)

CHECKS += check-demo-nh
check-demo-nh: $(B)/bin/tissuefit $(DEMO_NH)/haptic
	@echo "== block48_nh haptic loop: its first $(NH_CHECK_TICKS) ticks against true nonlinear solves$(call check_len,, (short: one in $(NH_CHECK_EVERY))) =="
	@HAPTIC_CSV=$(DEMO_NH)/check.csv $(DEMO_NH)/haptic > /dev/null
	@out=$$($(B)/bin/tissuefit -q replay coeffs/block48_nh.yaml --ticks $(DEMO_NH)/check.csv \
	  --first $(NH_CHECK_TICKS) --every $(NH_CHECK_EVERY) --max-error-mm $(NH_CHECK_BOUND) 2>&1) || { echo "$$out"; exit 1; }; \
	dev=$$(echo "$$out" | sed -n 's/.*from the solve: \([0-9.e+-]*\) mm.*/\1/p'); \
	awk -v d="$$dev" -v b=$(NH_CHECK_BOUND) 'BEGIN { exit !(d > b / 10) }' || \
	  { echo "$$out"; echo "the largest deviation ($$dev mm) is under a tenth of the bound: the check could not fail"; exit 1; }; \
	echo "ok: block48_nh's firmware within $(NH_CHECK_BOUND) mm of $$(( $(NH_CHECK_TICKS) / $(NH_CHECK_EVERY) )) nonlinear solves over its first $(NH_CHECK_TICKS) ticks ($$dev mm, above a tenth of the bound)"
	@if $(B)/bin/tissuefit -q replay coeffs/block48_nh.yaml --ticks $(DEMO_NH)/check.csv \
	  --first 5 --max-error-mm 1e-9 > /dev/null 2>&1; then \
	  echo "replay accepted 5 ticks at a bound of 1e-9 mm"; exit 1; fi
	@echo "ok: replay refuses ticks beyond its bound (5 ticks at 1e-9 mm)"
