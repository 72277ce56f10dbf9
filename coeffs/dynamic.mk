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

DYN_SCENES := coeffs/block48_dyn.yaml
DYN_HEADERS := $(DYN_SCENES:.yaml=.h)

.PHONY: coeffs-dyn check-coeffs-dyn
coeffs-dyn: $(B)/bin/tissuefit | deps-demo
	@mkdir -p $(REPORTS)
	@set -e; for s in $(DYN_SCENES); do echo "== $$s -> $${s%.yaml}.h"; \
	  OMP_NUM_THREADS=1 $(B)/bin/tissuefit fit $$s -o $${s%.yaml}.h --report $(REPORTS); done

CHECKS += check-coeffs-dyn
check-coeffs-dyn: $(B)/bin/tissuefit
	@echo "== shipped dynamic headers: regenerated = committed, byte for byte =="
	@set -e; for s in $(DYN_SCENES); do h=$${s%.yaml}.h; n=$$(basename $$h .h); \
	  mkdir -p $(B)/coeffs/dyn; \
	  OMP_NUM_THREADS=1 $(B)/bin/tissuefit -q fit $$s -o $(B)/coeffs/dyn/$$n.h; \
	  for f in $$n.h $${n}_golden.h; do \
	    if ! cmp -s $(B)/coeffs/dyn/$$f coeffs/$$f; then \
	      echo "coeffs/$$f differs from its regeneration: run make coeffs-dyn"; \
	      diff $(B)/coeffs/dyn/$$f coeffs/$$f | head -5; exit 1; fi; done; \
	  echo "ok: $$h: identical to its regeneration"; done
