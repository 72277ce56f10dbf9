# physics.mk — the shipped headers' error against the physics (issue 14):
#
#   check-physics   block48.h's discretisation figures recomputed by
#                   tests/physics/physics_check.c (another route than the
#                   tool's) against the CalculiX reference: the header may not
#                   understate them; a copy of the header with the figure
#                   lowered by 1 % must be caught.  And its outputs are
#                   still the seed grid's 121 top nodes, in order, at their
#                   positions (tests/physics/seed_map.c against
#                   tests/solver/block48_seed.yaml).  And the shipped
#                   scene's solve, at its own grid, is within 2 % of the
#                   CalculiX reference at node 61 for 1 N along x, y and -z
#                   (issue 14; calculix_compare, tests/solver.mk).
PHYSICS_DATA := tests/calculix/data
PHYSICS_CSV := $(PHYSICS_DATA)/block48_fx_h0.6.csv $(PHYSICS_DATA)/block48_fy_h0.6.csv \
  $(PHYSICS_DATA)/block48_fz_h0.6.csv

.PHONY: check-physics
CHECKS += check-physics

$(T)/physics/%: tests/physics/%.c $(B)/native/libtissuefit-host.a | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -O2 $< $(B)/native/libtissuefit-host.a $(HOST_LIBS) -o $@

# seed_map reads the committed header's tables: compiled against it.
$(T)/physics/seed_map: tests/physics/seed_map.c coeffs/block48.h $(B)/native/libtissuefit-host.a \
    $(B)/native/libtfit.a | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -Icoeffs -DHEADER='"block48.h"' $< $(B)/native/libtissuefit-host.a \
	  $(B)/native/libtfit.a $(HOST_LIBS) -o $@

check-physics: $(T)/physics/physics_check $(T)/physics/seed_map $(T)/solver/calculix_compare
	@echo "== shipped headers: the error against the physics is not understated =="
	@$< coeffs/block48.yaml coeffs/block48.h $(PHYSICS_CSV)
	@mkdir -p $(T)/physics/under
	@awk '/_FORWARD_DISCRETISATION_MAX_MM/ {$$3 = $$3 * 0.99} {print}' coeffs/block48.h \
	  > $(T)/physics/under/block48.h
	@if $< coeffs/block48.yaml $(T)/physics/under/block48.h $(PHYSICS_CSV) > /dev/null 2>&1; then \
	  echo "physics_check accepted a header whose figure is 1 % too low"; exit 1; fi
	@echo "ok: block48.h states its discretisation error (recomputed; a 1 % understatement is caught)"
	@echo "== shipped block48.h: its outputs are the seed grid's nodes, in order, at their positions =="
	@$(T)/physics/seed_map tests/solver/block48_seed.yaml
	@echo "== shipped block48.yaml: node 61 within 2 % of CalculiX for 1 N along x, y, -z =="
	@grid=$$(sed -n 's/^ *grid: *\[\([0-9, ]*\)\].*/\1/p' coeffs/block48.yaml | tr -d ' '); \
	out=$$($(T)/solver/calculix_compare --scene coeffs/block48.yaml --levels "$$grid" \
	  --max-err61 0.02) || { echo "$$out"; exit 1; }; \
	echo "$$out" | awk -F, 'NR > 1 { printf "ok: block48 %s, %s: node 61 %.2f %% off CalculiX (u = %s, %s, %s mm; bound 2 %%)\n", $$2, $$4, 100 * $$11, $$5, $$6, $$7 }'

# The nonlinear shipped headers: block48_nh against CalculiX NLGEOM
# (tests/calculix/data/block48_nh_physics.csv: 2.1 N along -z, the
# envelope's radius, and 1 N along +x), block48_ve against its refinement study
# (tests/physics/data/block48_ve_physics.csv, make physics-ve-reference).
# physics_check solves each case in load levels, another route than the
# tool's one solve from rest; a copy of each header with its figure lowered
# by 1 % must be caught.  block48_nh's stated totals (fit + discretisation)
# must also stay within its design target, 3 % of its peak displacement and
# of its envelope's force (docs/fitting.md §7.8; tests/physics/total_target.sh).
PHYSICS_NONLINEAR := block48_nh:tests/calculix/data/block48_nh_physics.csv \
  block48_ve:tests/physics/data/block48_ve_physics.csv

.PHONY: check-physics-nonlinear
CHECKS += check-physics-nonlinear
check-physics-nonlinear: $(T)/physics/physics_check
	@echo "== shipped nonlinear headers: the error against the physics is not understated =="
	@mkdir -p $(T)/physics/under
	@set -e; for e in $(PHYSICS_NONLINEAR); do n=$${e%%:*}; ref=$${e#*:}; \
	  $< coeffs/$$n.yaml coeffs/$$n.h $$ref; \
	  awk '/_FORWARD_DISCRETISATION_MAX_MM/ {$$3 = $$3 * 0.99} {print}' coeffs/$$n.h \
	    > $(T)/physics/under/$$n.h; \
	  if $< coeffs/$$n.yaml $(T)/physics/under/$$n.h $$ref > /dev/null 2>&1; then \
	    echo "physics_check accepted a $$n.h whose figure is 1 % too low"; exit 1; fi; \
	  echo "ok: $$n.h states its discretisation error (recomputed; a 1 % understatement is caught)"; \
	done
	@tests/physics/total_target.sh coeffs/block48_nh.h 0.03

# block48_ve's reference: the relaxed equilibrium (the largest displacement
# a force reaches in the Kelvin law) under 1 N along -z on the finer cloud
# tests/physics/block48_ve_fine.yaml, at the 121 output points (seconds;
# the committed files are its output).  -z only: the lateral 1 N cases did
# not converge on the finer cloud (modified or full Newton, 21 x 21 x 5
# graded or uniform) within 4-5 minutes, so they are not measured
# (docs/fitting.md §7.6).
PHYSICS_VE_DATA := tests/physics/data
.PHONY: physics-ve-reference
physics-ve-reference: $(B)/bin/tissuefit
	@mkdir -p $(PHYSICS_VE_DATA)
	@set -e; printf 'fx,fy,fz,file\n' > $(PHYSICS_VE_DATA)/block48_ve_physics.csv.tmp; \
	for c in fz:0,0,-1; do a=$${c%%:*}; f=$${c#*:}; \
	  out=$(PHYSICS_VE_DATA)/block48_ve_fine_$$a.csv; \
	  $(B)/bin/tissuefit -q solve tests/physics/block48_ve_fine.yaml --force $$f -o /dev/null \
	    --outputs $$out.tmp; \
	  sed '1s/^output,/node,/' $$out.tmp > $$out; rm -f $$out.tmp; \
	  echo "$$f,block48_ve_fine_$$a.csv" >> $(PHYSICS_VE_DATA)/block48_ve_physics.csv.tmp; \
	  echo "wrote $$out"; done; \
	mv $(PHYSICS_VE_DATA)/block48_ve_physics.csv.tmp $(PHYSICS_VE_DATA)/block48_ve_physics.csv

# The discretisation error the tool measures itself (no reference) against
# the one measured with CalculiX, block48, the liver and the stomach
# (docs/fitting.md, "The discretisation measured by the tool itself");
# about 4 minutes.  check-fit's tests/fit/cli_discretisation.sh checks
# block48's row in make check.
.PHONY: discretisation-table
discretisation-table: $(B)/bin/tissuefit
	@tests/physics/self_table.sh $(B)/bin/tissuefit $(B)/physics/self_table.md
