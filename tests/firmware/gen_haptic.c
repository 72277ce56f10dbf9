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
 *
 * The numbers are synthetic but plausible: a compliance field peaked at the
 * contact node with block48's reported centre compliances (2.83 mm/N in
 * plane, 14.5 mm/N normal, seed 000 §4.1), decaying with distance; the
 * contact models invert the centre compliance and add a few percent of
 * deterministic higher-order terms.  usage: gen_haptic FILE.h
 */
#include <math.h>
#include <stdio.h>

#include "emit_header.h"
#include "rng.h"

#define GRID 11
#define SPACING 4.8        /* mm */
#define DECAY 7.0          /* mm */
#define C_PLANE 2.83       /* mm/N */
#define C_NORMAL 14.5      /* mm/N */
#define FORCE_RADIUS 1.0   /* N */
#define CONTACT_NODE 61

static tf_model *forward(char *err, size_t errlen)
{
    const uint32_t dims[1] = {1};
    tf_model *m = tf_model_new("haptic_forward", TFIT_FAMILY_NODAL, GRID * GRID, dims, 1, err,
                               errlen);
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

static tf_model *contact(uint32_t p, char *err, size_t errlen)
{
    char name[32];
    snprintf(name, sizeof name, "haptic_contact_p%u", p);
    const uint32_t dims[1] = {p};
    tf_model *m = tf_model_new(name, TFIT_FAMILY_CONTACT, 1, dims, 1, err, errlen);
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

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: gen_haptic FILE.h\n");
        return 2;
    }
    char err[512];
    tf_model *models[4] = {forward(err, sizeof err), NULL, NULL, NULL};
    for (uint32_t p = 1; p <= 3 && models[p - 1] != NULL; ++p) {
        models[p] = contact(p, err, sizeof err);
    }
    int rc = 1;
    if (models[3] != NULL) {
        const tf_emit_info info = {
            .source = "synthetic block48-shaped test models (tests/firmware/gen_haptic.c)",
            .golden_seed = 48};
        rc = tf_emit_header(argv[1], models, 4, &info, err, sizeof err) != 0;
    }
    if (rc != 0) {
        fprintf(stderr, "gen_haptic: %s\n", err);
    }
    for (int i = 0; i < 4; ++i) {
        tf_model_free(models[i]);
    }
    return rc;
}
