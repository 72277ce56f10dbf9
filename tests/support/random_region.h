/*
 * random_region.h — random region models (law and surface of one region)
 * for the bit-exact, fixed-cost and property tests: random charts (a box
 * face, or any rotation; flat or a curved height field), stiffness fields
 * that vary smoothly over the region, convex potentials of degree 2 .. 4,
 * random surface modes.  Built through host/model/region_model.c, so every
 * model passed its checks.
 */
#ifndef TF_RANDOM_REGION_H
#define TF_RANDOM_REGION_H

#include "base/context.h"
#include "base/rng.h"
#include "model/region_model.h"

typedef struct tf_random_region {
    tf_region_grid chart;
    double s_u;          /* 1 / the displacement scale, 1/mm */
    double mu;           /* friction */
    double force_radius; /* R_F, N */
    double k0[9];        /* the stiffness at the region's centre, N/mm (chart frame) */
    double variation;    /* K(g) = K0 (1 + variation w(g)), |w| <= 1 */
    double bump;         /* the height field's amplitude, mm (0: flat) */
    double phase[4];     /* of the height and stiffness fields */
    uint32_t degree;     /* P */
    double cubic, quartic; /* the potential's degree-3 and -4 weights (0 .. 1 of the
                            * largest that keeps it convex) */
    double cubic_dir[3];
    uint32_t near;       /* a surface's near-field entries per control point (p = 1; 0: none) */
} tf_random_region;

/* A random region; grid sides in [2, max_side]. */
void tf_random_region_draw(tf_rng *r, uint32_t max_side, tf_random_region *g);

/* A block-like region: a flat z+ face, its chart the scene's axes, spacing
 * h (mm) on an n x n grid, K0 diagonal {kt, kt, kn} N/mm varying by
 * +-variation, degree P, friction mu; curved: a height field of amplitude
 * `bump` mm instead of the flat face. */
void tf_random_region_block(tf_random_region *g, uint32_t n, double h, double kt, double kn,
                            double variation, double bump, uint32_t degree, double mu);

/* The law of g (name "NAME"), region index 0. */
tf_model *tf_random_region_law(tf_ctx *ctx, const tf_random_region *g, const char *name);

/* A surface for g: rank r, degree p, n_out outputs with random modes (site
 * modes when site_modes); amplitudes smooth over the region; with p = 1 and
 * g->near > 0, g->near random near-field entries per control point. */
tf_model *tf_random_region_surface(tf_ctx *ctx, tf_rng *r, const tf_random_region *g,
                                   const char *name, uint32_t rank, uint32_t degree,
                                   int site_modes, uint32_t n_out);

/* The stiffness K(g) (chart frame, N/mm) the law of g was built with, at
 * grid coordinates (ga, gb) of a control point (i, j) = (ga, gb) integers
 * from -1; and the largest eigenvalue of K over the region's controls. */
void tf_random_region_stiffness(const tf_random_region *g, double ga, double gb, double k[9]);
double tf_random_region_max_stiffness(const tf_random_region *g);

#endif /* TF_RANDOM_REGION_H */
