# calculix.mk — the CalculiX finite-element reference for block48
# (docs/calculix-reference.md).
#
#   make calculix-reference   runs CalculiX (about 70 min, one run at a time)
#                             and rewrites tests/calculix/data, the plots and
#                             build/calculix/tables.md
#   make calculix-report      from the committed data: docs/calculix-*.png,
#                             build/calculix/tables.md and vtk/*.vtk (ParaView)
#   check-calculix-data       (make check) validates the committed data
#   check-calculix-deck       (make check) the deck writer's counts, loads, usage

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

$(CX)/block48_deck $(CX)/check_data: $(CX)/%: tests/calculix/%.c | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O2 $< -lm -o $@

calculix-reference: $(CX)/block48_deck | deps-calculix
	$(Q)LEVELS="$(CALCULIX_LEVELS)" NUS="$(CALCULIX_NUS)" SWEEP_LEVEL=$(CALCULIX_SWEEP_LEVEL) \
	  LOCK_LEVEL=$(CALCULIX_LOCK_LEVEL) MESH_RUNS="$(CALCULIX_MESH_RUNS)" \
	  POINT_LEVELS="$(CALCULIX_POINT_LEVELS)" \
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
	$(Q)for f in $(CX_DATA)/block48_f*_*.csv $(CX_DATA)/block48_nu*.csv; do \
	  b=$$(basename $$f .csv); awk -v title=$$b -f tests/calculix/csv_to_vtk.awk $$f > $(CX)/vtk/$$b.vtk; done
	@echo "calculix: docs/calculix-convergence.png, docs/calculix-nu-sweep.png, $(CX)/tables.md, $(CX)/vtk/*.vtk"

check-calculix-data: $(CX)/check_data
	@echo "== CalculiX reference data for block48 =="
	@tests/calculix/check_data.sh $< $(CX_DATA) $(CX)/mutant $(CX_CHECK_ARGS)
	@echo "ok: the CalculiX reference data pass their checks; every mutant is rejected"

check-calculix-deck: $(CX)/block48_deck
	@echo "== CalculiX deck writer for block48 =="
	@tests/calculix/check_deck.sh $<
	@echo "ok: the block48 deck writer's counts, output nodes and load sums"
