# calculix_organ.mk — the CalculiX reference of the organ scenes (issue 15,
# acceptance 1; docs/validation.md, "Organs").
#
#   make calculix-organ     runs CalculiX on the liver at the levels below
#                           (tens of minutes) and rewrites
#                           tests/calculix/data/liver_*.csv, then the table
#   make calculix-organ-table  the convergence table from the committed data
#                           and a fresh meshless solve (build/calculix/organ.md)
#   check-organ-calculix    (make check) the shipped liver's meshless solve
#                           within 3 % of the finest level, at the contact
#                           vertex and over the output vertices; the deck
#                           writer's patch and counts on a coarse level
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

check-organ-calculix: $(CX)/organ_compare $(CX)/organ_deck
	@echo "== the liver against CalculiX (finest level $(ORGAN_FINEST), bound $(ORGAN_BOUND)) =="
	@$< $(CX_DATA)/liver_$(ORGAN_FINEST).csv $(ORGAN_SCENE) $(ORGAN_BOUND)
	@echo "ok: the liver's contact displacement and output vertices within $(ORGAN_BOUND) of CalculiX"
	@echo "== the organ deck writer: s20r0 deck (its loaded faces' area = the patch's, checked) has the committed level's size =="
	@mkdir -p $(CX)
	@$(CX)/organ_deck $(ORGAN_SCENE) --spacing 20 --refine 0 > $(CX)/check_s20r0.inp
	@got=$$(awk '$$1 == "**" && $$2 == "SIZE" { print $$3 "," $$4 "," $$5; exit }' $(CX)/check_s20r0.inp); \
	  want=$$(awk -F, '$$1 == "s20r0" { print $$5 "," $$6 "," $$7 }' $(CX_DATA)/liver_runs.csv); \
	  if [ "$$got" != "$$want" ]; then echo "organ_deck: s20r0 elements,nodes,dofs $$got, the reference's $$want"; exit 1; fi; \
	  echo "ok: s20r0 deck: $$got elements,nodes,dofs as in $(CX_DATA)/liver_runs.csv"

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

# The stomach and the heart (coeffs/NAME.yaml) the same way, at two levels:
# their headers state their solves' error against s20r1 (coeffs.mk,
# PHYSICS_NAME).  s20r1 took 229 s and 2.3 GB (the stomach, 387,999
# unknowns) and 991 s and 6.2 GB (the heart, 825,213) with one thread.
ORGAN_PAIR_LEVELS := s20r0:20:0 s20r1:20:1
.PHONY: calculix-stomach calculix-heart
calculix-stomach calculix-heart: calculix-%: $(CX)/organ_deck | deps-calculix
	$(Q)tests/calculix/run_organ.sh $< coeffs/$*.yaml $(CX)/organ $(CX_DATA) $* $(ORGAN_PAIR_LEVELS)
	$(call organ_physics,$*,s20r1)
