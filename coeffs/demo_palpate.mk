# demo_palpate.mk — `make demo-palpate`: palpation anywhere on the liver
# (tests/region/liver_region.yaml: 80 x 80 mm of the anterior surface, an
# 8 mm probe) through the firmware's region calls, replayed against true
# solves (coeffs/palpate/palpate.c; docs/firmware.md §12.1):
#
#   1. the scene's solver (one factorisation), the region's law and surface
#      fitted in-process at PALPATE_SPACING mm between sites and at most
#      PALPATE_RANK modes, built as device models and checked;
#   2. a probe pressing, sliding, lifting and pressing elsewhere, and a
#      second instrument for 1,400 of the 3,200 ticks, through
#      tfit_region_force / tfit_region_pair every tick and
#      tfit_region_surface / _surface_pair every 16, on the caller's states;
#   3. every PALPATE_EVERY-th display tick in contact against true site
#      solves: the force error (% of the envelope radius; target 2 %) and
#      the surface error (% of the peak displacement; target 5 %); the
#      demo fails above either;
#   4. the force map and the deformed surface at four ticks
#      (build/demo_palpate/*.png, *.vtk for ParaView).
#
#   demo-palpate-nodule: the same with a stiff nodule (a material region)
#      under the region's centre (build/demo_palpate/nodule/).
#
#   check-palpate (make check): the same program on block48's top face
#      (tests/region/block48_region.yaml: 38.4 x 38.4 mm, a 4.8 mm square
#      probe, 4.8 mm between sites), every fourth display tick replayed:
#      within the same targets, with ticks of two instruments compared and
#      errors that are not zero (a replay of the firmware against itself).

DEMO_PALPATE := $(B)/demo_palpate
PALPATE_SRC := $(wildcard coeffs/palpate/*.c)
PALPATE_SPACING ?= 5
PALPATE_RANK ?= 48
PALPATE_EVERY ?= 2

$(DEMO_PALPATE)/palpate: $(PALPATE_SRC) $(wildcard coeffs/palpate/*.h) \
    $(B)/native/libtissuefit-host.a $(B)/native/libtfit.a | deps-demo
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_CFLAGS) -O2 -I. $(PALPATE_SRC) $(B)/native/libtissuefit-host.a \
	  $(B)/native/libtfit.a $(HOST_LIBS) -o $@

.PHONY: demo-palpate
demo-palpate: $(DEMO_PALPATE)/palpate | deps-demo
	@echo "== palpating the liver's anterior region (80 x 80 mm): fit, firmware loop, replay against true solves, pictures =="
	$(Q)$< tests/region/liver_region.yaml $(DEMO_PALPATE) --rank $(PALPATE_RANK) \
	  --every $(PALPATE_EVERY) contact.0.spacing=$(PALPATE_SPACING) | tee $(DEMO_PALPATE)/palpate.txt

# The same liver with a stiff nodule under the region's centre (a material
# region: a sphere 16 mm across, 5 times the liver's E, its centre 18 mm
# under the rest surface at the chart's centre (-42.55, -64.98, 26.41),
# along the outward normal there (-0.448, -0.865, 0.225), its top 10 mm
# under the surface): the force map shows it.  It is the nodule of
# tests/calculix/scenes/liver_nodule.yaml, checked against CalculiX
# (docs/validation.md §18).
PALPATE_NODULE := 'inclusions.0.sphere.centre=-34.49,-49.41,22.36' inclusions.0.sphere.radius=8 \
    inclusions.0.material.E=0.0261 inclusions.0.material.nu=0.45 inclusions.0.name=nodule
.PHONY: demo-palpate-nodule
demo-palpate-nodule: $(DEMO_PALPATE)/palpate | deps-demo
	@echo "== palpating the liver's anterior region with a stiff nodule under it =="
	@mkdir -p $(DEMO_PALPATE)/nodule
	$(Q)$< tests/region/liver_region.yaml $(DEMO_PALPATE)/nodule --rank $(PALPATE_RANK) \
	  --every $(PALPATE_EVERY) contact.0.spacing=$(PALPATE_SPACING) $(PALPATE_NODULE) | \
	  tee $(DEMO_PALPATE)/nodule/palpate.txt
	@cp $(DEMO_PALPATE)/nodule/force_map.png docs/organs/liver_nodule_force_map.png

.PHONY: check-palpate
CHECKS += check-palpate
check-palpate: $(DEMO_PALPATE)/palpate
	@echo "== palpation through the firmware's region calls, replayed: block48's top face =="
	@mkdir -p $(DEMO_PALPATE)/check
	@$< tests/region/block48_region.yaml $(DEMO_PALPATE)/check --every 4 --map 21 \
	  contact.0.spacing=4.8 | tee $(DEMO_PALPATE)/check/palpate.txt
	@grep -q "^replay: .* with two instruments" $(DEMO_PALPATE)/check/palpate.txt
	@! grep -qE "force error 0\.000 %|surface error 0\.000 %" $(DEMO_PALPATE)/check/palpate.txt || \
	  { echo "the replay found no error at all: it compared the firmware with itself"; exit 1; }
	@echo "ok: block48's region palpated with one and two instruments, force and surface within 2 % and 5 % of true solves"
