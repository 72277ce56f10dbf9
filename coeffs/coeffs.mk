# coeffs.mk — the shipped headers: coeffs/NAME.h (+ NAME_golden.h) fitted
# from coeffs/NAME.yaml, with their reports in docs/reports/.
#
#   make coeffs    regenerate every shipped header and report
#   check-coeffs   regenerate each shipped header with 1 and with 2 threads
#                  (the two at once); both must be byte-identical to the
#                  committed files
#   check-fit      the held-out errors recomputed from a freshly fitted
#                  header, compiled, and fresh solves; `tissuefit fit`
#                  refusing bad scenes

SHIPPED_SCENES := coeffs/block48.yaml coeffs/block48_nh.yaml coeffs/liver.yaml coeffs/stomach.yaml \
                  coeffs/heart.yaml coeffs/block48_cut.yaml
# The organ headers (issue 15, tests/organs.mk): their golden files run to
# megabytes, so the firmware matrix (linker/firmware.mk) runs them on the
# Cortex-M4F only, in check-organs.
ORGAN_HEADERS := coeffs/liver.h coeffs/stomach.h coeffs/heart.h coeffs/liver_tumour.h
# A finer solution of each scene's physics, when one exists: the header then
# states the solve's error against it (tissuefit fit --reference).
export PHYSICS_block48 := tests/calculix/data/block48_physics.csv
# block48_nh: CalculiX NLGEOM (C3D20, neo-Hooke) at the 121 top points, 2.1 N along -z on
# the graded g0.6 mesh (0.7 of the 3 N path, the envelope's radius) and 1 N along +x
# on h1.2 (docs/calculix-reference.md, "What to use"; docs/fitting.md §7.8)
export PHYSICS_block48_nh := tests/calculix/data/block48_nh_physics.csv
# the liver: CalculiX's finest organ level s20r1 at the 240 output vertices
# (make calculix-organ-physics; docs/validation.md §14)
export PHYSICS_liver := tests/calculix/data/liver_physics.csv
# the stomach: CalculiX s20r1 at its 484 output vertices (make calculix-stomach)
export PHYSICS_stomach := tests/calculix/data/stomach_physics.csv
# the heart: CalculiX s20r1 at its output vertices (make calculix-heart)
export PHYSICS_heart := tests/calculix/data/heart_physics.csv
# block48_ve (seed 001's Kelvin law, the prony family): no CalculiX reference
# of the law; its header states the difference of the relaxed solve from a
# finer cloud's, 1 N along -z (make physics-ve-reference, tests/physics.mk;
# docs/fitting.md §7.6).  (It stated block48's static figure, assumed,
# with --discretisation-rel 0.0445,0.0711, before.)
export PHYSICS_block48_ve := tests/physics/data/block48_ve_physics.csv
# stomach_ve (the Kelvin law on the stomach): no reference of the law on
# this organ; its header states the tool's own measurement on the 16, 12
# and 9 mm clouds (their relaxed responses; the file's skin, so the
# interior's part of the error: docs/validation.md §16.1)
# liver_tumour: CalculiX NLGEOM on meshes that conform to its nodule, the
# finest level's three load levels (make calculix-liver-nh)
export PHYSICS_liver_tumour := tests/calculix/data/liver_tumour_physics.csv
# $$n's reference option, in the shell loops below
physics_arg = ref=$$(eval echo \$${PHYSICS_$$n}); if [ -n "$$ref" ]; then ref="--reference $$ref"; \
  else ref=$$(eval echo \$${DISCREL_$$n}); if [ -n "$$ref" ]; then ref="--discretisation-rel $$ref"; fi; fi
SHIPPED_HEADERS := $(SHIPPED_SCENES:.yaml=.h)
# Contact regions (docs/fitting.md §9): a law and a surface per header (no
# report: tissuefit fit --report does not take a region yet), no forward
# model or contact inverse, so not in check-fit's held-out check (the
# header states its errors at sites never fitted; check-region measures them
# at random sites) nor in the haptic-loop example's images (linker/firmware.mk);
# their golden vectors run natively (check-golden) and under QEMU (check-qemu).
REGION_SCENES := coeffs/block48_region.yaml
REGION_HEADERS := $(REGION_SCENES:.yaml=.h)
# Every shipped header make coeffs writes and check-coeffs compares: the
# viscoelastic block48_ve's prony model is checked by tests/prony.mk
# (check-prony-long, check-prony-ve), not by check-fit's static bounds.
COEFF_SCENES := $(SHIPPED_SCENES) coeffs/block48_ve.yaml coeffs/stomach_ve.yaml \
                coeffs/liver_tumour.yaml $(REGION_SCENES)
REPORTS := docs/reports

.PHONY: coeffs check-coeffs check-fit
CHECKS += check-coeffs check-fit

coeffs: $(B)/bin/tissuefit | deps-demo
	@mkdir -p $(REPORTS)
	@set -e; for s in $(COEFF_SCENES); do \
	  echo "== $$s -> $${s%.yaml}.h"; n=$$(basename $$s .yaml); $(physics_arg); \
	  rep="--report $(REPORTS)"; case " $(REGION_SCENES) " in *" $$s "*) rep=;; esac; \
	  $(B)/bin/tissuefit fit $$s -o $${s%.yaml}.h $$rep $$ref; done

# The thread counts each header is regenerated with: make check-full both
# (their bits must not depend on the count), make check the two threads a
# 2-core machine gives by default (test_conformance shows every solver's
# bits the same with one and two threads in both lengths).  Each
# regeneration is a file, $(B)/coeffs/tN/NAME.h (+ NAME_golden.h), fitted
# with the options make coeffs gives NAME (no report), so that make builds
# them side by side with everything else the checks need.
#
# make check regenerates the headers whose fits take seconds (block48,
# block48_cut, block48_region and the stomach: 8, 9, 10 and 25 s of CPU);
# make check-full also the slow ones, COEFF_SLOW (block48_ve 80 s,
# block48_nh about 640: 465 Newton solves on 2,205 nodes; liver and heart
# about 45 each), the slowest first.  Their families' fitters are run in
# make check by their own checks (check-prony-fit, check-demo-nh,
# check-resonant, check-organs' walkthrough).
COEFF_THREADS = $(call check_len,1 2,2)
COEFF_SLOW := coeffs/block48_nh.yaml coeffs/block48_ve.yaml coeffs/stomach_ve.yaml coeffs/liver.yaml \
              coeffs/heart.yaml
# liver_tumour (the neo-Hookean liver with its nodule, 10,995 nodes): its
# fit takes 19 minutes with two threads, 12 on two MPI ranks (75 Newton
# cases; the same bytes); make coeffs fits it, no check repeats it (its
# golden vectors run natively and on the M4F: check-python, check-organs)
COEFF_UNCHECKED := coeffs/liver_tumour.yaml
COEFF_CHECKED := $(call check_len,$(COEFF_SLOW) $(filter-out $(COEFF_SLOW) $(COEFF_UNCHECKED),$(COEFF_SCENES)),\
                   $(filter-out $(COEFF_SLOW) $(COEFF_UNCHECKED),$(COEFF_SCENES)))
COEFF_REGEN := $(foreach t,$(COEFF_THREADS),$(COEFF_CHECKED:coeffs/%.yaml=$(B)/coeffs/t$(t)/%.h))
.SECONDARY: $(COEFF_REGEN) $(COEFF_REGEN:.h=_golden.h)
# $(call regen_fit,THREADS): the recipe of one regeneration
regen_fit = n=$*; $(physics_arg); OMP_WAIT_POLICY=passive OMP_NUM_THREADS=$(1) \
  $(B)/bin/tissuefit -q fit $< -o $(@D)/$*.h $$ref
define regen_rule
$(B)/coeffs/t$(1)/%.h $(B)/coeffs/t$(1)/%_golden.h: coeffs/%.yaml $(B)/bin/tissuefit
	@mkdir -p $$(@D)
	$$(call say,FIT)
	$(Q)$$(call regen_fit,$(1))
endef
$(foreach t,1 2,$(eval $(call regen_rule,$(t))))
check-coeffs: $(COEFF_REGEN)
	@echo "== shipped headers: regenerated ($(subst $(space),$(comma) ,$(COEFF_THREADS)) thread(s)$(call check_len,,; short: not $(notdir $(COEFF_SLOW:.yaml=.h)))) = committed, byte for byte =="
	@r=0; for s in $(COEFF_CHECKED); do \
	  CC='$(CC) $(HOST_STRICT)' tests/fit/compare_regenerated.sh $$(basename $$s .yaml) $(B)/coeffs '$(COEFF_THREADS)' || r=1; \
	done; exit $$r

# The held-out check, one binary per shipped scene, compiled with a header
# fitted now by this build's tool where check-coeffs regenerates it (its
# comments may carry the error against the physics, its tables and golden
# vectors are the fit's): a change in the fitter shows here.  In make
# check, block48_nh's is the committed header (its regeneration is
# check-full's), and the liver and the heart (20 and 18 s of fresh organ
# solves) are check-full's; the stomach is make check's organ.
HELDOUT_SCENES := $(call check_len,$(SHIPPED_SCENES),$(filter-out coeffs/liver.yaml coeffs/heart.yaml,$(SHIPPED_SCENES)))
FRESH := $(T)/fresh$(call check_len,-full,)
FRESH_FITTED := $(filter $(COEFF_CHECKED),$(HELDOUT_SCENES))
FRESH_COMMITTED := $(filter-out $(COEFF_CHECKED),$(HELDOUT_SCENES))
.SECONDARY: $(HELDOUT_SCENES:coeffs/%.yaml=$(FRESH)/%.h)
$(FRESH_FITTED:coeffs/%.yaml=$(FRESH)/%.h): $(FRESH)/%.h: $(B)/coeffs/t$(lastword $(COEFF_THREADS))/%.h
	@mkdir -p $(@D)
	$(Q)cp $< $@ && cp $(<D)/$*_golden.h $(@D)/$*_golden.h
$(FRESH_COMMITTED:coeffs/%.yaml=$(FRESH)/%.h): $(FRESH)/%.h: coeffs/%.h
	@mkdir -p $(@D)
	$(Q)cp $< $@ && cp coeffs/$*_golden.h $(@D)/$*_golden.h
$(T)/heldout-%: tests/fit/heldout_check.c $(FRESH)/%.h $(B)/native/libtissuefit-host.a $(B)/native/libtest-support.a \
    $(B)/native/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)u=$$(echo $* | tr a-z A-Z); $(CC) $(TEST_CFLAGS) -I$(FRESH) -DHEADER='"$*.h"' \
	  -DFORWARD=tfit_$*_forward -DCONTACT=tfit_$*_contact -DPFX=TFIT_$$u \
	  -DTFIT_$${u}_IMPLEMENTATION $< $(call host_test_link,native) -o $@

# Bounds: 1 um for the linear forward model (the fitting issue's
# acceptance); the contact inverse within 4 float32 ulps of the force,
# relative (4 x 2^-23 = 4.8e-7; measured 7.5e-8 on block48: a linear tissue's
# degree-1 inverse is exact up to the float32 evaluation's rounding, a few
# ulps over its ~20 operations; a fit 7 times worse fails).
CONTACT_REL_BOUND := 4.8e-7
# A cut model's error is its interpolation in the cut progress s between
# the solved knots (docs/cutting.md, "Cut progress"): 27 um measured at the
# held-out s of block48_cut, of 2.36 mm; the bound is twice that.
export FORWARD_BOUND_block48_cut := 0.055
# The neo-Hookean block48 is not exact at any degree: its forward bound is
# the design target's 1 % of the largest displacement (5.57 mm; 0.0183 mm
# measured), its contact inverse's a regression bound over the measured
# 1.28 % (a relative error near the envelope's centre, where the force is small).
export FORWARD_BOUND_block48_nh := 0.0557
export CONTACT_BOUND_block48_nh := 0.02
# make check recomputes block48_nh's first 8 held-out cases, the anchors of
# its route, each solved from rest (17 s of Newton solves against 100 s for
# all 50; measured forward 0.0146 mm of the header's 0.0183, contact 0.00621
# N of 0.00984): each maximum at most the header's and at least a tenth of
# it; make check-full all 50, and the header's maxima and RMS to 1e-5.
export HELDOUT_FIRST_block48_nh := $(call check_len,,8)
# Every part of check-fit is a single-threaded line of tests/run_lines.sh,
# $(NPROC) at a time, the longest first (block48_nh's fresh Newton
# solves): the tool's tests run beside them, and no line's
# threads wait for another's core (two threads each cost about a third more
# CPU here for the same bits).
HELDOUT_ORDER := $(filter coeffs/block48_nh.yaml,$(HELDOUT_SCENES)) \
                 $(filter-out coeffs/block48_nh.yaml,$(HELDOUT_SCENES))
check-fit: $(HELDOUT_SCENES:coeffs/%.yaml=$(T)/heldout-%) $(B)/bin/tissuefit $(T)/extremes
	@h="echo '== fitted headers: held-out errors recomputed from the compiled header$(call check_len,, (short: not the liver and the heart; block48_nh: 8 of its 50 cases)) =='; "; \
	for s in $(HELDOUT_ORDER); do n=$$(basename $$s .yaml); \
	  b=$$(eval echo \$${FORWARD_BOUND_$$n}); c=$$(eval echo \$${CONTACT_BOUND_$$n}); \
	  f=$$(eval echo \$${HELDOUT_FIRST_$$n}); \
	  echo "$$h printf '%s: ' $$n; $(T)/heldout-$$n $$s $${b:-0.001} $${c:-$(CONTACT_REL_BOUND)} $$f"; h=; done | \
	{ cat; echo "echo '== material extremes: the stated bound holds at fresh forces =='; $(T)/extremes tests/solver/block48_seed.yaml 2>/dev/null"; \
	  echo "echo '== tissuefit fit: scenes it must refuse =='; tests/fit/cli_fit.sh $(B)/bin/tissuefit"; \
	  echo "echo '== tissuefit sweep and budget-driven choice =='; tests/fit/cli_sweep.sh $(B)/bin/tissuefit"; \
	  echo "echo '== tissuefit fit: the discretisation measured by the tool itself =='; tests/fit/cli_discretisation.sh $(B)/bin/tissuefit"; } | \
	  OMP_NUM_THREADS=1 tests/run_lines.sh $(NPROC) $(T)/fit-logs

# The speed-for-accuracy sweep of each shipped scene (docs/tradeoff.md); the
# native times are this machine's.
# block48_nh ships a rank <= 8 model (its fit: section), but its sweep
# shows the degrees and ranks beyond (docs/tradeoff.md §5); its scene
# outputs only, because a nonlinear scene re-solves its 465 load cases for
# every output set (about 6 minutes each here).
export SWEEP_block48_nh := --set fit.max_degree=6 --set fit.max_rank=12 --outputs scene
.PHONY: tradeoff
tradeoff: $(B)/bin/tissuefit | deps-demo
	@mkdir -p $(REPORTS)
	@set -e; for s in $(SHIPPED_SCENES); do n=$$(basename $$s .yaml); \
	  args=$$(eval echo \$${SWEEP_$$n}); \
	  $(B)/bin/tissuefit sweep $$s --csv $(REPORTS)/$${n}_sweep.csv --md $(REPORTS)/$${n}_sweep.md \
	    --png $(REPORTS)/$${n}_sweep.png $$args; done
	@set -e; for s in $(REGION_SCENES); do n=$$(basename $$s .yaml); \
	  $(B)/bin/tissuefit sweep $$s --csv $(REPORTS)/$${n}_sweep.csv --md $(REPORTS)/$${n}_sweep.md \
	    --png $(REPORTS)/$${n}_sweep.png; done

# Material extremes through the whole pipeline (issue 7 item 3).
$(T)/extremes: tests/fit/extremes.c $(B)/native/libtissuefit-host.a $(B)/native/libtest-support.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -O2 $< $(call host_test_link,native) -o $@

# make bench: the time to regenerate each shipped header, split into the
# solver's setup, the load cases' solves, the fits and the header.
REGEN_RUNS ?= 3
.PHONY: bench-regen
BENCHES += bench-regen
bench-regen: $(B)/bin/tissuefit
	@echo "== time to regenerate each shipped header: setup, solves, fits, header =="
	@tests/bench/bench_regen.sh $(B)/bin/tissuefit $(REGEN_RUNS) $(COEFF_SCENES)
