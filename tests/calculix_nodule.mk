# calculix_nodule.mk — material regions (scene key inclusions) against
# CalculiX meshes that conform to them (docs/validation.md, "Material
# regions against CalculiX").
#
#   make calculix-nodule        CalculiX on block48 with a stiff sphere under
#                               its patch, and on the liver with a stiff
#                               nodule pressed over it and 30 mm beside it, at
#                               the levels below (about an hour, one thread);
#                               rewrites tests/calculix/data/NAME_*.csv, then
#                               the table
#   make calculix-nodule-table  from the committed data and fresh meshless
#                               solves: each CalculiX level and the meshless
#                               solve at several node spacings against the
#                               finest level, and the nodule's signal (the
#                               stiffness a probe feels over it minus
#                               beside it); build/calculix/nodule.md
#   check-nodule-calculix       (make check) block48's sphere at 41 x 41 x 9
#                               within 3 % of the finest level at the contact
#                               and over the outputs (L2), and in
#                               neo-Hookean tissue at 21 x 21 x 5 against
#                               CalculiX NLGEOM at four load levels; make check-full
#                               adds the liver pressed over and beside its
#                               nodule (two solves of about 75 s of CPU each):
#                               the one over it within 3 %, and the nodule's
#                               signal within 10 % of the finest level's; the
#                               deck writer's h24r0 deck of block48_sphere
#                               has the committed level's counts
#
# A level is label:spacing:refine[:grade] (organ_deck.c); the inclusion's
# surface has edges of at most the --inclusion-spacing of its ARGS and is
# meshed at that size (halved by each refinement).  block48 is meshed from its surface split
# into 1.2 mm squares (the patch's edges and the 4.8 mm output grid on
# their lines).
NODULE_BOX := tests/calculix/scenes/block48_sphere.yaml
NODULE_OVER := tests/calculix/scenes/liver_nodule.yaml
NODULE_BESIDE := tests/calculix/scenes/liver_nodule_beside.yaml
NODULE_BOX_ARGS := --quantum 1.2 --inclusion-spacing 0.5
NODULE_BOX_LEVELS := h24r0:2.4:0 h12r0:1.2:0 h24r1:2.4:1
NODULE_BOX_FINEST := h24r1
NODULE_LIVER_ARGS := --inclusion-spacing 2
NODULE_LIVER_LEVELS := s20r0:20:0 s10r0:10:0 s20r1:20:1
NODULE_LIVER_FINEST := s20r1
# the meshless convergence tables: block48's grids; the liver pressed over
# its nodule at uniform spacings (refine at the same spacing: none), then at
# 6 mm refined to finer spacings within 30 mm of the probe (the scenes' own:
# 2 mm)
NODULE_BOX_GRIDS := 11,11,3 21,21,5 41,41,9 61,61,13
NODULE_LIVER_CLOUDS := 9:9 6:6 4.5:4.5 6:4.5 6:3 6:2
NODULE_BOUND := 0.03
NODULE_SIGNAL_BOUND := 0.10

# Large deformation (tests/calculix/scenes/block48_sphere_nh.yaml: both
# materials neo-Hookean): CalculiX NLGEOM at the levels below, the normal
# force ramped to NODULE_NH_FORCE and printed at NODULE_NH_STEPS equal
# levels (organ_deck --nlgeom), against the Newton solves at the grids
# below (tests/calculix/organ_nl_compare.sh).
#   make calculix-nodule-nh        the CalculiX runs (h24r0 3.3 minutes,
#                                  h12r0 10, one thread); rewrites
#                                  tests/calculix/data/block48_sphere_nh_*.csv
#   make calculix-nodule-nh-table  the other level and the meshless grids
#                                  against the finest level, at every load
#                                  level; build/calculix/nodule_nh.md
NODULE_NH := tests/calculix/scenes/block48_sphere_nh.yaml
NODULE_NH_FORCE := 0,0,-3
NODULE_NH_STEPS := 4
NODULE_NH_LEVELS := h24r0:2.4:0 h12r0:1.2:0
NODULE_NH_FINEST := h12r0
NODULE_NH_GRIDS := geometry.grid=11,11,3 geometry.grid=21,21,5 geometry.grid=41,41,9

.PHONY: calculix-nodule calculix-nodule-table check-nodule-calculix calculix-nodule-nh \
        calculix-nodule-nh-table
CHECKS += check-nodule-calculix

calculix-nodule: $(CX)/organ_deck | deps-calculix
	$(Q)DECK_ARGS="$(NODULE_BOX_ARGS)" tests/calculix/run_organ.sh $< $(NODULE_BOX) \
	  $(CX)/nodule/block48_sphere $(CX_DATA) block48_sphere $(NODULE_BOX_LEVELS)
	$(Q)for s in $(NODULE_OVER) $(NODULE_BESIDE); do n=$$(basename $$s .yaml); \
	  DECK_ARGS="$(NODULE_LIVER_ARGS)" tests/calculix/run_organ.sh $< $$s $(CX)/nodule/$$n $(CX_DATA) \
	    $$n $(NODULE_LIVER_LEVELS) || exit 1; done
	@$(MAKE) --no-print-directory calculix-nodule-table

# $(call nodule_levels,NAME,FINEST,LEVELS): each coarser level against FINEST
define nodule_levels
for l in $(3); do n=$${l%%:*}; [ $$n = $(2) ] && continue; \
  echo; echo "CalculiX $(1) $$n against $(2):"; echo; \
  $(CX)/organ_compare $(CX_DATA)/$(1)_$(2).csv --csv $(CX_DATA)/$(1)_$$n.csv || exit 1; done
endef

calculix-nodule-table: $(CX)/organ_compare
	@mkdir -p $(CX)
	@set -e; { \
	  $(call nodule_levels,block48_sphere,$(NODULE_BOX_FINEST),$(NODULE_BOX_LEVELS)); \
	  for g in $(NODULE_BOX_GRIDS); do echo; echo "meshless block48_sphere, grid $$g, against $(NODULE_BOX_FINEST):"; echo; \
	    $(CX)/organ_compare $(CX_DATA)/block48_sphere_$(NODULE_BOX_FINEST).csv $(NODULE_BOX) \
	      --set geometry.grid=$$g || true; done; \
	  for s in liver_nodule liver_nodule_beside; do \
	    $(call nodule_levels,$${s},$(NODULE_LIVER_FINEST),$(NODULE_LIVER_LEVELS)); done; \
	  for c in $(NODULE_LIVER_CLOUDS); do h=$${c%%:*} r=$${c##*:}; \
	    echo; echo "meshless liver_nodule, spacing $$h mm, $$r mm within 30 mm of the probe, against $(NODULE_LIVER_FINEST):"; echo; \
	    $(CX)/organ_compare $(CX_DATA)/liver_nodule_$(NODULE_LIVER_FINEST).csv $(NODULE_OVER) \
	      --set geometry.spacing=$$h --set geometry.refine.spacing=$$r || true; done; \
	  echo; echo "the nodule's signal, CalculiX levels finest first, then the meshless solves:"; echo; \
	  $(CX)/organ_compare --signal $(NODULE_OVER) $(NODULE_BESIDE) \
	    $(foreach l,$(NODULE_LIVER_FINEST) $(filter-out $(NODULE_LIVER_FINEST),$(foreach l,$(NODULE_LIVER_LEVELS),$(firstword $(subst :, ,$(l))))),\
	      $(CX_DATA)/liver_nodule_$(l).csv $(CX_DATA)/liver_nodule_beside_$(l).csv); \
	} | tee $(CX)/nodule.md

NODULE_BOX_CHECK_GRID := 41,41,9
NODULE_NH_CHECK_GRID := 21,21,5
check-nodule-calculix: $(CX)/organ_compare $(CX)/organ_deck $(B)/bin/tissuefit
	@echo "== material regions against CalculiX meshes that conform to them (finest levels; bound $(NODULE_BOUND)$(call check_len,$(comma) the liver's signal $(NODULE_SIGNAL_BOUND),; short: block48 only$(comma) make check-full adds the liver)) =="
	@$< $(CX_DATA)/block48_sphere_$(NODULE_BOX_FINEST).csv $(NODULE_BOX) $(NODULE_BOUND) \
	  --set geometry.grid=$(NODULE_BOX_CHECK_GRID)
	@echo "== the same sphere in neo-Hookean tissue against CalculiX NLGEOM ($(NODULE_NH_FINEST)), Newton at $(NODULE_NH_CHECK_GRID), every load level =="
	@BOUND=$(NODULE_BOUND) tests/calculix/organ_nl_compare.sh $(B)/bin/tissuefit $(NODULE_NH) $(NODULE_NH_FORCE) \
	  $(NODULE_NH_STEPS) $(CX_DATA)/block48_sphere_nh_$(NODULE_NH_FINEST).csv geometry.grid=$(NODULE_NH_CHECK_GRID)
	$(call check_len,@$< --signal $(NODULE_OVER) $(NODULE_BESIDE) \
	  $(CX_DATA)/liver_nodule_$(NODULE_LIVER_FINEST).csv \
	  $(CX_DATA)/liver_nodule_beside_$(NODULE_LIVER_FINEST).csv --bound $(NODULE_SIGNAL_BOUND) \
	  --bound-u $(NODULE_BOUND),)
	@echo "== the deck writer: block48_sphere's h24r0 deck has the committed level's size =="
	@$(CX)/organ_deck $(NODULE_BOX) --spacing 2.4 $(NODULE_BOX_ARGS) > $(CX)/check_sphere_h24r0.inp
	@got=$$(awk '$$1 == "**" && $$2 == "SIZE" { print $$3 "," $$4 "," $$5; exit }' $(CX)/check_sphere_h24r0.inp); \
	  want=$$(awk -F, '$$1 == "h24r0" { print $$5 "," $$6 "," $$7 }' $(CX_DATA)/block48_sphere_runs.csv); \
	  if [ "$$got" != "$$want" ]; then echo "organ_deck: h24r0 elements,nodes,dofs $$got, the reference's $$want"; exit 1; fi
	@echo "== the deck writer: an NLGEOM deck of block48_sphere_nh has its neo-Hookean materials, one ramped step and its load levels =="
	@$(CX)/organ_deck $(NODULE_NH) --spacing 2.4 $(NODULE_BOX_ARGS) --nlgeom $(NODULE_NH_FORCE) \
	  --levels $(NODULE_NH_STEPS) > $(CX)/check_sphere_nh_h24r0.inp
	@n=$$(grep -c '^\*HYPERELASTIC, NEO HOOKE$$' $(CX)/check_sphere_nh_h24r0.inp); \
	  s=$$(grep -c '^\*STEP, NLGEOM' $(CX)/check_sphere_nh_h24r0.inp); \
	  l=$$(grep -c '^\*\* STEP [0-9]* l[0-9]' $(CX)/check_sphere_nh_h24r0.inp); \
	  if [ "$$n,$$s,$$l" != "2,1,$(NODULE_NH_STEPS)" ]; then \
	    echo "organ_deck --nlgeom: $$n neo-Hookean materials, $$s NLGEOM steps, $$l load levels"; exit 1; fi
	@if $(CX)/organ_deck $(NODULE_BOX) --spacing 2.4 $(NODULE_BOX_ARGS) --nlgeom 0,0,-1 >/dev/null 2>&1; then \
	  echo "organ_deck wrote an NLGEOM deck of a linear scene"; exit 1; fi
	@echo "ok: block48's sphere$(call check_len, and the liver's nodule (its signal within $(NODULE_SIGNAL_BOUND)),) within $(NODULE_BOUND) of CalculiX, linear and neo-Hookean"

calculix-nodule-nh: $(CX)/organ_deck | deps-calculix
	$(Q)DECK_ARGS="$(NODULE_BOX_ARGS) --nlgeom $(NODULE_NH_FORCE) --levels $(NODULE_NH_STEPS)" \
	  tests/calculix/run_organ.sh $< $(NODULE_NH) $(CX)/nodule/block48_sphere_nh $(CX_DATA) \
	  block48_sphere_nh $(NODULE_NH_LEVELS)
	@$(MAKE) --no-print-directory calculix-nodule-nh-table

calculix-nodule-nh-table: $(B)/bin/tissuefit
	@mkdir -p $(CX)
	@set -e; { \
	  echo "CalculiX levels against $(NODULE_NH_FINEST):"; echo; \
	  for l in $(filter-out $(NODULE_NH_FINEST),$(foreach l,$(NODULE_NH_LEVELS),$(firstword $(subst :, ,$(l))))); do \
	    tests/calculix/organ_nl_compare.sh --csv $(CX_DATA)/block48_sphere_nh_$$l.csv \
	      $(CX_DATA)/block48_sphere_nh_$(NODULE_NH_FINEST).csv $$l; done; \
	  echo; echo "the Newton solves (rpim-newton) against $(NODULE_NH_FINEST):"; echo; \
	  tests/calculix/organ_nl_compare.sh $(B)/bin/tissuefit $(NODULE_NH) $(NODULE_NH_FORCE) $(NODULE_NH_STEPS) \
	    $(CX_DATA)/block48_sphere_nh_$(NODULE_NH_FINEST).csv $(NODULE_NH_GRIDS); \
	} | tee $(CX)/nodule_nh.md
