# demo_ve.mk — `make demo-ve`: the creeping block48 (coeffs/block48_ve.yaml,
# seed 001's Kelvin law) end to end, like `make demo` (coeffs/demo.mk):
#
#   1. the native haptic loop (target/examples, HAPTIC_FORWARD_PRONY: the
#      prony model stepped once per tick with its state) against the
#      shipped coeffs/block48_ve.h and libtfit.a;
#   2. 1,000 ticks of 1 ms: press in 200 ms, hold 500 ms (the tissue
#      creeps), release in 200 ms, rest (-DHAPTIC_SCRIPT_PRESS_HOLD);
#   3. tissuefit replay: the same 1,000 forces time-stepped from rest by the
#      Newton solver at every tick (about 1,000 steps: a minute or more of
#      CPU) and the largest deviation of the firmware's outputs.
# Results: docs/reports/block48_ve_demo.txt and .png (committed), docs/fitting.md §7.6.

DEMO_VE := $(B)/demo_ve

.PHONY: demo-ve
demo-ve: $(B)/bin/tissuefit $(B)/lib/libtfit.a | deps-demo
	@mkdir -p $(DEMO_VE)
	@echo "== 1. native haptic loop (prony, stateful) against coeffs/block48_ve.h and libtfit.a =="
	$(Q)tests/firmware/haptic_config.sh coeffs/block48_ve.h >$(DEMO_VE)/haptic_config.h
	$(Q)$(CC) $(HOST_STRICT) -O2 -DHAPTIC_SCRIPT_PRESS_HOLD -Itarget/include -Itarget/examples \
	  -I$(DEMO_VE) -Icoeffs $(DEMO_LOOP) $(B)/lib/libtfit.a -o $(DEMO_VE)/haptic
	@echo "== 2. 1,000 ticks of 1 ms: press, hold (creep), release =="
	$(Q)HAPTIC_CSV=$(DEMO_VE)/ticks.csv $(DEMO_VE)/haptic | tee $(DEMO_VE)/haptic.txt
	@echo "== 3. every tick against the time-stepped solve =="
	$(Q)$(B)/bin/tissuefit -q replay coeffs/block48_ve.yaml --ticks $(DEMO_VE)/ticks.csv \
	  --png $(DEMO_VE)/deformed.png | tee $(DEMO_VE)/replay.txt
	$(Q)$(call demo_results,$(DEMO_VE),block48_ve_demo)
