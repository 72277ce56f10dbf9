# dynamic.mk — the shipped dynamic scene (issue 16): block48 struck and
# released, MLS collocation with explicit dynamics, the resonant family.
# Apart from SHIPPED_SCENES (coeffs.mk) because its forward model is
# stateful: check-fit's static held-out check does not apply (its held-out
# histories are in its report, docs/reports/block48_dyn.md).  Its header is
# in the firmware matrix like every coeffs/*.h (linker/firmware.mk: golden
# vectors on the QEMU boards, check-cycles); check-resonant runs its golden
# vectors and 10^6 ticks natively, `make resonant-long-qemu` the 10^6 ticks
# under QEMU.
#
#   make coeffs-dyn     coeffs/block48_dyn.h (+ _golden.h) and
#                       docs/reports/block48_dyn.md with its plots
#   check-coeffs-dyn    regenerated (one thread) = committed, byte for byte
#                       (make check runs it inside check-coeffs)

DYN_SCENES := coeffs/block48_dyn.yaml
DYN_HEADERS := $(DYN_SCENES:.yaml=.h)

.PHONY: coeffs-dyn check-coeffs-dyn
coeffs-dyn: $(B)/bin/tissuefit | deps-demo
	@mkdir -p $(REPORTS)
	@set -e; for s in $(DYN_SCENES); do echo "== $$s -> $${s%.yaml}.h"; \
	  OMP_NUM_THREADS=1 $(B)/bin/tissuefit fit $$s -o $${s%.yaml}.h --report $(REPORTS); done

# make check-full's check-coeffs regenerates them among the other shipped
# scenes (coeffs.mk, $(B)/coeffs/t1/); check-coeffs-dyn is that part alone.
DYN_REGEN := $(DYN_SCENES:coeffs/%.yaml=$(B)/coeffs/t1/%.h)
.SECONDARY: $(DYN_REGEN) $(DYN_REGEN:.h=_golden.h)
check-coeffs: $(call check_len,$(DYN_REGEN),)
check-coeffs-dyn: $(DYN_REGEN)
	@echo "== shipped dynamic headers: regenerated (1 thread) = committed, byte for byte =="
	@set -e; for s in $(DYN_SCENES); do \
	  CC='$(CC) $(HOST_STRICT)' tests/fit/compare_regenerated.sh $$(basename $$s .yaml) $(B)/coeffs 1; done
