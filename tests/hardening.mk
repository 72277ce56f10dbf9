# hardening.mk — hostile scenes, command lines and outputs (issue 19).
#
#   check-hostile   tests/cli/hostile.sh: strict scene values, file:line:field
#                   for absurd ones, non-regular scene paths, outputs checked
#                   before the solve, standard output on a full disk, a fit
#                   on 3 outputs, replay with a NaN
#   check-outputs   tests/cli/outputs.sh: NAME.h and NAME_golden.h change
#                   together (a full disk, SIGTERM while writing and at the
#                   first rename, SIGKILL between the renames, through
#                   tests/cli/rename_fault.c), non-regular
#                   destinations, links written through, hostile text in
#                   generated comments compiled by gcc and clang
#   check-interrupts  (not in make check: about a minute) tests/cli/interrupts.sh:
#                   INTERRUPTS (50) SIGINT/SIGTERM/SIGKILL sent to fit's process at
#                   random moments around its writes (check-outputs sends
#                   them at chosen points, deterministically)
#   (the fuzz targets: tests/fuzz.mk; unit tests: test_scene_hostile.c,
#   test_neighbours.c, test_emit.c)

.PHONY: check-hostile check-outputs check-interrupts
CHECKS += check-hostile check-outputs
INTERRUPTS ?= 50

$(T)/rename_fault.so: tests/cli/rename_fault.c | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(STRICT) -shared -fPIC $< -o $@

check-hostile: $(B)/bin/tissuefit
	@echo "== hostile scenes and command lines =="
	@tests/cli/hostile.sh $(B)/bin/tissuefit

check-outputs: $(B)/bin/tissuefit $(B)/native/libtfit.a $(T)/rename_fault.so
	@echo "== outputs that belong together: header and golden file =="
	@tests/cli/outputs.sh $(B)/bin/tissuefit $(B)/native/libtfit.a $(T)/rename_fault.so

check-interrupts: $(B)/bin/tissuefit
	@echo "== $(INTERRUPTS) signals at random moments of fit =="
	@tests/cli/interrupts.sh $(B)/bin/tissuefit $(INTERRUPTS)
