# region.mk — contact regions ("palpation anywhere"): the host's site solves,
# the fitted law and surface, judged at sites never fitted.
#
#   check-region   (make check) block48's region targets: the whole top face
#                  by tissuefit fit's rule, 200 held-out sites x 5 forces,
#                  force <= 1 % of the envelope radius, surface <= 5 % of
#                  the peak displacement; and on a 9.6 mm square at 1.2 mm
#                  sites (40 held-out sites, 10 two-instrument cases), two
#                  instruments <= 2 %
#   region-study   the tables over site spacing and rank for block48's top
#                  face and the liver's anterior surface (200 held-out sites
#                  x 5 forces, 50 two-instrument cases each; minutes)
#   region-nonlinear neo-Hookean block48: (site, force) cases through the
#                  case runner, per-site potentials of degree 2 to 4

REGION_STUDY := $(T)/region/region_study

$(REGION_STUDY): tests/region/region_study.c $(B)/native/libtissuefit-host.a \
    $(B)/native/libtest-support.a $(B)/native/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -O2 $< $(call host_test_link,native) -o $@

.PHONY: check-region region-study
CHECKS += check-region

check-region: $(REGION_STUDY)
	@echo "== contact regions: block48's whole top face [4.8, 43.2]^2 by tissuefit fit's rule (at most 48 modes and the near field), at sites never fitted =="
	@$(REGION_STUDY) tests/region/block48_region.yaml --device --sites 200 --forces 5 --pairs 0 \
	  --assert 1,5,100
	@echo "== two instruments: a 9.6 mm square of the face, 1.2 mm sites, the rank searched to 512 =="
	@$(REGION_STUDY) tests/region/block48_region.yaml --rect 19.2,28.8,19.2,28.8 --sites 40 \
	  --forces 5 --pairs 10 --assert 1,5,2 contact.0.spacing=1.2
	@echo "ok: block48's region law within 1 % and surface within 5 % at 200 held-out sites of the whole face; two instruments within 2 % on the square"

region-study: $(REGION_STUDY)
	@echo "== contact regions: block48's top face [4.8, 43.2]^2, 4.8 mm square probe =="
	@$(REGION_STUDY) tests/region/block48_region.yaml --levels 3
	@echo "== the same on coeffs/block48.yaml's grading (3, 3, 2) =="
	@$(REGION_STUDY) tests/region/block48_region.yaml --levels 2 --pairs 0 geometry.grading=3,3,2
	@echo "== contact regions: the liver's anterior surface, 80 x 80 mm, 8 mm probe =="
	@$(REGION_STUDY) tests/region/liver_region.yaml --levels 3

# A region whose response is not affine: block48_nh's (site, force) cases
# through the case runner, per-site potentials of degree 2 to 4 (minutes).
REGION_NONLINEAR := $(T)/region/region_nonlinear

$(REGION_NONLINEAR): tests/region/region_nonlinear.c $(B)/native/libtissuefit-host.a \
    $(B)/native/libtest-support.a $(B)/native/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -O2 $< $(call host_test_link,native) -o $@

.PHONY: region-nonlinear
region-nonlinear: $(REGION_NONLINEAR)
	@echo "== contact regions, neo-Hookean block48: 19.2 mm square of the top face, 4 x 4 sites =="
	@$(REGION_NONLINEAR) tests/region/block48_nh_region.yaml --rect 14.4,33.6,14.4,33.6 \
	  --grid 4 --centres 3 --train 24 --heldout 6

# The liver's region law against CalculiX at three sites never fitted
# (cell centres of the 4 mm grid tissuefit fit chooses: 2.8 mm from the
# nearest site), loaded over the same probe patch (organ_deck --sites,
# tests/calculix/region_dat.awk: the patch-averaged compliance;
# docs/validation.md §14.2).
#   calculix-liver-region  runs CalculiX on the sites (about 45 minutes with
#                          two threads, 8 GB): the liver's levels as they are
#                          (liver_region_*), the skin refined at the patches'
#                          edges to 1 mm (liver_region_p1_*; s20r1 is the
#                          finest) and, at s20r0, to 0.5 and 0.25 mm, and
#                          site 3 alone graded towards it (2 and 1.5 mm
#                          within 20 mm, liver_region_site3_*); rewrites
#                          tests/calculix/data/liver_region*.csv, then
#   region-calculix        the tables from the committed data: the scene's
#                          6 mm cloud, the shipped liver's (5 mm, refined
#                          skin), 4 mm, and 5 mm with 3 and 2 mm nodes
#                          near the region, each fitted by tissuefit fit's
#                          rule (about 17 minutes)
#   check-region-calculix  (make check) the deck writer at s20r0: each site's
#                          loads sum to 1 N and its site point is the
#                          committed data's
REGION_CALCULIX := $(T)/region/region_calculix
REGION_CX_SCENE := tests/region/liver_region.yaml
REGION_CX_SITES := 18,62:42,38:66,18
REGION_CX_FINEST := $(CX_DATA)/liver_region_p1_s20r1.csv
REGION_CX_OTHERS := $(foreach l,s20r0 s10r0 s20r1 p1_s20r0 p0.5_s20r0 p0.25_s20r0,\
  $(CX_DATA)/liver_region_$(l).csv)
# the shipped liver's cloud (coeffs/liver.yaml)
REGION_CX_LIVER := geometry.spacing=5 geometry.refine_skin=true

$(REGION_CALCULIX): tests/region/region_calculix.c $(B)/native/libtissuefit-host.a \
    $(B)/native/libtest-support.a $(B)/native/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -O2 $< $(call host_test_link,native) -o $@

.PHONY: calculix-liver-region region-calculix check-region-calculix
CHECKS += check-region-calculix

# $(call region_ccx,NAME,SITES,ARGS,LEVELS): organ_deck --sites SITES ARGS at
# each level, extracted by region_dat.awk into CX_DATA/NAME_<level>.csv
define region_ccx
	$(Q)CCX_THREADS=$${CCX_THREADS:-2} DAT_AWK=region_dat.awk DECK_ARGS="--sites $(2) $(3)" \
	  tests/calculix/run_organ.sh $(CX)/organ_deck $(REGION_CX_SCENE) $(CX)/$(1) $(CX_DATA) $(1) $(4)

endef
calculix-liver-region: $(CX)/organ_deck | deps-calculix
	$(call region_ccx,liver_region,$(REGION_CX_SITES),,s20r0:20:0 s10r0:10:0 s20r1:20:1)
	$(call region_ccx,liver_region_p1,$(REGION_CX_SITES),--patch-refine 1,s20r0:20:0 s20r1:20:1)
	$(call region_ccx,liver_region_p0.5,$(REGION_CX_SITES),--patch-refine 0.5,s20r0:20:0)
	$(call region_ccx,liver_region_p0.25,$(REGION_CX_SITES),--patch-refine 0.25,s20r0:20:0)
	$(call region_ccx,liver_region_site3_g2,66$(comma)18,--patch-refine 0.5,s20r0:20:0:2)
	$(call region_ccx,liver_region_site3_g1.5,66$(comma)18,--patch-refine 0.25,s20r0:20:0:1.5)
	@$(MAKE) --no-print-directory region-calculix

region-calculix: $(REGION_CALCULIX)
	@echo "== the trace of each CalculiX level's compliance (mm/N) per site =="
	@for f in $(CX_DATA)/liver_region*_s[0-9]*r[0-9].csv; do awk -F, -v f=$$(basename $$f .csv) \
	  'FNR > 1 { k = index("xyz", substr($$7, 2, 1)); t[$$1] += $$(7 + k); a[$$1] = $$2 "," $$3; n = $$1 > n ? $$1 : n } \
	   END { printf "%s:", f; for (s = 1; s <= n; s++) if (s in t) printf " (%s) %.4g;", a[s], t[s]; print "" }' $$f; done
	@echo "== the liver's region law against CalculiX at three sites never fitted: the scene's 6 mm cloud =="
	@$< $(REGION_CX_SCENE) $(REGION_CX_FINEST) $(REGION_CX_OTHERS)
	@echo "== the same on the shipped liver's cloud ($(REGION_CX_LIVER)) =="
	@$< $(REGION_CX_SCENE) $(REGION_CX_FINEST) $(REGION_CX_OTHERS) $(REGION_CX_LIVER)
	@echo "== the same at 4 mm (geometry.spacing=4 geometry.refine_skin=true) =="
	@$< $(REGION_CX_SCENE) $(REGION_CX_FINEST) $(REGION_CX_OTHERS) geometry.spacing=4 \
	  geometry.refine_skin=true
	@echo "== the same at 5 mm with 3 mm nodes within 45 mm of the region's centre =="
	@$< $(REGION_CX_SCENE) $(REGION_CX_FINEST) $(REGION_CX_OTHERS) $(REGION_CX_LIVER) \
	  'geometry.refine={at: [-50, -80, 25], spacing: 3, radius: 45, ramp: 65}'
	@echo "== the same with 2 mm nodes there =="
	@$< $(REGION_CX_SCENE) $(REGION_CX_FINEST) $(REGION_CX_OTHERS) $(REGION_CX_LIVER) \
	  'geometry.refine={at: [-50, -80, 25], spacing: 2, radius: 45, ramp: 65}'

check-region-calculix: $(CX)/organ_deck
	@echo "== the region deck writer (organ_deck --sites --patch-refine 1, s20r0): each site's loads sum to 1 N, its site point is the committed data's =="
	@mkdir -p $(CX)
	@$< $(REGION_CX_SCENE) --spacing 20 --refine 0 --sites $(REGION_CX_SITES) --patch-refine 1 \
	  > $(CX)/check_region_s20r0.inp
	@awk -f tests/calculix/check_region_deck.awk $(CX)/check_region_s20r0.inp $(REGION_CX_FINEST)
	@for bad in "--sites 18,62:" "--sites 18" "--patch-refine 1"; do \
	  if $< $(REGION_CX_SCENE) --spacing 20 $$bad > $(CX)/check_region_bad.inp 2> /dev/null \
	     || [ $$? -ne 2 ] || [ -s $(CX)/check_region_bad.inp ]; then \
	    echo "FAILED: organ_deck $$bad: not refused with exit 2 and nothing written"; exit 1; fi; done
	@echo "ok: a trailing ':', a site without b, --patch-refine without --sites refused (exit 2, nothing written)"
