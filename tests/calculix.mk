# calculix.mk — the CalculiX finite-element references of the box scenes
# (docs/calculix-reference.md): block48 linear and large-deformation.
#
#   make calculix-reference   block48, linear: runs CalculiX (hours, one run at
#                             a time) and rewrites tests/calculix/data, the
#                             plots and build/calculix/tables.md;
#                             CALCULIX_REUSE=1 runs only what the committed
#                             data lacks
#   make calculix-nlgeom      block48, NLGEOM (neo-Hooke, St. Venant-Kirchhoff):
#                             many hours; CALCULIX_NL_* below
#   make calculix-report      from the committed data: docs/calculix-*.png,
#                             build/calculix/tables.md and vtk/*.vtk (ParaView)
#   make calculix-nlgeom-report  docs/calculix-nlgeom.png, build/calculix/nl_tables.md
#   check-calculix-*          (make check) validate the committed data and
#                             the deck writer

DEBS_CALCULIX := calculix-ccx time
DEBS_CALCULIX_PLOT := gnuplot-nox

CX := $(B)/calculix
CX_DATA := tests/calculix/data

# Mesh levels name:divisions:layers, coarse to fine: every step halves the
# element size in all three directions (docs/calculix-reference.md).
CALCULIX_LEVELS := h2.4:20:2 h1.2:40:4 h0.6:80:8
CALCULIX_NUS := 0 0.3 0.45 0.49 0.499
# The sweep and the element comparison run one level below the finest,
# which costs three quarters of an hour and 11 GB a run.
CALCULIX_SWEEP_LEVEL := h1.2
CALCULIX_LOCK_LEVEL := h1.2
# Extra C3D20R runs level:layers:nu: through-thickness convergence, and
# nu = 0.499 on a coarser and a finer mesh than the sweep's (locking).
CALCULIX_MESH_RUNS := h1.2:2:0.49 h1.2:8:0.49 h0.6:4:0.49 h2.4:2:0.499 h0.6:4:0.499
# Levels run again with the whole force on node 61, as the seed did.
CALCULIX_POINT_LEVELS := h2.4 h1.2
# Bounds on the change between the two finest levels (relative): RMS over
# the 121 nodes, and node 61.
CALCULIX_RMS_BOUND := 0.01
CALCULIX_N61_BOUND := 0.01

cx_comma := ,
cx_empty :=
cx_list = $(subst $(cx_empty) $(cx_empty),$(cx_comma),$(strip $(1)))
CX_LEVEL_NAMES := $(foreach l,$(CALCULIX_LEVELS),$(firstword $(subst :, ,$(l))))
CX_CHECK_ARGS := $(call cx_list,$(CX_LEVEL_NAMES)) $(call cx_list,$(CALCULIX_NUS)) \
                 $(CALCULIX_SWEEP_LEVEL) $(CALCULIX_RMS_BOUND) $(CALCULIX_N61_BOUND)

.PHONY: deps-calculix deps-calculix-plot calculix-reference calculix-report check-calculix-data \
        check-calculix-deck
CHECKS += check-calculix-data check-calculix-deck

deps-calculix: ; $(call ensure_debs,$(DEBS_CALCULIX))
deps-calculix-plot: ; $(call ensure_debs,$(DEBS_CALCULIX_PLOT))

$(CX)/box_deck: tests/calculix/box_deck.c | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O2 $< -lm -o $@

# the data checkers share the CSV reader
$(CX)/check_%: tests/calculix/check_%.c tests/calculix/data_csv.c tests/calculix/data_csv.h | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O2 $< tests/calculix/data_csv.c -lm -o $@

calculix-reference: $(CX)/box_deck | deps-calculix
	$(Q)SCENE=block48 NU_REF=0.49 POINT=61 LEVELS="$(CALCULIX_LEVELS)" NUS="$(CALCULIX_NUS)" \
	  SWEEP_LEVEL=$(CALCULIX_SWEEP_LEVEL) LOCK_LEVEL=$(CALCULIX_LOCK_LEVEL) \
	  MESH_RUNS="$(CALCULIX_MESH_RUNS)" GRID_RUNS="$(CALCULIX_GRID_RUNS)" \
	  POINT_LEVELS="$(CALCULIX_POINT_LEVELS)" REUSE=$(CALCULIX_REUSE) \
	  tests/calculix/run_reference.sh $< $(CX) $(CX_DATA)
	@$(MAKE) --no-print-directory calculix-report check-calculix-data

# Pictures, tables and VTK files, from the committed data only (no CalculiX).
CX_LEVEL_FILES := $(foreach l,$(CX_LEVEL_NAMES),$(foreach c,fx fy fz,$(CX_DATA)/block48_$(c)_$(l).csv))
CX_SWEEP_MESH := $(wordlist 2,3,$(subst :, ,$(filter $(CALCULIX_SWEEP_LEVEL):%,$(CALCULIX_LEVELS))))
calculix-report: | deps-calculix-plot
	@mkdir -p $(CX)/vtk
	$(Q)awk -f tests/calculix/convergence.awk $(CX_DATA)/block48_runs.csv $(CX_LEVEL_FILES) > $(CX)/convergence.txt
	$(Q)gnuplot -e "table='$(CX)/convergence.txt'; data='$(CX_DATA)'; levels='$(CX_LEVEL_NAMES)'; \
	  out='docs/calculix-convergence.png'" tests/calculix/convergence.gp
	$(Q)gnuplot -e "node61='$(CX_DATA)/block48_node61.csv'; div=$(word 1,$(CX_SWEEP_MESH)); \
	  layers=$(word 2,$(CX_SWEEP_MESH)); level='$(CALCULIX_SWEEP_LEVEL)'; out='docs/calculix-nu-sweep.png'" \
	  tests/calculix/nu_sweep.gp
	$(Q){ awk -v md=1 -f tests/calculix/convergence.awk $(CX_DATA)/block48_runs.csv $(CX_LEVEL_FILES) && echo && \
	  awk -v div=$(word 1,$(CX_SWEEP_MESH)) -v layers=$(word 2,$(CX_SWEEP_MESH)) -f tests/calculix/tables.awk \
	  $(CX_DATA)/block48_runs.csv $(CX_DATA)/block48_node61.csv $(CX_DATA)/block48_reactions.csv; } > $(CX)/tables.md
	$(Q)awk -F, -v levels="$(CALCULIX_LEVELS)" -f tests/calculix/richardson.awk \
	  $(CX_DATA)/block48_node61.csv > $(CX_DATA)/block48_node61_reference.csv.tmp && \
	  mv $(CX_DATA)/block48_node61_reference.csv.tmp $(CX_DATA)/block48_node61_reference.csv
	$(Q)awk -F, -f tests/calculix/accuracy.awk $(CX_DATA)/block48_node61_reference.csv \
	  $(CX_DATA)/block48_runs.csv $(CX_DATA)/block48_node61.csv > $(CX)/accuracy.md
	$(Q)for f in $(CX_DATA)/block48_f*_*.csv $(CX_DATA)/block48_nu*.csv; do \
	  b=$$(basename $$f .csv); awk -v title=$$b -f tests/calculix/csv_to_vtk.awk $$f > $(CX)/vtk/$$b.vtk; done
	@echo "calculix: docs/calculix-convergence.png, docs/calculix-nu-sweep.png, $(CX)/tables.md, $(CX)/accuracy.md, $(CX)/vtk/*.vtk"

check-calculix-data: $(CX)/check_data
	@echo "== CalculiX reference data for block48 =="
	@tests/calculix/check_data.sh $< block48 $(CX_DATA) $(CX)/mutant $(CX_CHECK_ARGS)
	@echo "ok: the CalculiX reference data pass their checks; every mutant is rejected"

check-calculix-deck: $(CX)/box_deck
	@echo "== CalculiX deck writer for the box scenes (block48, beam40) =="
	@tests/calculix/check_deck.sh $<
	@echo "ok: the block48 deck writer's counts, output nodes and load sums"

# ---- block48, large deformation (NLGEOM): run_nlgeom.sh, check_nlgeom.c ----
# Study element C3D20 (full integration; C3D20R compared on the coarse level).
# Levels as above: the in-plane division a multiple of 20 (patch and output
# grid on element edges).  h0.8 (60x60x6) and finer did not fit the time the
# study had (docs/calculix-reference.md, "Large deformation"): NL_EXTRA
# "60:6:neohooke:a" adds that level for one path.
CALCULIX_NL_LEVELS := h2.4:20:2 h1.2:40:4
CALCULIX_NL_ELEMENT := C3D20
CALCULIX_NL_MATERIALS := neohooke svk
# name:force:symmetry (the mirror planes the path allows, used to cut the mesh)
CALCULIX_NL_PATHS := a:0,0,-3:xy b:1,0,0:y c:1,0,-3:y
CALCULIX_NL_LOAD_LEVELS := 10
CALCULIX_NL_COMPARE := h2.4:C3D20R
CALCULIX_NL_EXTRA :=
CALCULIX_NL_SMALL := h2.4
# Graded levels name:fine:least:layers:ratio, coarse to fine (box_deck
# --grade FINE:LEAST --layers L --layer-ratio R: FINE elements per 2.4 mm
# quantum under the patch, 0.7 times fewer per quantum away from it, at
# least LEAST; layers thinnest at the top, each R times the one above), and
# the runs on each (material:path[:factor], the check holding node 61 of
# the two finest graded levels to CALCULIX_NL_GRADED_BOUND up to factor):
# the reference the meshless curves are compared with (docs/validation.md
# §12; docs/calculix-reference.md, "Graded levels").
CALCULIX_NL_GRADED := g1.2:2:1:3:1.6 g0.6:4:2:4:1.6
CALCULIX_NL_GRADED_RUNS := neohooke:a
CALCULIX_NL_GRADED_BOUND := 0.04
CALCULIX_NL_SMALL_FACTORS := 0.001 0.01
# The check: node 61 of the two finest levels within CONV_BOUND (relative) at
# every load level up to CONV_FACTOR of the force; the small-load runs within
# SMALL_SLOPE x factor of the linear solution of their mesh.
CALCULIX_NL_CONV_BOUND := 0.06
CALCULIX_NL_CONV_FACTOR := 0.5
CALCULIX_NL_SMALL_SLOPE := 0.5

CX_NL_LEVEL_NAMES := $(foreach l,$(CALCULIX_NL_LEVELS),$(firstword $(subst :, ,$(l))))
CX_NL_PATH_ARGS := $(call cx_list,$(foreach p,$(CALCULIX_NL_PATHS),$(subst $(cx_comma),:,$(word 1,$(subst :, ,$(p))):$(word 2,$(subst :, ,$(p))))))
CX_NL_CHECK_ARGS := $(call cx_list,$(CX_NL_LEVEL_NAMES)) $(call cx_list,$(CALCULIX_NL_MATERIALS)) \
                    $(CX_NL_PATH_ARGS) $(CALCULIX_NL_LOAD_LEVELS) $(CALCULIX_NL_ELEMENT) \
                    $(CALCULIX_NL_CONV_BOUND) $(CALCULIX_NL_CONV_FACTOR) $(CALCULIX_NL_SMALL_SLOPE) \
                    $(call cx_list,$(foreach g,$(CALCULIX_NL_GRADED),$(firstword $(subst :, ,$(g))))) \
                    $(call cx_list,$(CALCULIX_NL_GRADED_RUNS)) $(CALCULIX_NL_GRADED_BOUND)

.PHONY: calculix-nlgeom calculix-nlgeom-report check-calculix-nlgeom
CHECKS += check-calculix-nlgeom

calculix-nlgeom: $(CX)/box_deck | deps-calculix
	$(Q)NL_LEVELS="$(CALCULIX_NL_LEVELS)" NL_ELEMENT=$(CALCULIX_NL_ELEMENT) \
	  NL_MATERIALS="$(CALCULIX_NL_MATERIALS)" NL_PATHS="$(CALCULIX_NL_PATHS)" \
	  NL_LOAD_LEVELS=$(CALCULIX_NL_LOAD_LEVELS) NL_COMPARE="$(CALCULIX_NL_COMPARE)" \
	  NL_EXTRA="$(CALCULIX_NL_EXTRA)" NL_SMALL="$(CALCULIX_NL_SMALL)" \
	  NL_SMALL_FACTORS="$(CALCULIX_NL_SMALL_FACTORS)" NL_GRADED="$(CALCULIX_NL_GRADED)" \
	  NL_GRADED_RUNS="$(foreach r,$(CALCULIX_NL_GRADED_RUNS),$(word 1,$(subst :, ,$(r))):$(word 2,$(subst :, ,$(r))))" \
	  tests/calculix/run_nlgeom.sh $< $(CX)/nl $(CX_DATA)
	@$(MAKE) --no-print-directory calculix-nlgeom-report check-calculix-nlgeom

# Why the graded meshes with 0.6 mm elements under the patch stop near 0.79
# of path a (docs/calculix-reference.md, "Why the fine levels stop"): neo-Hooke
# path a on graded meshes name:fine:least:layers:element:min_fraction, every
# node's displacement at the printed levels, the top surface's compression
# under the load centre (tests/calculix/run_nlgeom_stop.sh; data
# block48_nl_stop*.csv).  About an hour of CalculiX on the loaded machine
# (6:1, 42k DOFs, most of it).
CALCULIX_NL_STOP_RUNS := stop_g4.1:4:1:4:C3D20:1e-2 stop_g4.1_C3D20R:4:1:4:C3D20R:1e-2 \
  stop_g6.1:6:1:5:C3D20:1e-2
.PHONY: calculix-nlgeom-stop
calculix-nlgeom-stop: $(CX)/box_deck | deps-calculix
	$(Q)NL_STOP_RUNS="$(CALCULIX_NL_STOP_RUNS)" tests/calculix/run_nlgeom_stop.sh $< $(CX)/nl_stop $(CX_DATA)
	@awk -F, -f tests/calculix/nl_stop_table.awk $(CX_DATA)/block48_nl_stop.csv $(CX_DATA)/block48_nl_stop_field.csv

# docs/calculix-nlgeom.png and build/calculix/nl_tables.md from the committed data
calculix-nlgeom-report: | deps-calculix-plot
	@mkdir -p $(CX)
	$(Q)gnuplot -e "curves='$(CX_DATA)/block48_nl_curves.csv'; levels='$(CX_NL_LEVEL_NAMES)'; \
	  materials='$(CALCULIX_NL_MATERIALS)'; element='$(CALCULIX_NL_ELEMENT)'; \
	  ux61=$$(awk -F, '$$1 == "h0.6" && $$7 == "fx" { print $$8 }' $(CX_DATA)/block48_node61.csv); \
	  uz61=$$(awk -F, '$$1 == "h0.6" && $$7 == "fz" { print $$10 }' $(CX_DATA)/block48_node61.csv); \
	  out='docs/calculix-nlgeom.png'" tests/calculix/nlgeom.gp
	$(Q)awk -F, -v factors="0.1 0.3 0.5 0.7 0.9 1" -f tests/calculix/nl_tables.awk \
	  $(CX_DATA)/block48_nl_runs.csv $(CX_DATA)/block48_nl_curves.csv $(CX_DATA)/block48_nl_linear.csv \
	  > $(CX)/nl_tables.md
	@echo "calculix: docs/calculix-nlgeom.png, $(CX)/nl_tables.md"

check-calculix-nlgeom: $(CX)/check_nlgeom
	@echo "== CalculiX large-deformation (NLGEOM) reference data for block48 =="
	@tests/calculix/check_nlgeom.sh $< $(CX_DATA) $(CX)/nl_mutant $(CX_NL_CHECK_ARGS)

# ---- beam40: the second FE-referenced box (coeffs/beam40.yaml), linear ----
# 40 x 20 x 20 mm, clamped at x = 0 only, nu = 0.45, the 5 mm patch centred
# at (30, 10, 20).  Levels name:divisions:layers (divisions a multiple of 16,
# the patch on element edges); elements twice as long through the
# thickness as in plane, the same shape at every level.  A third level
# (h0.83:48:12, 182k DOFs) did not fit the time the study had.
CALCULIX_BEAM40_LEVELS := h2.5:16:4 h1.25:32:8
CALCULIX_BEAM40_RMS_BOUND := 0.01
CALCULIX_BEAM40_N25_BOUND := 0.04
CX_BEAM40_LEVEL_NAMES := $(foreach l,$(CALCULIX_BEAM40_LEVELS),$(firstword $(subst :, ,$(l))))

.PHONY: calculix-beam40 check-calculix-beam40
CHECKS += check-calculix-beam40

calculix-beam40: $(CX)/box_deck | deps-calculix
	$(Q)SCENE=beam40 NU_REF=0.45 POINT=25 LEVELS="$(CALCULIX_BEAM40_LEVELS)" NUS="" SWEEP_LEVEL= \
	  LOCK_LEVEL= MESH_RUNS="" GRID_RUNS="" POINT_LEVELS="" REUSE=$(CALCULIX_REUSE) \
	  tests/calculix/run_reference.sh $< $(CX)/beam40 $(CX_DATA)
	@$(MAKE) --no-print-directory check-calculix-beam40

check-calculix-beam40: $(CX)/check_data
	@echo "== CalculiX reference data for beam40 =="
	@tests/calculix/check_data.sh $< beam40 $(CX_DATA) $(CX)/beam40_mutant \
	  $(call cx_list,$(CX_BEAM40_LEVEL_NAMES)) none none $(CALCULIX_BEAM40_RMS_BOUND) $(CALCULIX_BEAM40_N25_BOUND)
	@echo "ok: the beam40 reference data pass their checks; every mutant is rejected"

# ---- make bench: CalculiX's time to 1 % and 0.3 % at block48's node 61 ----
# target%:divisions:layers, the cheapest committed C3D20R mesh reaching the
# target at node 61 for both fx and fz against block48_node61_reference.csv
# (docs/calculix-reference.md, "Accuracy per second"): 40x40x4 is 0.61 %
# off in fz, 80x80x4 0.16 %.  About 7 minutes on one thread.
CALCULIX_BENCH_LEVELS := 1:40:4 0.3:80:4
.PHONY: bench-calculix
BENCHES += bench-calculix

bench-calculix: $(CX)/box_deck | deps-calculix
	@echo "== CalculiX C3D20R: time to 1 % and 0.3 % at block48 node 61 =="
	$(Q)tests/calculix/bench_ccx.sh $< $(CX)/bench $(CX_DATA)/block48_node61_reference.csv $(CALCULIX_BENCH_LEVELS)
