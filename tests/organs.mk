# organs.mk — the shipped organ scenes: coeffs/{liver,stomach,heart,liver_tumour}.
#
#   check-organs    each organ header's output map against its mesh file
#                   and scene (vertex index, positions, CRC) and its servo
#                   budget at 1 kHz on a Cortex-M4F (tests/organs/map_check.c)
#   organ-pictures  the organs at rest and deformed (docs/organs/*.png) and
#                   their VTK files for ParaView (build/organs/*.vtu); at
#                   rest, the surface over a material region green
#   bench-organs    (make bench) the organ models' native speed; their
#                   regeneration times are bench-regen's (coeffs.mk)
#   organ-subsets   what the near-contact outputs leave out: the largest
#                   displacement of a surface vertex that is not an output
# The headers' held-out errors are recomputed by check-fit (coeffs.mk) and
# the liver is compared with CalculiX by check-organ-calculix
# (tests/calculix_organ.mk).

ORGAN_SCENES := coeffs/liver.yaml coeffs/stomach.yaml coeffs/heart.yaml coeffs/liver_tumour.yaml
ORGAN_NAMES := $(ORGAN_SCENES:coeffs/%.yaml=%)

.PHONY: check-organs organ-pictures bench-organs organ-subsets
CHECKS += check-organs
BENCHES += bench-organs

$(T)/organs/map-%: tests/organs/map_check.c coeffs/%.h $(B)/native/libtissuefit-host.a $(B)/native/libtest-support.a \
    $(B)/native/libtfit.a | deps-check
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)u=$$(echo $* | tr a-z A-Z); $(CC) $(TEST_CFLAGS) -Icoeffs -DHEADER='"$*.h"' \
	  -DFORWARD=tfit_$*_forward -DPFX=TFIT_$$u -DMAP=tfit_$* -DTFIT_$${u}_IMPLEMENTATION $< \
	  $(call host_test_link,native) -o $@

# Golden vectors of the organ headers on the Cortex-M4F (QEMU mps2-an386).
$(foreach h,$(ORGAN_HEADERS),$(eval $(call fw_golden,$(h),m4f)))

# The new-organ walkthrough (docs/scene-format.md) draws with gnuplot.
DEBS_CHECK += gnuplot-nox
check-organs: $(ORGAN_NAMES:%=$(T)/organs/map-%) $(ORGAN_NAMES:%=$(FW)/m4f/golden-%.elf) $(B)/bin/tissuefit
	@echo "== organ headers: output maps against the mesh files, servo budget at 1 kHz on M4F, golden vectors on M4F; the new-organ walkthrough =="
	@set -e; for n in $(ORGAN_NAMES); do $(T)/organs/map-$$n coeffs/$$n.yaml; done
	@set -e; for n in $(ORGAN_NAMES); do tests/firmware/qemu_run.sh mps2-an386 $(FW)/m4f/golden-$$n.elf; done
	@tests/cli/guide_walkthrough.sh $(B)/bin/tissuefit ../shared/data/meshes/derived/liver_vtk_main.obj
	@echo "ok: organ headers map their outputs to the mesh files, fit a 1 kHz tick and pass their golden vectors on M4F; the new-organ walkthrough runs as written"

# The force of each picture: the envelope's largest, into the organ at its
# site; displacements drawn to scale, or magnified where a dent of a
# millimetre or two would not show on an organ ten centimetres across (the
# title says so).
ORGAN_FORCE_liver := 0,0.3,0
ORGAN_FORCE_stomach := 0,0.3,0
ORGAN_FORCE_heart := -0.3,0,0
ORGAN_MAGNIFY_liver := 1
ORGAN_MAGNIFY_stomach := 5
ORGAN_MAGNIFY_heart := 5
# liver_tumour: pressed over its nodule along the inward normal (its
# reference's direction), the nodule's footprint green at rest
ORGAN_FORCE_liver_tumour := 0.1344,0.2595,-0.0675
ORGAN_MAGNIFY_liver_tumour := 1
ORGAN_PICTURES := $(ORGAN_NAMES)

# $(call organ_picture,NAME)
organ_picture = $(B)/bin/tissuefit -q solve coeffs/$(1).yaml --force $(ORGAN_FORCE_$(1)) \
  -o $(B)/organs/$(1).csv --vtk $(B)/organs/$(1).vtu --png-rest docs/organs/$(1)_rest.png \
  --png docs/organs/$(1)_deformed.png --exaggerate $(ORGAN_MAGNIFY_$(1));

organ-pictures: $(B)/bin/tissuefit | deps-demo
	@echo "== organ pictures: docs/organs/*_{rest,deformed}.png, $(B)/organs/*.vtu =="
	@mkdir -p docs/organs $(B)/organs
	@set -e; $(foreach n,$(ORGAN_PICTURES),$(call organ_picture,$(n)))

# Native speed and instruction counts of the organ models (tests/bench/run.sh).
$(foreach h,$(ORGAN_HEADERS),$(eval $(call bench_binary,$(h))))

# Native speed and instruction counts of the organ models; their
# regeneration times are in bench-regen (coeffs.mk: every shipped scene).
bench-organs: $(foreach h,$(ORGAN_HEADERS),$(B)/bench/bench-$(call fw_name,$(h)))
	@echo "== organ models: native speed and instructions per evaluation =="
	@set -e; $(foreach h,$(ORGAN_HEADERS),tests/bench/run.sh $(B)/bench/bench-$(call fw_name,$(h)) $(h) $(BENCH_CALLS);)

$(T)/organs/subset_report: tests/organs/subset_report.c $(B)/native/libtissuefit-host.a $(B)/native/libtest-support.a \
    $(B)/native/libtfit.a | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -O2 $< $(call host_test_link,native) -o $@

organ-subsets: $(T)/organs/subset_report
	@echo "== organs: what the near-contact outputs leave out (the envelope's force along x, y, z) =="
	@$< $(ORGAN_SCENES)
