/*
 * region_model.h — region models on the host (docs/header-format.md §3,
 * §5.10-§5.12): their table layout, a builder of the law and surface tables
 * from raw arrays (chart, grid, control values, modes) for the fitting side,
 * the checks tfit_model_check() will make on the device (with a message
 * naming the entry at fault) and the golden design (the self-test and the
 * golden runs are the forms', model/forms/region.c and region_surface.c).

 * The table layout: region_layout.h.
 */
#ifndef TF_REGION_MODEL_H
#define TF_REGION_MODEL_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "model/model.h"
#include "model/region_layout.h"

/* The chart and grid of a region model (spec: a height field over a plane);
 * problem/contact_region.h's tf_region_chart is the scene's chart it comes from. */
typedef struct tf_region_grid {
    double origin[3]; /* o, mm, scene frame */
    double rot[9];    /* R, rows e1, e2, n (outward), orthonormal */
    uint32_t nx, ny;  /* sites per side, >= 2 */
    double ha, hb;    /* site spacing, mm */
} tf_region_grid;

/* A law (TFIT_FAMILY_REGION, dims {nx, ny, P}): ctrl holds the
 * (nx+2)(ny+2) control blocks {h, e_1 .. e_T} (mm; the potential's
 * coefficients in N mm), s_u = 1 / the displacement scale (1/mm), mu the
 * friction coefficient; node_ids[0] = region.  The model is checked
 * (tf_region_law_validate).  NULL with the message in ctx on failure. */
tf_model *tf_region_law_new(tf_ctx *ctx, const char *name, const tf_region_grid *chart,
                            uint32_t degree, double s_u, double mu, const double *ctrl,
                            uint32_t region);

/* A surface's near field (region_surface.h): per control point n entries,
 * idx the output points, D (9 per entry, row-major: scene component x
 * chart force axis) in mm per unit normalised force f = F / R_F. */
typedef struct tf_region_near_table {
    uint32_t n;
    const uint32_t *idx;
    const double *D;
} tf_region_near_table;

/* A surface (TFIT_FAMILY_REGION_SURFACE, dims {nx, ny, r, p, site_modes,
 * near}): ctrl the control blocks {A[r][T(p) - 1], Phi_site[3][r] when
 * site_modes} (amplitudes per normalised chart-frame force f = F / R_F,
 * monomials of degrees 1 .. p), modes Phi[3 n_out][r] (mm, scene frame),
 * node_ids[n_out]; near NULL or its near field (p = 1); s_u and mu as the
 * law's (repeated so that the model stands alone). */
tf_model *tf_region_surface_new(tf_ctx *ctx, const char *name, const tf_region_grid *chart,
                                double s_u, double mu, double force_radius, uint32_t rank,
                                uint32_t degree, int site_modes, const double *ctrl,
                                const tf_region_near_table *near, const double *modes,
                                uint32_t n_out, const uint32_t *node_ids);

/* What tfit_model_check() checks of a region law and of a region surface
 * (sizes, chart, scalars, the overflow bounds of header-format.md §8), and
 * for a law that every control point's potential is convex on the unit
 * ball (the blend is then convex: the law is passive).  0, or -1 with the
 * entry named. */
int tf_region_law_validate(tf_ctx *ctx, const tf_model *m);
int tf_region_surface_validate(tf_ctx *ctx, const tf_model *m);

/* A law and a surface of one region: the same grid, chart and scalars. */
int tf_region_agree(tf_ctx *ctx, const tf_model *law, const tf_model *surf);

/* The golden design (§7): a law's tick sequence of tool-tip positions
 * (pressing, sliding, off the edge, lifting, NaN/Inf, far, huge and
 * subnormal tips); a surface's forces (the input design of golden.c over
 * its force map).  At most TF_GOLDEN_MAX (golden.h); returns the count. */
size_t tf_region_law_golden_design(const tf_model *m, uint64_t seed, float in[][3]);
size_t tf_region_surface_golden_design(const tf_model *m, uint64_t seed, float in[][3]);

/* The law's rest surface point x(g) and its normalised potential's
 * coefficients at grid coordinates g, blended in double (for designing
 * inputs and for the property tests): x in the chart frame; e[T] may be
 * NULL. */
void tf_region_rest_point(const tf_model *law, const double g[2], double x[3], double *e);

#endif /* TF_REGION_MODEL_H */
