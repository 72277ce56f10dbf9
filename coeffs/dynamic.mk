# dynamic.mk — the shipped dynamic scene (issue 16): block48 struck and
# released, MLS collocation with explicit dynamics, the resonant family.
# Apart from SHIPPED_SCENES (coeffs.mk) because its forward model is
# stateful (check-fit's static held-out check does not apply: its
# held-out histories are in its report) and because the firmware matrix's
# cycle model does not describe the resonant family yet (linker/firmware.mk
# leaves it out of FW_SHIPPED; check-resonant runs it natively and
# `make resonant-long-qemu` under QEMU).
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
