/*
 * fuzz_cuts.c — libFuzzer target: arbitrary text as the `cuts:` section of
 * a small block48-like box scene (48 x 48 x 6 mm on a 7 x 7 x 3 grid).
 * Every line of the input is indented under `cuts:`, so the text can only
 * be cut entries (or an error), never another section.  The scene is
 * loaded as the tool loads it (tf_scene_load: scene_build.c's cuts, then
 * scene_cut_check.c: size, degenerate paths, paths along a face, every
 * node's support past the cuts).  When the cuts pass, the shape functions
 * a Galerkin solve builds are cut the same way (meshfree/shape.c:
 * tf_shape_set_cuts, RPIM's visibility and EFG's enrichment) and
 * evaluated at the points the cuts are hardest on: every path point and
 * segment midpoint at mid-depth, at the cut's bottom and on the top face.
 * Built with ASan + UBSan; a crash, a leak, undefined behaviour or a run
 * over the time limit is a finding.  tests/fuzz.mk runs it.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "meshfree/shape.h"
#include "scene/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const char header[] =
    "name: fuzz_cuts\n"
    "geometry: {box: {min: [0, 0, 0], max: [48, 48, 6]}, grid: [7, 7, 3]}\n"
    "material: {E: 0.32, nu: 0.49}\n"
    "fixed: [{face: x-}, {face: x+}, {face: y-}, {face: y+}]\n"
    "contact: [{name: top-centre, node: 123}]\n"
    "outputs: {select: face, face: z+}\n"
    "cuts:\n";

/* The scene text: header, then each input line indented by two spaces. */
static char *scene_text(const uint8_t *data, size_t size, size_t *len)
{
    size_t lines = 1;
    for (size_t i = 0; i < size; ++i) {
        lines += data[i] == '\n';
    }
    char *t = malloc(sizeof header + size + 2 * lines);
    if (t == NULL) {
        return NULL;
    }
    size_t n = sizeof header - 1;
    memcpy(t, header, n);
    t[n++] = ' ';
    t[n++] = ' ';
    for (size_t i = 0; i < size; ++i) {
        t[n++] = (char)data[i];
        if (data[i] == '\n') {
            t[n++] = ' ';
            t[n++] = ' ';
        }
    }
    *len = n;
    return t;
}

/* The points of cut c where its panels meet, end or are crossed. */
static size_t cut_points(const tf_cut *c, double (*x)[3], size_t max)
{
    const double z[3] = {c->top - c->depth / 2, c->top - c->depth, c->top};
    size_t m = 0;
    for (size_t i = 0; i < c->n && m + 6 <= max; ++i) {
        for (int k = 0; k < 3; ++k, ++m) {
            x[m][0] = c->xy[i][0];
            x[m][1] = c->xy[i][1];
            x[m][2] = z[k];
        }
        if (i + 1 < c->n) {
            for (int k = 0; k < 3; ++k, ++m) {
                x[m][0] = 0.5 * (c->xy[i][0] + c->xy[i + 1][0]);
                x[m][1] = 0.5 * (c->xy[i][1] + c->xy[i + 1][1]);
                x[m][2] = z[k];
            }
        }
    }
    return m;
}

/* The solver's shape functions (RPIM, or EFG when efg) with the problem's
 * cuts, at the points of every cut.  A singular support at such a point is
 * the solver's to report, not a finding. */
static void shapes_at_cuts(const tf_problem *p, int efg)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_shape sh;
    double lo[3], hi[3];
    tf_problem_bounds(p, lo, hi);
    if (tf_shape_init(&sh, &p->cloud, lo, hi, &p->solver) != 0) {
        return;
    }
    if ((!efg || tf_shape_use_efg(&ctx, &sh) == 0) &&
        tf_shape_set_cuts(&ctx, &sh, p->cuts, p->n_cuts) == 0) {
        tf_shape_work w;
        tf_shape_work_init(&w);
        double x[6 * TF_CUT_MAX_POINTS][3];
        for (size_t k = 0; k < p->n_cuts; ++k) {
            size_t m = cut_points(&p->cuts[k], x, sizeof x / sizeof x[0]);
            for (size_t j = 0; j < m; ++j) {
                (void)tf_shape_at(&sh, &w, x[j], tf_shape_cell(&sh, x[j]), 1);
            }
        }
        tf_shape_work_free(&w);
    }
    tf_shape_free(&sh);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    size_t len;
    char *text = scene_text(data, size, &len);
    if (text == NULL) {
        return 0;
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = tf_scene_load_text(&ctx, text, len, "fuzz_cuts.yaml", NULL, 0);
    if (s != NULL && s->problem.n_cuts > 0) {
        shapes_at_cuts(&s->problem, 0);
        shapes_at_cuts(&s->problem, 1);
    }
    tf_scene_free(s);
    free(text);
    return 0;
}
