# geometry.mk — organ surfaces to node clouds with tetrahedral cells
# (issue 15, host/geometry/).
#
#   check-geometry   the liver (OBJ, and the original binary VTK with its
#                    specks and inward winding) at a coarse spacing: cells'
#                    volume within 1 % of the enclosed volume, no node
#                    outside the surface (winding numbers); a second run
#                    gives the same bytes; seconds
#   geometry-demo    liver, stomach and heart at two spacings each, the
#                    liver graded towards a surface point, and liver.vtk:
#                    counts, volumes, median times of 3 runs (the table in
#                    docs/geometry.md) and a .vtu per mesh for ParaView in
#                    build/geometry/
# Unit tests (tests/unit/geometry/test_{rules,surface,mesh}.c) run with
# check-unit and check-sanitize.
#
# The organ meshes are read from MESHES (outside the repository, see
# ../shared/data/meshes/README.md for units and licences); a missing file
# fails the check.

MESHES ?= ../shared/data/meshes
GEOMETRY_OUT := $(B)/geometry

.PHONY: check-geometry geometry-demo
CHECKS += check-geometry

$(T)/unit/geometry/test_surface $(T)/unit/geometry/test_mesh $(T)/unit/geometry/test_surface_refine \
$(T)/asan/geometry/test_surface $(T)/asan/geometry/test_mesh $(T)/asan/geometry/test_surface_refine: tests/geometry/shapes.h

$(T)/geometry/mesh_demo: tests/geometry/mesh_demo.c $(B)/native/libtissuefit-host.a | deps-build
	@mkdir -p $(@D)
	$(call say,BUILD)
	$(Q)$(CC) $(TEST_CFLAGS) -O2 $< $(B)/native/libtissuefit-host.a $(HOST_LIBS) -o $@

check-geometry: $(T)/geometry/mesh_demo
	@echo "== organ geometry: the liver filled with tetrahedra (volume within 1 %, no node outside) =="
	@$< $(MESHES)/derived/liver_vtk_main.obj --spacing 12 --check --vtu $(T)/geometry/liver-1.vtu
	@$< $(MESHES)/liver.vtk --spacing 12 --check
	@$< $(MESHES)/derived/liver_vtk_main.obj --spacing 12 --vtu $(T)/geometry/liver-2.vtu >/dev/null
	@cmp $(T)/geometry/liver-1.vtu $(T)/geometry/liver-2.vtu && \
	  echo "ok: two runs on the same liver wrote the same .vtu, byte for byte"

# $(call geometry_run,LABEL,FILE,SPACING,TRANSFORM)
geometry_run = $(T)/geometry/mesh_demo $(MESHES)/$(2) --spacing $(3) $(4) --check \
  --repeat 3 --vtu $(GEOMETRY_OUT)/$(1)-$(3).vtu --row '$(1) ($(2))' | tee -a $(GEOMETRY_OUT)/log.txt;

geometry-demo: $(T)/geometry/mesh_demo
	@echo "== organ geometry: three organs at two spacings, the liver graded, and liver.vtk =="
	@mkdir -p $(GEOMETRY_OUT) && rm -f $(GEOMETRY_OUT)/log.txt
	@$(call geometry_run,liver,derived/liver_vtk_main.obj,10,) \
	 $(call geometry_run,liver,derived/liver_vtk_main.obj,5,) \
	 $(call geometry_run,stomach,FMA7148_Stomach.obj,8,--centre) \
	 $(call geometry_run,stomach,FMA7148_Stomach.obj,4,--centre) \
	 $(call geometry_run,heart,derived/coeur1.obj,2.5,) \
	 $(call geometry_run,heart,derived/coeur1.obj,1.25,) \
	 $(call geometry_run,liver-graded,derived/liver_vtk_main.obj,10,--grade 113.805 61.0116 116.117 2.5 5 40) \
	 $(call geometry_run,liver-vtk,liver.vtk,10,)
	@echo "| organ (file) | spacing mm | surface nodes | interior nodes | nodes | tetrahedra | enclosed mm^3 | cells - enclosed | outside | read+check s | mesh s |"
	@echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
	@grep '^| ' $(GEOMETRY_OUT)/log.txt
