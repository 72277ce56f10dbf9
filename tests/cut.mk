# cut.mk — cutting by enrichment (issue 17, docs/cutting.md).
#
#   check-cut        (make check) a cut along the load leaves the solve alone
#                    away from it (acceptance 2, 1e-3: rpim-galerkin with
#                    Gauss points printed against it, rpim-galerkin with VCI
#                    and efg-galerkin with Gauss points held to it), the
#                    slit block's lips open, and the short real version of
#                    the validation: CalculiX at its coarsest level and the
#                    meshless solve at its coarsest grid reproduce the
#                    committed data
#   cut-validation   crack-opening displacement of the slit block against
#                    CalculiX (crack by duplicated nodes) at the levels
#                    below; rewrites tests/cut/data, docs/cutting-cod.png,
#                    docs/cutting-slit.png and build/cut/table.md (about
#                    20 minutes; not part of make check)
#   cut-far-study    acceptance 2 by method, integration, grid, Gauss points
#                    and cut placement (tests/cut/data/far_study.md; about
#                    20 minutes on the shared machine; not part of make check)
#   cut-progress-pictures  block48_cut's top surface at cut progress 0, 0.5
#                    and 1 (docs/cutting-progress.png, build/cut/progress_*.vtu)
#   cut-progress-study  ways of making the cut progress s a model input,
#                    measured on block48_cut (tests/cut/data/progress_study.md,
#                    about a minute; not part of make check)

CUT_TOOL := $(T)/cut/cut_tool
SLIT_DECK := $(B)/calculix/slit_deck
CUT_CCX_LEVELS := 4 8 16
CUT_GRIDS := 16,8,8 24,12,12 32,16,16
CUT_DATA := tests/cut/data

.PHONY: check-cut cut-validation cut-pictures cut-progress-pictures cut-progress-study cut-far-study
CHECKS += check-cut

$(T)/cut/%: tests/cut/%.c $(B)/native/libtissuefit-host.a | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -O2 $< $(B)/native/libtissuefit-host.a $(HOST_LIBS) -o $@

$(SLIT_DECK): tests/calculix/slit_deck.c | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(HOST_STRICT) -O2 $< -o $@

check-cut: $(CUT_TOOL) $(SLIT_DECK) | deps-calculix
	@echo "== cuts: enriched vs unenriched far from the cut; the slit opens; CalculiX and meshless data reproduce =="
	@$(CUT_TOOL) far tests/cut/slit_parallel.yaml
	@$(CUT_TOOL) far --bound=1e-3 tests/cut/slit_parallel.yaml solver.integration=vci
	@$(CUT_TOOL) far --bound-all=1e-3 tests/cut/slit_parallel_weak.yaml
	@tests/cut/check_short.sh $(SLIT_DECK) $(CUT_TOOL) $(B)/cut-check $(CUT_DATA)

cut-validation: $(CUT_TOOL) $(SLIT_DECK) | deps-calculix deps-validation
	$(Q)CCX_LEVELS="$(CUT_CCX_LEVELS)" GRIDS="$(CUT_GRIDS)" \
	  tests/cut/run_validation.sh $(SLIT_DECK) $(CUT_TOOL) $(B)/cut $(CUT_DATA)
	@$(MAKE) --no-print-directory cut-pictures

cut-far-study: $(CUT_TOOL)
	$(Q)tests/cut/far_study.sh $(CUT_TOOL) $(CUT_DATA)/far_study.md

# Table and pictures from the committed data and one solve of the slit.
cut-pictures: $(B)/bin/tissuefit | deps-validation
	@mkdir -p $(B)/cut
	$(Q)tests/cut/table.sh $(CUT_DATA) > $(B)/cut/table.md
	$(Q)gnuplot -e "data='$(CUT_DATA)'; ccx='$(CUT_CCX_LEVELS)'; \
	  grids='$(foreach g,$(CUT_GRIDS),$(firstword $(subst $(cx_comma), ,$(g))))'; \
	  out='docs/cutting-cod.png'" tests/cut/cod.gp
	$(Q)$(B)/bin/tissuefit -q solve tests/cut/slit.yaml -o $(B)/cut/slit.csv --vtk $(B)/cut/slit.vtu
	$(Q)y=$$(awk -F, 'NR > 1 { print $$3 }' $(B)/cut/slit.csv | sort -gu | sed -n 4p); \
	  awk -F, -v y=$$y -v scale=1 -v cx=10 -v cz=5 -f tests/cut/sort.awk -f tests/cut/section.awk $(B)/cut/slit.csv > $(B)/cut/section.dat; \
	  awk -F, -v y=$$y -v scale=0 -v cx=10 -v cz=5 -f tests/cut/sort.awk -f tests/cut/section.awk $(B)/cut/slit.csv > $(B)/cut/plain.dat
	$(Q)gnuplot -e "section='$(B)/cut/section.dat'; plain='$(B)/cut/plain.dat'; out='docs/cutting-slit.png'; scale=1" \
	  tests/cut/slit_picture.gp
	@echo "cut: $(B)/cut/table.md, docs/cutting-cod.png, docs/cutting-slit.png, $(B)/cut/slit.vtu (ParaView)"

.PHONY: bench-cut
BENCHES += bench-cut
bench-cut: $(T)/cut/bench_cut
	@echo "== cuts: shape functions recomputed only where a support meets the cut =="
	@$(T)/cut/bench_cut tests/cut/slit.yaml geometry.grid=32,16,16 solver.cells=32,16,16

# Cut progress (the cut family, docs/cutting.md "Cut progress").
cut-progress-pictures: $(B)/bin/tissuefit | deps-validation
	$(Q)tests/cut/progress_pictures.sh $(B)/bin/tissuefit coeffs/block48_cut.yaml $(B)/cut \
	  docs/cutting-progress.png

cut-progress-study: $(T)/cut/progress_study
	$(Q)$(T)/cut/progress_study coeffs/block48_cut.yaml > $(B)/progress_study.md.tmp
	$(Q)mv $(B)/progress_study.md.tmp $(CUT_DATA)/progress_study.md
	@cat $(CUT_DATA)/progress_study.md
