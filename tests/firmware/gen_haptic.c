/*
 * gen_haptic.c — writes haptic.h: test models shaped like the block48 scene
 * until the fitting pipeline ships real ones (coeffs/), so that the firmware
 * budgets (docs/firmware.md) are measured on the right sizes:
 *
 *   haptic_forward      nodal, p = 1, 121 output points (the 11 x 11 top
 *                       surface of block48, nodes 1..121), force [N] -> mm
 *   haptic_contact_p1   contact, p = 1, 2, 3 at node 61 (the top centre),
 *   haptic_contact_p2   displacement [mm] -> force [N]
 *   haptic_contact_p3
 *   haptic_creep        prony: haptic_forward's compliance as the relaxed
 *                       static map, creeping with two terms (0.3 at 0.25 s,
 *                       0.2 at 2.5 s) at a 1 ms tick
 *
 * The numbers are synthetic but plausible: a compliance field peaked at the
 * contact node with block48's reported centre compliances (2.83 mm/N in
 * plane, 14.5 mm/N normal, seed 000 §4.1), decaying with distance; the
 * contact models invert the centre compliance and add a few percent of
 * deterministic higher-order terms.
 *
 * `gen_haptic shapes FILE.h` writes shapes.h instead: small models of every
 * family at the edges of the loop structure (p = 0, 1, 2, 5, 8; r = 1 and
 * 48; zhou2017 orders with zeros; p = 1 with n_out = 1, 16, 30, 33; prony
 * with K = 0, 1, 2, 8 terms over nodal and modal static maps), so
 * that the golden vectors and the cycle model's check
 * (make check-cycles) sees every path through the compiled evaluator.
 *
 * usage: gen_haptic FILE.h | gen_haptic shapes FILE.h
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/rng.h"
#include "emit/emit_header.h"
#include "model/forms/prony.h"

#define GRID 11
#define SPACING 4.8        /* mm */
#define DECAY 7.0          /* mm */
#define C_PLANE 2.83       /* mm/N */
#define C_NORMAL 14.5      /* mm/N */
#define FORCE_RADIUS 1.0   /* N */
#define CONTACT_NODE 61

static tf_model *forward(tf_ctx *ctx)
{
    const uint32_t dims[1] = {1};
    tf_model *m = tf_model_new(ctx, "haptic_forward", TFIT_FAMILY_NODAL, GRID * GRID, dims, 1);
    if (m == NULL) {
        return NULL;
    }
    const double centre[3] = {0, 0, 0};
    tf_model_set_ball(m, centre, FORCE_RADIUS);
    float *c = tf_model_tables(m); /* rows of 4: constant, g0, g1, g2 */
    for (int node = 0; node < GRID * GRID; ++node) {
        double x = (node % GRID - GRID / 2) * SPACING, y = (node / GRID - GRID / 2) * SPACING;
        double w = exp(-(x * x + y * y) / (2 * DECAY * DECAY));
        double comp[3][3] = {{C_PLANE * w, 0, 0.1 * x / DECAY * w},
                             {0, C_PLANE * w, 0.1 * y / DECAY * w},
                             {0.2 * x / DECAY * w, 0.2 * y / DECAY * w, C_NORMAL * w}};
        m->node_ids[node] = (uint32_t)node + 1;
        for (int i = 0; i < 3; ++i) {
            for (int k = 0; k < 3; ++k) {
                c[(3 * node + i) * 4 + 1 + k] = (float)(comp[i][k] * FORCE_RADIUS);
            }
        }
    }
    m->envelope_radius = FORCE_RADIUS;
    return m;
}

/* The forward model's compliance as the relaxed map of a creeping body. */
static tf_model *creep(tf_ctx *ctx, const tf_model *fwd)
{
    const uint32_t dims[TFIT_PRONY_DIMS] = {1, 0, 2, 1000000};
    tf_model *m =
        tf_model_new(ctx, "haptic_creep", TFIT_FAMILY_PRONY, fwd->n_out, dims, TFIT_PRONY_DIMS);
    if (m == NULL) {
        return NULL;
    }
    const double centre[3] = {0, 0, 0};
    tf_model_set_ball(m, centre, FORCE_RADIUS);
    tf_prony_set_term(m, 0, 0.25, 0.3);
    tf_prony_set_term(m, 1, 2.5, 0.2);
    const tf_model v = tf_stateful_static_view(m);
    for (uint32_t i = 0; i < fwd->n_coef - TFIT_INPUT_MAP_FLOATS; ++i) {
        v.coef[TFIT_INPUT_MAP_FLOATS + i] = fwd->coef[TFIT_INPUT_MAP_FLOATS + i];
    }
    for (uint32_t j = 0; j < fwd->n_out; ++j) {
        m->node_ids[j] = fwd->node_ids[j];
    }
    return m;
}

static tf_model *contact(tf_ctx *ctx, uint32_t p)
{
    char name[32];
    snprintf(name, sizeof name, "haptic_contact_p%u", p);
    const uint32_t dims[1] = {p};
    tf_model *m = tf_model_new(ctx, name, TFIT_FAMILY_CONTACT, 1, dims, 1);
    if (m == NULL) {
        return NULL;
    }
    const double centre[3] = {0, 0, 0};
    const double radius = C_NORMAL * FORCE_RADIUS; /* mm: the largest displacement */
    tf_model_set_ball(m, centre, radius);
    m->node_ids[0] = CONTACT_NODE;
    uint32_t t = tf_terms(p);
    float *c = tf_model_tables(m);
    const double stiffness[3] = {1 / C_PLANE, 1 / C_PLANE, 1 / C_NORMAL}; /* N/mm */
    tf_rng r = {2017 + p};
    for (int row = 0; row < 3; ++row) {
        c[row * t + 1 + (uint32_t)row] = (float)(stiffness[row] * radius);
        for (uint32_t k = 4; k < t; ++k) { /* degree >= 2: a few percent */
            c[row * t + k] = (float)(0.03 * tf_rng_range(&r, -1, 1));
        }
    }
    return m;
}

/* A model of the given shape with small deterministic coefficients: every
 * bound of tf_model_validate stays far below its limit. */
static tf_model *shaped(tf_ctx *ctx, const char *name, tfit_family f, uint32_t n_out,
                        const uint32_t *dims, uint32_t n_dims, tf_rng *r)
{
    tf_model *m = tf_model_new(ctx, name, f, n_out, dims, n_dims);
    if (m == NULL) {
        return NULL;
    }
    uint32_t n = m->n_coef - TFIT_INPUT_MAP_FLOATS;
    float *c = tf_model_tables(m);
    for (uint32_t i = 0; i < n; ++i) {
        c[i] = (float)(tf_rng_range(r, -1, 1) / (4.0 * n));
    }
    if (f == TFIT_FAMILY_ZHOU2017) {
        for (uint32_t i = n - 2 * n_out; i < n; ++i) {
            c[i] = (float)tf_rng_range(r, -1, 1);
        }
    }
    for (uint32_t k = 0; f == TFIT_FAMILY_PRONY && k < dims[2]; ++k) { /* tau 2^k ticks */
        tf_prony_set_term(m, k, ldexp(tf_stateful_tick(m), (int)k), 0.1);
    }
    for (uint32_t j = 0; j < n_out; ++j) {
        m->node_ids[j] = j + 1;
    }
    return m;
}

static int shapes(const char *path)
{
    static const uint32_t zhou_dims[TFIT_ZHOU2017_DIMS] = {
        0, 1, 8, /* lambda */
        0, 0, 0, 1, 0, 2, 0, 1, 1, /* (A, B, k) for xx, xy, xz */
        2, 2, 0, 8, 8, 8, 1, 3, 0, /* yx, yy, yz */
        3, 1, 2, 0, 2, 3, 1, 1, 1};  /* zx, zy, zz */
    struct {
        const char *name;
        tfit_family f;
        uint32_t n_out, dims[TFIT_PRONY_DIMS], n_dims;
    } list[] = {
        {"nodal_p0", TFIT_FAMILY_NODAL, 3, {0, 0}, 1},
        {"nodal_p2", TFIT_FAMILY_NODAL, 2, {2, 0}, 1},
        {"nodal_p5", TFIT_FAMILY_NODAL, 1, {5, 0}, 1},
        {"nodal_p8", TFIT_FAMILY_NODAL, 2, {8, 0}, 1},
        {"contact_p0", TFIT_FAMILY_CONTACT, 1, {0, 0}, 1},
        {"modal_p0_r1", TFIT_FAMILY_MODAL, 2, {0, 1}, 2},
        {"modal_p2_r5", TFIT_FAMILY_MODAL, 3, {2, 5}, 2},
        {"modal_p1_r48", TFIT_FAMILY_MODAL, 2, {1, 48}, 2},
        /* degree 1 (tfit_degree1_armv7em.c): n_out / 16 iterations of the
         * 8-pair loop, (n_out / 2) mod 8 single pairs, an odd point */
        {"nodal_p1_n1", TFIT_FAMILY_NODAL, 1, {1, 0}, 1},
        {"nodal_p1_n16", TFIT_FAMILY_NODAL, 16, {1, 0}, 1},
        {"nodal_p1_n30", TFIT_FAMILY_NODAL, 30, {1, 0}, 1},
        {"nodal_p1_n33", TFIT_FAMILY_NODAL, 33, {1, 0}, 1},
        /* prony {p, r, K, tick_ns}: no term (the loop skipped), one, two, eight */
        {"prony_k0_p1", TFIT_FAMILY_PRONY, 2, {1, 0, 0, 1000000}, 4},
        {"prony_k1_p0", TFIT_FAMILY_PRONY, 3, {0, 0, 1, 250000}, 4},
        {"prony_k2_p1_r1", TFIT_FAMILY_PRONY, 1, {1, 1, 2, 1000000}, 4},
        {"prony_k8_p2_r3", TFIT_FAMILY_PRONY, 2, {2, 3, 8, 100000}, 4},
    };
    enum { N_LIST = sizeof list / sizeof list[0] };
    tf_model *models[N_LIST + 1] = {NULL};
    tf_rng r = {77};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    int rc = 1;
    size_t n = 0;
    for (; n < N_LIST; ++n) {
        models[n] =
            shaped(&ctx, list[n].name, list[n].f, list[n].n_out, list[n].dims, list[n].n_dims, &r);
        if (models[n] == NULL) {
            goto done;
        }
    }
    models[n] =
        shaped(&ctx, "zhou_edges", TFIT_FAMILY_ZHOU2017, 3, zhou_dims, TFIT_ZHOU2017_DIMS, &r);
    if (models[n++] == NULL) {
        goto done;
    }
    const tf_emit_info info = {
        .source = "loop-structure edge cases for the cycle model (tests/firmware/gen_haptic.c)",
        .golden_seed = 5};
    rc = tf_emit_header(&ctx, path, models, n, &info) != 0;
done:
    if (rc != 0) {
        fprintf(stderr, "gen_haptic: %s\n", ctx.err);
    }
    for (size_t i = 0; i < n; ++i) {
        tf_model_free(models[i]);
    }
    return rc;
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "shapes") == 0) {
        return shapes(argv[2]);
    }
    if (argc != 2) {
        fprintf(stderr, "usage: gen_haptic FILE.h | gen_haptic shapes FILE.h\n");
        return 2;
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *models[5] = {forward(&ctx), NULL, NULL, NULL, NULL};
    for (uint32_t p = 1; p <= 3 && models[p - 1] != NULL; ++p) {
        models[p] = contact(&ctx, p);
    }
    if (models[3] != NULL) {
        models[4] = creep(&ctx, models[0]);
    }
    int rc = 1;
    if (models[4] != NULL) {
        const tf_emit_info info = {
            .source = "synthetic block48-shaped test models (tests/firmware/gen_haptic.c)",
            .golden_seed = 48};
        rc = tf_emit_header(&ctx, argv[1], models, 5, &info) != 0;
    }
    if (rc != 0) {
        fprintf(stderr, "gen_haptic: %s\n", ctx.err);
    }
    for (int i = 0; i < 5; ++i) {
        tf_model_free(models[i]);
    }
    return rc;
}
