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

# demo-nh: the same loop on block48_nh (neo-Hookean, 3 N envelope, issue
# 14): the shipped coeffs/block48_nh.h, the script's forces scaled by 3,
# every tick against a true nonlinear solve (a thousand solves from rest:
# over 30 minutes on a loaded 2-core machine; no result committed yet).
.PHONY: demo-nh
demo-nh: $(B)/bin/tissuefit $(B)/lib/libtfit.a | deps-demo
	@mkdir -p $(DEMO)/nh
	@echo "== 1. native haptic loop against coeffs/block48_nh.h (the shipped header) =="
	$(Q)tests/firmware/haptic_config.sh coeffs/block48_nh.h >$(DEMO)/nh/haptic_config.h
	$(Q)$(CC) $(HOST_STRICT) -O2 -DHAPTIC_FORCE_SCALE=3.0f -Itarget/include -Itarget/examples \
	  -Icoeffs -I$(DEMO)/nh $(DEMO_LOOP) $(B)/lib/libtfit.a -o $(DEMO)/nh/haptic
	@echo "== 2. 1,000 ticks: press 2.4 N, sweep, release, a push beyond the envelope, a NaN =="
	$(Q)HAPTIC_CSV=$(DEMO)/nh/ticks.csv $(DEMO)/nh/haptic
	@echo "== 3. every tick against a true solve =="
	$(Q)$(B)/bin/tissuefit -q replay coeffs/block48_nh.yaml --ticks $(DEMO)/nh/ticks.csv \
	  --png $(DEMO)/nh/deformed.png
