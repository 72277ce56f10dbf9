/*
 * fuzz_mesh.c — libFuzzer target: arbitrary bytes as an organ's surface
 * mesh.  The first byte picks the format, '0' + k for k = 0 .. 4 (others
 * modulo 5): .obj, .stl (ASCII or binary: the reader tells them by their
 * content), .ply, .off (assimp, read_assimp.c) or legacy .vtk (gmsh,
 * read_gmsh.c); the rest is written to a file of that extension and loaded
 * as the tool loads `geometry.surface.file` (tf_surface_load: the bounded
 * file check, the reader, surface_prepare.c's repeated vertices, unused
 * vertices, open or non-manifold edges, winding, pieces, volume, units and
 * self-intersections), then the volume mesher's option check.  It stops
 * before gmsh fills the surface with tetrahedra (seconds per input).
 * Built with ASan + UBSan (the two readers' libraries are not instrumented:
 * their own memory errors show only as crashes); a crash, a leak,
 * undefined behaviour or a run over the time limit is a finding, except
 * the libraries' own leaks (suppressed below).  tests/fuzz.mk runs it.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "geometry/surface_prepare.h"
#include "geometry/volume_mesh.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
const char *__asan_default_options(void);
const char *__lsan_default_suppressions(void);

/* The readers' libraries leak on some malformed files: gmsh 4.8's
 * GModel::readVTK the nodes it has read when a file breaks off (fewer
 * POINTS than announced), assimp 5.2's importers what they had built when
 * they throw (a PLY file whose rows break off).  The libraries' leaks, not
 * the readers', and one per refused file in a process that then exits;
 * they are suppressed by name, which needs the full stack of every
 * allocation (libstdc++ has no frame pointers for the fast unwinder).
 * Leaks of what tissuefit's own code allocates are still findings. */
const char *__asan_default_options(void) { return "fast_unwind_on_malloc=0"; }
const char *__lsan_default_suppressions(void)
{
    return "leak:GModel::readVTK\nleak:libassimp.so\n";
}

static const char *const ext[5] = {"obj", "stl", "ply", "off", "vtk"};
static char dir[512], path[5][600];

static void remove_files(void)
{
    for (int k = 0; k < 5; ++k) {
        unlink(path[k]);
    }
    rmdir(dir);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    const char *tmp = getenv("TMPDIR");
    snprintf(dir, sizeof dir, "%s/fuzz_mesh_XXXXXX", tmp && *tmp ? tmp : "/tmp");
    if (mkdtemp(dir) == NULL) {
        perror("fuzz_mesh: mkdtemp");
        exit(2);
    }
    for (int k = 0; k < 5; ++k) {
        snprintf(path[k], sizeof path[k], "%s/organ.%s", dir, ext[k]);
    }
    atexit(remove_files);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0) {
        return 0;
    }
    const char *file = path[(uint8_t)(data[0] - '0') % 5];
    FILE *f = fopen(file, "wb");
    if (f == NULL || fwrite(data + 1, 1, size - 1, f) != size - 1 || fclose(f) != 0) {
        perror("fuzz_mesh: mesh file");
        abort();
    }
    tf_transform place = tf_transform_identity();
    tf_surface s;
    tf_geom_msg m;
    if (tf_surface_load(file, &place, &s, &m) == TF_GEOM_OK) {
        const tf_mesh_options o = {.spacing = 5};
        (void)tf_volume_mesh_check_options(&s, &o, &m);
        tf_surface_free(&s);
    }
    return 0;
}
