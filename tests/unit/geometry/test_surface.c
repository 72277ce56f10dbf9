/*
 * test_surface.c — reading, checking, repairing and placing organ
 * surfaces (geometry/surface_*.h, transform.h, self_intersect.h) on
 * surfaces the test generates: each bad mesh gets its clear message.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include "tests/geometry/shapes.h"
#include "assert_close.h"
#include "geometry/self_intersect.h"
#include "geometry/surface_prepare.h"
#include "geometry/surface_read.h"
#include "geometry/surface_vertices.h"
#include "geometry/transform.h"

static char dir[64];

static int make_dir(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/tf_geometry_XXXXXX");
    return mkdtemp(dir) == NULL ? -1 : 0;
}

static int remove_dir(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

static const char *file(const char *name)
{
    static char path[128];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return path;
}

static void assert_contains(const char *text, const char *part)
{
    if (strstr(text, part) == NULL) {
        print_error("\"%s\" does not contain \"%s\"\n", text, part);
        fail();
    }
}

/* A cube of 20 mm at x0 = 10, cleaned and checked as the scene would. */
static int prepare(tf_surface *s, tf_geom_msg *m)
{
    memset(m, 0, sizeof *m);
    int rc = tf_surface_clean(s, m);
    return rc ? rc : tf_surface_check_placed(s, m);
}

static void a_closed_cube_passes_untouched(void **state)
{
    (void)state;
    tf_surface s;
    tf_geom_msg m;
    assert_int_equal(shape_cube(&s, 10, 20), 0);
    assert_int_equal(prepare(&s, &m), TF_GEOM_OK);
    assert_string_equal(m.notes, "");
    assert_int_equal(s.nv, 8);
    assert_int_equal(s.nt, 12);
    assert_close(tf_surface_volume(&s), 8000, 1e-9);
    assert_close(tf_surface_area(&s), 2400, 1e-9);
    tf_surface_free(&s);
}

static void an_open_box_is_refused(void **state)
{
    (void)state;
    tf_surface s;
    tf_geom_msg m;
    shape_cube(&s, 10, 20);
    s.nt = 11; /* the lid loses a triangle */
    assert_int_equal(prepare(&s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "open surface (edges of only one triangle): 3 edges");
    tf_surface_free(&s);
}

static void a_flipped_triangle_is_refused(void **state)
{
    (void)state;
    tf_surface s;
    tf_geom_msg m;
    shape_cube(&s, 10, 20);
    size_t v = s.tri[3 * 5 + 1];
    s.tri[3 * 5 + 1] = s.tri[3 * 5 + 2];
    s.tri[3 * 5 + 2] = v;
    assert_int_equal(prepare(&s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "inconsistent winding");
    assert_contains(m.error, "3 edges");
    assert_contains(m.error, "vertices 0 (10, 10, 10) and 4 (10, 10, 30), triangles 5 and 10");
    tf_surface_free(&s);
}

static void inward_winding_is_reversed_with_a_note(void **state)
{
    (void)state;
    tf_surface s;
    tf_geom_msg m;
    shape_cube(&s, 10, 20);
    tf_surface_reverse(&s);
    assert_close(tf_surface_volume(&s), -8000, 1e-9);
    assert_int_equal(prepare(&s, &m), TF_GEOM_OK);
    assert_contains(m.notes, "wound inward");
    assert_close(tf_surface_volume(&s), 8000, 1e-9);
    tf_surface_free(&s);
}

/* Two cubes in one surface: the second's vertices follow the first's. */
static void two_cubes(tf_surface *s, double size2)
{
    tf_surface a, b;
    shape_cube(&a, 10, 20);
    shape_cube(&b, 50, size2);
    tf_surface_alloc(s, 16, 24);
    memcpy(s->xyz, a.xyz, 24 * sizeof *s->xyz);
    memcpy(s->xyz + 24, b.xyz, 24 * sizeof *s->xyz);
    for (size_t k = 0; k < 36; ++k) {
        s->tri[k] = a.tri[k];
        s->tri[36 + k] = b.tri[k] + 8;
    }
    tf_surface_free(&a);
    tf_surface_free(&b);
}

static void specks_are_dropped_and_a_second_organ_refused(void **state)
{
    (void)state;
    tf_surface s;
    tf_geom_msg m;
    two_cubes(&s, 2); /* 8 mm^3: 0.1 % of 8000 */
    assert_int_equal(prepare(&s, &m), TF_GEOM_OK);
    assert_contains(m.notes, "kept the largest of 2 pieces; dropped 12 triangles");
    assert_int_equal(s.nv, 8);
    assert_int_equal(s.nt, 12);
    assert_int_equal(s.source[7], 7);
    tf_surface_free(&s);

    two_cubes(&s, 5); /* 125 mm^3: 1.6 % */
    assert_int_equal(prepare(&s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "2 separate pieces: piece 2 (from triangle 12) encloses 1.56 %");
    tf_surface_free(&s);
}

static void unused_vertices_are_dropped_keeping_file_indices(void **state)
{
    (void)state;
    tf_surface s, c;
    tf_geom_msg m;
    shape_cube(&c, 10, 20);
    tf_surface_alloc(&s, 9, 12); /* vertex 0 is unused, the cube's are 1..8 */
    s.xyz[0] = s.xyz[1] = s.xyz[2] = 1e6;
    memcpy(s.xyz + 3, c.xyz, 24 * sizeof *s.xyz);
    for (size_t k = 0; k < 36; ++k) {
        s.tri[k] = c.tri[k] + 1;
    }
    assert_int_equal(prepare(&s, &m), TF_GEOM_OK);
    assert_contains(m.notes, "dropped 1 vertices");
    assert_int_equal(s.nv, 8);
    for (size_t v = 0; v < 8; ++v) {
        assert_int_equal(s.source[v], (long)v + 1);
        assert_true(memcmp(s.xyz + 3 * v, c.xyz + 3 * v, 3 * sizeof *s.xyz) == 0);
    }
    tf_surface_free(&s);
    tf_surface_free(&c);
}

static void a_degenerate_or_nonmanifold_surface_is_refused(void **state)
{
    (void)state;
    tf_surface s;
    tf_geom_msg m;
    shape_cube(&s, 10, 20);
    s.tri[3 * 7 + 2] = s.tri[3 * 7];
    assert_int_equal(prepare(&s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "degenerate triangle 7");
    tf_surface_free(&s);

    /* a fin: a triangle standing on an edge of the cube (third triangle there) */
    tf_surface c;
    shape_cube(&c, 10, 20);
    tf_surface_alloc(&s, 9, 13);
    memcpy(s.xyz, c.xyz, 24 * sizeof *s.xyz);
    memcpy(s.tri, c.tri, 36 * sizeof *s.tri);
    s.xyz[24] = 0, s.xyz[25] = 0, s.xyz[26] = 0;
    s.tri[36] = 0, s.tri[37] = 1, s.tri[38] = 8;
    assert_int_equal(prepare(&s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "open surface"); /* the fin's free edges come first */
    tf_surface_free(&s);
    tf_surface_free(&c);
}

/* Two cubes joined at one corner: every edge has two triangles traversing
 * it in opposite directions, one piece, positive volume, but the shared
 * vertex carries two fans of triangles (two discs pinched together). */
static void two_cubes_joined_at_a_vertex_are_refused(void **state)
{
    (void)state;
    tf_surface a, b, s;
    tf_geom_msg m;
    shape_cube(&a, 10, 20); /* vertex 6 at (30, 30, 30) */
    shape_cube(&b, 30, 20); /* vertex 0 at (30, 30, 30) */
    assert_int_equal(tf_surface_alloc(&s, 15, 24), 0);
    memcpy(s.xyz, a.xyz, 24 * sizeof *s.xyz);
    memcpy(s.xyz + 24, b.xyz + 3, 21 * sizeof *s.xyz);
    memcpy(s.tri, a.tri, 36 * sizeof *s.tri);
    for (size_t k = 0; k < 36; ++k) {
        s.tri[36 + k] = b.tri[k] == 0 ? 6 : b.tri[k] + 7;
    }
    assert_int_equal(prepare(&s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "non-manifold vertex");
    assert_contains(m.error, "1 vertex; the first, vertex 6 at (30, 30, 30), joins 2 fans");
    tf_vertex_fault f;
    assert_int_equal(tf_surface_vertex_fans(&s, &f), 0);
    assert_int_equal(f.count, 1);
    tf_surface_free(&s);
    /* each cube alone: every vertex one fan */
    assert_int_equal(tf_surface_vertex_fans(&a, &f), 0);
    assert_int_equal(f.count, 0);
    tf_surface_free(&a);
    tf_surface_free(&b);
}

/* A cube whose top corner (vertex 6) is pushed down through the bottom:
 * still one closed, consistently wound piece, but it crosses itself. */
static void a_self_intersecting_surface_is_refused(void **state)
{
    (void)state;
    tf_surface s;
    tf_geom_msg m;
    shape_cube(&s, 10, 20);
    s.xyz[3 * 6] = 22, s.xyz[3 * 6 + 1] = 22, s.xyz[3 * 6 + 2] = 5;
    assert_int_equal(prepare(&s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "self-intersecting surface:");
    assert_contains(m.error, "the volume mesher cannot fill it");
    tf_crossing c;
    assert_int_equal(tf_surface_crossings(&s, &c), 0);
    assert_true(c.pairs >= 1);
    assert_true(c.at[2] >= 10 - 1e-9 && c.at[2] <= 30); /* on the bottom or a side */
    tf_surface_free(&s);

    shape_cube(&s, 10, 20); /* the untouched cube crosses nothing */
    assert_int_equal(tf_surface_crossings(&s, &c), 0);
    assert_int_equal(c.pairs, 0);
    tf_surface_free(&s);
}

static void segment_triangle_crossing(void **state)
{
    (void)state;
    const double a[3] = {0, 0, 0}, b[3] = {4, 0, 0}, c[3] = {0, 4, 0};
    const double p[3] = {1, 1, -1}, q[3] = {1, 1, 3}, r[3] = {5, 5, -1}, s[3] = {5, 5, 1};
    double at[3];
    assert_int_equal(tf_segment_crosses_triangle(p, q, a, b, c, at), 1);
    assert_close(at[0], 1, 1e-15);
    assert_close(at[2], 0, 1e-15);
    assert_int_equal(tf_segment_crosses_triangle(r, s, a, b, c, at), 0); /* misses */
    assert_int_equal(tf_segment_crosses_triangle(p, a, a, b, c, at), 0); /* touches a corner */
}

static void absurd_units_are_refused(void **state)
{
    (void)state;
    tf_surface s;
    tf_geom_msg m;
    tf_transform t = tf_transform_identity();
    shape_cube(&s, 10, 20);
    t.scale = 0.01; /* 20 file units read as cm -> 0.2 mm */
    assert_int_equal(tf_transform_apply(&t, &s, &m), TF_GEOM_OK);
    assert_int_equal(prepare(&s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "absurd size: the bounding box is 0.2 x 0.2 x 0.2 mm after "
                             "scaling, under 1 mm");
    tf_surface_free(&s);

    shape_cube(&s, 10, 20);
    t.scale = 100;
    tf_transform_apply(&t, &s, &m);
    assert_int_equal(prepare(&s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "over 1 m");
    tf_surface_free(&s);

    shape_cube(&s, 10, 20);
    t.scale = -1;
    assert_int_equal(tf_transform_apply(&t, &s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "scale -1: must be a positive number");
    tf_surface_free(&s);
}

static void transform_scales_centres_rotates_translates(void **state)
{
    (void)state;
    tf_surface s;
    tf_geom_msg m;
    shape_cube(&s, 10, 20); /* [10, 30]^3, vertex 1 at (30, 10, 10) */
    tf_transform t = {.scale = 2, .centre = 1, .axis = {0, 0, 5}, .angle_deg = 90,
                      .translate = {1, 2, 3}};
    assert_int_equal(tf_transform_apply(&t, &s, &m), TF_GEOM_OK);
    /* scaled (60, 20, 20), centre (40, 40, 40) -> (20, -20, -20), turned
     * 90 degrees about z -> (20, 20, -20), moved -> (21, 22, -17) */
    assert_close(s.xyz[3], 21, 1e-12);
    assert_close(s.xyz[4], 22, 1e-12);
    assert_close(s.xyz[5], -17, 1e-12);
    assert_close(tf_surface_volume(&s), 64000, 1e-6); /* 8000 x 2^3, turning keeps it */
    double lo[3], hi[3];
    tf_surface_bbox(&s, lo, hi);
    assert_close(0.5 * (lo[0] + hi[0]), 1, 1e-12);
    assert_close(0.5 * (lo[2] + hi[2]), 3, 1e-12);
    tf_surface_free(&s);
}

/* The same cube through each reader: OBJ with groups and texture seams,
 * STL (one triangle per facet, nothing shared), ASCII VTK. */
static void each_format_reads_the_same_closed_cube(void **state)
{
    (void)state;
    tf_surface c, s;
    tf_geom_msg m = {0};
    shape_cube(&c, 10, 20);
    FILE *fp = fopen(file("cube.obj"), "w");
    fprintf(fp, "vt 0 0\nvt 1 0\nvt 0 1\n");
    for (size_t v = 0; v < 8; ++v) {
        fprintf(fp, "v %g %g %g\n", c.xyz[3 * v], c.xyz[3 * v + 1], c.xyz[3 * v + 2]);
    }
    for (size_t t = 0; t < 12; ++t) {
        fprintf(fp, "%sf %zu/%zu %zu/%zu %zu/%zu\n", t == 6 ? "g second\nusemtl other\n" : "",
                c.tri[3 * t] + 1, t % 3 + 1, c.tri[3 * t + 1] + 1, (t + 1) % 3 + 1,
                c.tri[3 * t + 2] + 1, (t + 2) % 3 + 1);
    }
    fclose(fp);
    assert_int_equal(shape_write_stl(&c, file("cube.STL")), 0);
    assert_int_equal(shape_write_vtk(&c, file("cube.vtk")), 0);
    const char *names[] = {"cube.obj", "cube.STL", "cube.vtk"};
    for (int k = 0; k < 3; ++k) {
        assert_int_equal(tf_surface_read(file(names[k]), &s, &m), TF_GEOM_OK);
        assert_int_equal(s.nv, 8);
        assert_int_equal(s.nt, 12);
        assert_int_equal(tf_surface_clean(&s, &m), TF_GEOM_OK);
        assert_string_equal(m.notes, "");
        assert_close(tf_surface_volume(&s), 8000, 1e-9);
        tf_surface_free(&s);
    }
    /* VTK keeps the file's vertex order */
    tf_surface_read(file("cube.vtk"), &s, &m);
    assert_true(memcmp(s.xyz, c.xyz, 24 * sizeof *s.xyz) == 0);
    tf_surface_free(&s);
    tf_surface_free(&c);
}

/* An OBJ keeps the file's digits: a BodyParts3D-like cube at 1061.67 mm
 * from the origin, whose coordinates float32 holds only to 6e-5 mm (a
 * clamp "z <= 12" after an offset of -1061.67 lost its vertices), read
 * back exactly as strtod reads the text; shuffled `v` lines and an unused
 * record do not confuse the match. */
static void obj_keeps_the_files_digits(void **state)
{
    (void)state;
    tf_surface c, s;
    tf_geom_msg m = {0};
    shape_cube(&c, 10, 20);
    char text[8][3][32];
    FILE *fp = fopen(file("far.obj"), "w");
    fprintf(fp, "v 1061.6700001 0.1 0.3\n"); /* used by no face */
    for (size_t v = 0; v < 8; ++v) {
        for (int a = 0; a < 3; ++a) {
            snprintf(text[7 - v][a], sizeof text[0][0], "%.10g",
                     c.xyz[3 * (7 - v) + a] + 1061.67 + 1e-7 * (double)(3 * v + (size_t)a));
        }
        fprintf(fp, "v %s %s %s\n", text[7 - v][0], text[7 - v][1], text[7 - v][2]);
    }
    for (size_t t = 0; t < 12; ++t) {
        fprintf(fp, "f %zu %zu %zu\n", 9 - c.tri[3 * t], 9 - c.tri[3 * t + 1], 9 - c.tri[3 * t + 2]);
    }
    fclose(fp);
    assert_int_equal(tf_surface_read(file("far.obj"), &s, &m), TF_GEOM_OK);
    assert_int_equal(s.nv, 8);
    for (size_t v = 0; v < s.nv; ++v) {
        size_t hit = 8;
        for (size_t w = 0; w < 8; ++w) {
            if (s.xyz[3 * v] == strtod(text[w][0], NULL) &&
                s.xyz[3 * v + 1] == strtod(text[w][1], NULL) &&
                s.xyz[3 * v + 2] == strtod(text[w][2], NULL)) {
                hit = w;
            }
        }
        if (hit == 8) {
            fail_msg("vertex %zu (%.17g, %.17g, %.17g) is not a record of the file", v, s.xyz[3 * v],
                     s.xyz[3 * v + 1], s.xyz[3 * v + 2]);
        }
    }
    tf_surface_free(&s);
    tf_surface_free(&c);
}

/* A cube with one coordinate replaced by text, read by assimp and cleaned:
 * the message of tf_surface_clean. */
static const char *cube_with(const char *coordinate, tf_geom_msg *m)
{
    tf_surface c, s;
    shape_cube(&c, 10, 20);
    FILE *fp = fopen(file("odd.obj"), "w");
    for (size_t v = 0; v < 8; ++v) {
        if (v == 3 && coordinate != NULL) {
            fprintf(fp, "v %s %g %g\n", coordinate, c.xyz[3 * v + 1], c.xyz[3 * v + 2]);
        } else { /* NULL: every vertex 1e9 mm off the origin */
            fprintf(fp, "v %.17g %.17g %.17g\n", c.xyz[3 * v] + (coordinate == NULL ? 1e9 : 0),
                    c.xyz[3 * v + 1], c.xyz[3 * v + 2]);
        }
    }
    for (size_t t = 0; t < 12; ++t) {
        fprintf(fp, "f %zu %zu %zu\n", c.tri[3 * t] + 1, c.tri[3 * t + 1] + 1, c.tri[3 * t + 2] + 1);
    }
    fclose(fp);
    tf_surface_free(&c);
    memset(m, 0, sizeof *m);
    if (tf_surface_read(file("odd.obj"), &s, m) == TF_GEOM_OK) {
        if (tf_surface_clean(&s, m) == TF_GEOM_OK) {
            fail_msg("a cube with %s was cleaned without a word", coordinate ? coordinate : "1e9 offsets");
        }
        tf_surface_free(&s);
    }
    return m->error;
}

/* NaN and 1e300 (float32's infinity) are not finite numbers; coordinates
 * 1e9 mm off the origin lose their digits in the reader's float32 (its
 * spacing there is 64 mm), and the merged vertices say why. */
static void odd_coordinates_say_what_they_are(void **state)
{
    (void)state;
    tf_geom_msg m;
    assert_contains(cube_with("nan", &m), "a coordinate is not a finite number");
    assert_contains(cube_with("1e300", &m), "a coordinate is not a finite number");
    assert_contains(cube_with(NULL, &m), "far from the origin");
}

/* Malformed files on which assimp 5.2 asserted (an OFF file announcing more
 * faces than it holds; a PLY face list that breaks off) or never returned
 * (a PLY header without end_header) are refused with a message: the fuzz
 * regression inputs (their first byte chose the format), read as files. */
static const char *malformed(const char *input, const char *ext, tf_geom_msg *m)
{
    static char path[512];
    FILE *in = fopen(input, "rb");
    assert_non_null(in);
    snprintf(path, sizeof path, "%s.%s", file("malformed"), ext);
    FILE *out = fopen(path, "wb");
    assert_non_null(out);
    int c = fgetc(in); /* the fuzzer's format byte */
    while ((c = fgetc(in)) != EOF) {
        fputc(c, out);
    }
    fclose(in);
    fclose(out);
    tf_surface s;
    alarm(60);
    int rc = tf_surface_read(path, &s, m);
    alarm(0);
    if (rc == TF_GEOM_OK) {
        tf_surface_free(&s);
    }
    assert_int_equal(rc, TF_GEOM_BAD_INPUT);
    return m->error;
}

static void malformed_files_are_refused(void **state)
{
    (void)state;
    tf_geom_msg m;
    assert_contains(malformed("tests/fuzz/regress/mesh/off-fewer-faces", "off", &m),
                    "cannot read mesh");
    assert_contains(malformed("tests/fuzz/regress/mesh/ply-no-end-header", "ply", &m),
                    "a PLY header without its end_header line");
    assert_contains(malformed("tests/fuzz/regress/mesh/ply-polygons-declared-none", "ply", &m),
                    "declared to hold polygons holds none");
    assert_contains(malformed("tests/fuzz/regress/mesh/obj-nul-byte", "obj", &m),
                    "line 1 holds a NUL byte");
    assert_contains(malformed("tests/fuzz/regress/mesh/ply-header-garbage", "ply", &m),
                    "line 5: a PLY header line of none of its keywords");
}

static void unreadable_files_say_why(void **state)
{
    (void)state;
    tf_surface s;
    tf_geom_msg m;
    assert_int_equal(tf_surface_read(file("none.obj"), &s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "cannot read mesh");
    assert_contains(m.error, "none.obj");
    assert_int_equal(tf_surface_read(file("none.vtk"), &s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "none.vtk': cannot open: No such file or directory");
    /* a FIFO would block either library, a device would be read without end */
    assert_int_equal(mkfifo(file("fifo.obj"), 0600), 0);
    alarm(20);
    assert_int_equal(tf_surface_read(file("fifo.obj"), &s, &m), TF_GEOM_BAD_INPUT);
    alarm(0);
    assert_contains(m.error, "fifo.obj': not a regular file");
    unlink(file("fifo.obj"));
    assert_int_equal(tf_surface_read("/dev/zero.obj", &s, &m), TF_GEOM_BAD_INPUT);
    FILE *big = fopen(file("big.obj"), "w");
    assert_non_null(big);
    assert_int_equal(ftruncate(fileno(big), (off_t)TF_SURFACE_MAX_BYTES + 1), 0);
    fclose(big);
    assert_int_equal(tf_surface_read(file("big.obj"), &s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "more than the 16 MiB a surface mesh file may hold");
    unlink(file("big.obj"));
    FILE *fp = fopen(file("bad.vtk"), "w");
    fprintf(fp, "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0\n");
    fclose(fp);
    assert_int_equal(tf_surface_read(file("bad.vtk"), &s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "cannot read mesh: Error loading");
    assert_contains(m.error, "bad.vtk");
    assert_int_equal(tf_surface_read(file("cube.dae"), &s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "unknown mesh format '.dae'");

    fp = fopen(file("lines.obj"), "w");
    fprintf(fp, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 2\n");
    fclose(fp);
    assert_int_equal(tf_surface_read(file("lines.obj"), &s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "1 faces are points or lines, not triangles");

    fp = fopen(file("range.obj"), "w");
    fprintf(fp, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
    fclose(fp);
    assert_int_equal(tf_surface_read(file("range.obj"), &s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "index out of range");

    /* the whole pipeline with a transform: an open surface from a file */
    tf_surface c;
    shape_cube(&c, 10, 20);
    c.nt = 10;
    shape_write_vtk(&c, file("open.vtk"));
    tf_transform t = tf_transform_identity();
    assert_int_equal(tf_surface_load(file("open.vtk"), &t, &s, &m), TF_GEOM_BAD_INPUT);
    assert_contains(m.error, "open surface");
    assert_null(s.xyz);
    tf_surface_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_closed_cube_passes_untouched),
        cmocka_unit_test(an_open_box_is_refused),
        cmocka_unit_test(a_flipped_triangle_is_refused),
        cmocka_unit_test(inward_winding_is_reversed_with_a_note),
        cmocka_unit_test(specks_are_dropped_and_a_second_organ_refused),
        cmocka_unit_test(unused_vertices_are_dropped_keeping_file_indices),
        cmocka_unit_test(a_degenerate_or_nonmanifold_surface_is_refused),
        cmocka_unit_test(two_cubes_joined_at_a_vertex_are_refused),
        cmocka_unit_test(a_self_intersecting_surface_is_refused),
        cmocka_unit_test(segment_triangle_crossing),
        cmocka_unit_test(absurd_units_are_refused),
        cmocka_unit_test(transform_scales_centres_rotates_translates),
        cmocka_unit_test(each_format_reads_the_same_closed_cube),
        cmocka_unit_test(obj_keeps_the_files_digits),
        cmocka_unit_test(odd_coordinates_say_what_they_are),
        cmocka_unit_test(malformed_files_are_refused),
        cmocka_unit_test(unreadable_files_say_why),
    };
    return cmocka_run_group_tests(tests, make_dir, remove_dir);
}
