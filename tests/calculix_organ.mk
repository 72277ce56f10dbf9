# calculix_organ.mk — the CalculiX reference of the organ scenes (issue 15,
# acceptance 1; docs/validation.md, "Organs").
#
#   make calculix-organ     runs CalculiX on the liver at the levels below
#                           (tens of minutes) and rewrites
#                           tests/calculix/data/liver_*.csv, then the table
#   make calculix-organ-table  the convergence table from the committed data
#                           and a fresh meshless solve (build/calculix/organ.md)
#   make organ-convergence  the liver and the stomach under refinement, with
#                           the file's skin and a refined one (below)
#   check-organ-calculix    (make check) the shipped liver's meshless solve
#                           within 3 % of the finest level at the contact
#                           vertex and 2 % (L2) over the output vertices; the deck
#                           writer's patch and counts on a coarse level;
#                           the liver's NLGEOM deck on the same level (make
#                           check-full adds liver_nh's Newton solves at 6 mm
#                           within 3 % at every load level: 75 s of CPU)
#
# The committed data are of the shipped liver's 240 outputs (within 40 mm
# of the contact vertex), rerun on 2026-11-24 (docs/validation.md §14).
# A level is label:spacing:refine[:grade] (organ_deck.c): the liver's
# surface as it is with the interior at `spacing` mm (graded to `grade` mm
# near the contact vertex), refined `refine` times (each tetrahedron into
# eight, the surface triangles into four on their own planes), 10-node
# tetrahedra.

ORGAN_SCENE := coeffs/liver.yaml
# s20r1 (537,042 unknowns) took 13-24 min and 3.6 GB with one thread; a graded
# refined level (g4r1:20:1:4) would be larger still and was not run.
ORGAN_LEVELS := s20r0:20:0 s10r0:10:0 s20r1:20:1
ORGAN_FINEST := s20r1
ORGAN_BOUND := 0.03
# the shipped liver's outputs: L2 within 2 % (its contact vertex within 3 %)
ORGAN_L2_BOUND := 0.02

.PHONY: calculix-organ calculix-organ-table calculix-organ-physics check-organ-calculix
CHECKS += check-organ-calculix

$(CX)/organ_deck $(CX)/organ_compare: $(CX)/%: tests/calculix/%.c $(B)/native/libtissuefit-host.a \
    $(B)/native/libtfit.a | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -O2 $< $(B)/native/libtissuefit-host.a $(B)/native/libtfit.a \
	  $(HOST_LIBS) -o $@

calculix-organ: $(CX)/organ_deck | deps-calculix
	$(Q)tests/calculix/run_organ.sh $< $(ORGAN_SCENE) $(CX)/organ $(CX_DATA) liver $(ORGAN_LEVELS)
	@$(MAKE) --no-print-directory calculix-organ-physics calculix-organ-table

calculix-organ-table: $(CX)/organ_compare
	@mkdir -p $(CX)
	@{ echo "CalculiX levels against the finest ($(ORGAN_FINEST)):"; \
	  for l in $(ORGAN_LEVELS); do n=$${l%%:*}; [ $$n = $(ORGAN_FINEST) ] && continue; \
	    echo; echo "level $$n:"; $< $(CX_DATA)/liver_$(ORGAN_FINEST).csv --csv $(CX_DATA)/liver_$$n.csv || true; done; \
	  echo; echo "meshless ($(ORGAN_SCENE)) against $(ORGAN_FINEST):"; \
	  $< $(CX_DATA)/liver_$(ORGAN_FINEST).csv $(ORGAN_SCENE) || true; } | tee $(CX)/organ.md

check-organ-calculix: $(CX)/organ_compare $(CX)/organ_deck $(B)/bin/tissuefit
	@echo "== the liver against CalculiX (finest level $(ORGAN_FINEST), bound $(ORGAN_BOUND) at the contact, $(ORGAN_L2_BOUND) L2) =="
	@$< $(CX_DATA)/liver_$(ORGAN_FINEST).csv $(ORGAN_SCENE) $(ORGAN_BOUND),$(ORGAN_L2_BOUND)
	@echo "ok: the liver's contact displacement within $(ORGAN_BOUND) and its output vertices within $(ORGAN_L2_BOUND) (L2) of CalculiX"
	@echo "== the organ deck writer: s20r0 deck (its loaded faces' area = the patch's, checked) has the committed level's size =="
	@mkdir -p $(CX)
	@$(CX)/organ_deck $(ORGAN_SCENE) --spacing 20 --refine 0 > $(CX)/check_s20r0.inp
	@got=$$(awk '$$1 == "**" && $$2 == "SIZE" { print $$3 "," $$4 "," $$5; exit }' $(CX)/check_s20r0.inp); \
	  want=$$(awk -F, '$$1 == "s20r0" { print $$5 "," $$6 "," $$7 }' $(CX_DATA)/liver_runs.csv); \
	  if [ "$$got" != "$$want" ]; then echo "organ_deck: s20r0 elements,nodes,dofs $$got, the reference's $$want"; exit 1; fi; \
	  echo "ok: s20r0 deck: $$got elements,nodes,dofs as in $(CX_DATA)/liver_runs.csv"
	@echo "== the liver in neo-Hookean tissue: the NLGEOM s20r0 deck has the committed level's size, one neo-Hookean material, one ramped step and its load levels$(call check_len,; Newton at 6 mm within $(ORGAN_BOUND) of $(LIVER_NH_FINEST) at every level,) =="
	@$(CX)/organ_deck $(LIVER_NH) --spacing 20 --refine 0 --nlgeom $(LIVER_NH_FORCE_liver_nh) \
	  --levels $(LIVER_NH_STEPS) > $(CX)/check_nh_s20r0.inp
	@got=$$(awk '$$1 == "**" && $$2 == "SIZE" { print $$3 "," $$4 "," $$5; exit }' $(CX)/check_nh_s20r0.inp); \
	  want=$$(awk -F, '$$1 == "s20r0" { print $$5 "," $$6 "," $$7 }' $(CX_DATA)/liver_nh_runs.csv); \
	  n=$$(grep -c '^\*HYPERELASTIC, NEO HOOKE$$' $(CX)/check_nh_s20r0.inp); \
	  s=$$(grep -c '^\*STEP, NLGEOM' $(CX)/check_nh_s20r0.inp); \
	  l=$$(grep -c '^\*\* STEP [0-9]* l[0-9]' $(CX)/check_nh_s20r0.inp); \
	  if [ "$$got;$$n,$$s,$$l" != "$$want;1,1,$(LIVER_NH_STEPS)" ]; then \
	    echo "organ_deck --nlgeom: $$got elements,nodes,dofs (the reference's $$want), $$n neo-Hookean materials, $$s NLGEOM steps, $$l load levels"; exit 1; fi
	$(call check_len,@BOUND=$(ORGAN_BOUND) tests/calculix/organ_nl_compare.sh $(B)/bin/tissuefit $(LIVER_NH) \
	  $(LIVER_NH_FORCE_liver_nh) $(LIVER_NH_STEPS) $(CX_DATA)/liver_nh_$(LIVER_NH_FINEST).csv geometry.spacing=6,)
	@echo "ok: the liver's NLGEOM deck$(call check_len, and its Newton solves within $(ORGAN_BOUND) of CalculiX,)"

# The organs under refinement (docs/validation.md §14): the liver and the
# stomach solved at each interior spacing below with the file's skin and
# with a refined one (geometry.refine_skin), against their finest CalculiX
# level (committed data); build/calculix/organ_convergence.{csv,md} and
# docs/validation/organ_convergence.png.  About 15 minutes and 6 GB.
ORGAN_CONVERGENCE := liver:10,8,6,5,4 stomach:12,8,6,4,3
.PHONY: organ-convergence
organ-convergence: $(CX)/organ_compare | deps-calculix-plot
	@mkdir -p $(CX)
	$(Q)tests/calculix/organ_convergence.sh $< $(CX_DATA) $(CX)/organ_convergence.csv \
	  $(ORGAN_CONVERGENCE) | tee $(CX)/organ_convergence.md
	$(Q)gnuplot -e "table='$(CX)/organ_convergence.csv'; out='docs/validation/organ_convergence.png'" \
	  tests/calculix/organ_convergence.gp
	@echo "wrote $(CX)/organ_convergence.md and docs/validation/organ_convergence.png"

# The finest level in tissuefit fit --reference's form (docs/fitting.md,
# "Error against the physics"): an index liver_physics.csv and one
# node,x,y,z,ux,uy,uz file per unit force (node: the file's vertex index),
# so the liver's header states its solve's error against CalculiX
# (coeffs/coeffs.mk, PHYSICS_liver).  Rewritten by calculix-organ.
# $(call organ_physics,NAME,LEVEL): NAME_physics.csv and its three cases
# from NAME_LEVEL.csv.
define organ_physics
	@set -e; d=$(CX_DATA); { echo "fx,fy,fz,file"; echo "1,0,0,$(1)_physics_fx.csv"; \
	  echo "0,1,0,$(1)_physics_fy.csv"; echo "0,0,1,$(1)_physics_fz.csv"; } > $$d/$(1)_physics.csv; \
	  for c in fx fy fz; do \
	    awk -F, -v c=$$c 'NR == 1 { print "node,x,y,z,ux,uy,uz"; next } \
	      $$5 == c { print $$1 "," $$2 "," $$3 "," $$4 "," $$6 "," $$7 "," $$8 }' \
	      $$d/$(1)_$(2).csv > $$d/$(1)_physics_$$c.csv; done
	@echo "wrote $(CX_DATA)/$(1)_physics.csv and its three cases from $(1)_$(2).csv"
endef
calculix-organ-physics:
	$(call organ_physics,liver,$(ORGAN_FINEST))

# How far the stomach moves with its bed clamp's plane (docs/validation.md
# §14.1): the meshless solve with the plane at 27 .. 33 mm against s20r1, and
# CalculiX s20r0 at 29 mm against s20r0 at 30 (about 3 minutes).
.PHONY: stomach-clamp
stomach-clamp: $(CX)/organ_compare $(CX)/organ_deck | deps-calculix
	$(Q)tests/calculix/stomach_clamp.sh $(CX)/organ_compare $(CX)/organ_deck $(CX_DATA) \
	  $(CX)/stomach_clamp | tee $(CX)/stomach_clamp.md

# The stomach and the heart (coeffs/NAME.yaml) the same way, at two levels:
# their headers state their solves' error against s20r1 (coeffs.mk,
# PHYSICS_NAME).  s20r1 took 229 s and 2.3 GB (the stomach, 387,999
# unknowns) and 991 s and 6.2 GB (the heart, 825,213) with one thread.
ORGAN_PAIR_LEVELS := s20r0:20:0 s20r1:20:1
.PHONY: calculix-stomach calculix-heart
calculix-stomach calculix-heart: calculix-%: $(CX)/organ_deck | deps-calculix
	$(Q)tests/calculix/run_organ.sh $< coeffs/$*.yaml $(CX)/organ $(CX_DATA) $* $(ORGAN_PAIR_LEVELS)
	$(call organ_physics,$*,s20r1)

# The liver in neo-Hookean tissue: tests/calculix/scenes/liver_nh.yaml (the
# shipped liver, law neo-hookean) and liver_nodule_nh.yaml (liver_nodule.yaml,
# both materials neo-Hookean).  CalculiX NLGEOM at the levels below, the
# probe's force ramped along the inward normal to the envelope's 0.3 N and
# printed at LIVER_NH_STEPS equal levels (organ_deck --nlgeom), against the
# Newton solves of the meshless clouds below (organ_nl_compare.sh).
#   make calculix-liver-nh        the CalculiX runs (liver_nh: s20r0 0.5 min,
#                                 s10r0 1, s20r1 17 and 3.8 GB; liver_nodule_nh
#                                 and liver_nodule_beside_nh: 1.6, 2.5-3.3 and
#                                 37-56, 6.1 GB; one thread); rewrites
#                                 tests/calculix/data/liver{,_nodule,_nodule_beside}_nh_*.csv
#   make calculix-liver-nh-table  the other levels and the meshless clouds
#                                 against the finest level, at every load
#                                 level; build/calculix/liver_nh.md; then
#                                 calculix-liver-nh-signal (below)
LIVER_NH_SCENES := liver_nh liver_nodule_nh liver_nodule_beside_nh
LIVER_NH := tests/calculix/scenes/liver_nh.yaml
LIVER_NH_FORCE_liver_nh := 0.138,0.266,0.0134
LIVER_NH_FORCE_liver_nodule_nh := 0.1344,0.2595,-0.0675
LIVER_NH_FORCE_liver_nodule_beside_nh := 0.2074,0.2158,-0.0204
LIVER_NH_DECK_liver_nodule_nh := --inclusion-spacing 2
LIVER_NH_DECK_liver_nodule_beside_nh := --inclusion-spacing 2
# the meshless clouds: the liver's at 9, 6 and 4.5 mm; the nodule's scene's
# 6 mm cloud refined within 30 mm of the probe to 6 (none), 4.5, 3 (the
# shipped liver_tumour's), 2 (the scene's own) and 1.5 mm, as in the linear
# table (calculix_nodule.mk)
LIVER_NH_CLOUDS_liver_nh := geometry.spacing=9 geometry.spacing=6 geometry.spacing=4.5
LIVER_NH_CLOUDS_liver_nodule_nh := geometry.refine.spacing=6 geometry.refine.spacing=4.5 \
                                   geometry.refine.spacing=3 geometry.refine.spacing=2 \
                                   geometry.refine.spacing=1.5
# beside the nodule: the scenes' 2 mm near the probe and the 3 mm of liver_tumour
LIVER_NH_CLOUDS_liver_nodule_beside_nh := geometry.refine.spacing=3 geometry.refine.spacing=2
LIVER_NH_STEPS := 3
LIVER_NH_LEVELS := s20r0:20:0 s10r0:10:0 s20r1:20:1
LIVER_NH_FINEST := s20r1

.PHONY: calculix-liver-nh calculix-liver-nh-table
calculix-liver-nh: $(CX)/organ_deck | deps-calculix
	$(Q)for n in $(LIVER_NH_SCENES); do \
	  DECK_ARGS="$$(eval echo \$${LIVER_NH_DECK_$$n}) --nlgeom $$(eval echo \$${LIVER_NH_FORCE_$$n}) --levels $(LIVER_NH_STEPS)" \
	  tests/calculix/run_organ.sh $< tests/calculix/scenes/$$n.yaml $(CX)/$$n $(CX_DATA) $$n $(LIVER_NH_LEVELS) || exit 1; done
	@$(MAKE) --no-print-directory calculix-liver-nh-physics calculix-liver-nh-table

# coeffs/liver_tumour.yaml is liver_nodule_nh.yaml's body and probe: its
# header states its error against the finest NLGEOM level's load levels
# (tissuefit fit --reference; coeffs/coeffs.mk, PHYSICS_liver_tumour).
# $(call organ_physics_nl,NAME,DATA,FX;FY;FZ,K): NAME_physics.csv and one
# file per load level k F / K of DATA.csv (organ_dat.awk's cases l1 .. lK)
define organ_physics_nl
	@set -e; d=$(CX_DATA); echo "fx,fy,fz,file" > $$d/$(1)_physics.csv; k=1; \
	  while [ $$k -le $(4) ]; do \
	    echo "$(3)" | awk -F';' -v k=$$k -v K=$(4) -v f=$(1)_physics_l$$k.csv \
	      '{ printf "%.17g,%.17g,%.17g,%s\n", $$1 * k / K, $$2 * k / K, $$3 * k / K, f }' \
	      >> $$d/$(1)_physics.csv; \
	    awk -F, -v c=l$$k 'NR == 1 { print "node,x,y,z,ux,uy,uz"; next } \
	      $$5 == c { print $$1 "," $$2 "," $$3 "," $$4 "," $$6 "," $$7 "," $$8 }' \
	      $$d/$(2).csv > $$d/$(1)_physics_l$$k.csv; k=$$((k + 1)); done
	@echo "wrote $(CX_DATA)/$(1)_physics.csv and its $(4) load levels from $(2).csv"
endef
.PHONY: calculix-liver-nh-physics
calculix-liver-nh-physics:
	$(call organ_physics_nl,liver_tumour,liver_nodule_nh_$(LIVER_NH_FINEST),$(subst $(comma),;,$(LIVER_NH_FORCE_liver_nodule_nh)),$(LIVER_NH_STEPS))

export LIVER_NH_FORCE_liver_nh LIVER_NH_FORCE_liver_nodule_nh LIVER_NH_DECK_liver_nodule_nh \
  LIVER_NH_CLOUDS_liver_nh LIVER_NH_CLOUDS_liver_nodule_nh LIVER_NH_FORCE_liver_nodule_beside_nh \
  LIVER_NH_DECK_liver_nodule_beside_nh LIVER_NH_CLOUDS_liver_nodule_beside_nh
calculix-liver-nh-table: $(B)/bin/tissuefit
	@mkdir -p $(CX)
	@set -e; for n in $(LIVER_NH_SCENES); do \
	  echo "$$n: CalculiX levels against $(LIVER_NH_FINEST):"; echo; \
	  for l in $(filter-out $(LIVER_NH_FINEST),$(foreach l,$(LIVER_NH_LEVELS),$(firstword $(subst :, ,$(l))))); do \
	    tests/calculix/organ_nl_compare.sh --csv $(CX_DATA)/$${n}_$$l.csv \
	      $(CX_DATA)/$${n}_$(LIVER_NH_FINEST).csv $$l; done; \
	  echo; echo "$$n: the Newton solves (rpim-newton) against $(LIVER_NH_FINEST):"; echo; \
	  tests/calculix/organ_nl_compare.sh $(B)/bin/tissuefit tests/calculix/scenes/$$n.yaml \
	    $$(eval echo \$${LIVER_NH_FORCE_$$n}) $(LIVER_NH_STEPS) $(CX_DATA)/$${n}_$(LIVER_NH_FINEST).csv \
	    $$(eval echo \$${LIVER_NH_CLOUDS_$$n}); echo; \
	done | tee $(CX)/liver_nh.md
	@$(MAKE) --no-print-directory calculix-liver-nh-signal

# What the hand feels of the nodule in neo-Hookean tissue: the secant
# stiffness along the press over the nodule and beside it at each load
# level, CalculiX's levels (finest first) and the Newton solves on
# liver_tumour's cloud (3 mm within 30 mm of the probe) and on the
# reference scenes' (2 mm); six Newton solves each, about 10 and 15
# minutes; build/calculix/liver_nh_signal.md
LIVER_NH_SIGNAL_CLOUDS := geometry.refine.spacing=3 geometry.refine.spacing=2
LIVER_NH_SIGNAL_REFS := $(foreach l,$(LIVER_NH_FINEST) $(filter-out $(LIVER_NH_FINEST),\
  $(foreach l,$(LIVER_NH_LEVELS),$(firstword $(subst :, ,$(l))))),\
  $(CX_DATA)/liver_nodule_nh_$(l).csv $(CX_DATA)/liver_nodule_beside_nh_$(l).csv)
.PHONY: calculix-liver-nh-signal
calculix-liver-nh-signal: $(B)/bin/tissuefit
	@mkdir -p $(CX)
	@set -e; for c in $(LIVER_NH_SIGNAL_CLOUDS); do \
	  tests/calculix/organ_nl_compare.sh --signal $(B)/bin/tissuefit \
	    tests/calculix/scenes/liver_nodule_nh.yaml tests/calculix/scenes/liver_nodule_beside_nh.yaml \
	    $(LIVER_NH_FORCE_liver_nodule_nh) $(LIVER_NH_FORCE_liver_nodule_beside_nh) $(LIVER_NH_STEPS) \
	    $$c $(LIVER_NH_SIGNAL_REFS); echo; done | tee $(CX)/liver_nh_signal.md
