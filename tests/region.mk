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
