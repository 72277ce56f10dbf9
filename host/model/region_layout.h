/*
 * region_layout.h — the table layout of the region models on the host
 * (docs/header-format.md §3), written from the header-format text (the
 * target's is in target/src/tfit_region.h):
 *   law:     o[3] R[9] | 1/ha 1/hb ha hb s_u 1/s_u mu |
 *            (nx+2)(ny+2) control points {h, e_1 .. e_T}, T = T(P) - 4
 *   surface: o[3] R[9] | the law's 7 scalars, 1/R_F | force map (x0 = 0,
 *            W = R / R_F) | (nx+2)(ny+2) control points {A[r][T(p) - 1],
 *            Phi_site[3][r] when has_site_modes} | (nx+2)(ny+2) x near
 *            entries {j, D[3][3]} (near = dims[5]) | Phi[3 n_out][r]
 * Control point (i, j), i = -1 .. nx, j = -1 .. ny, is block
 * (j + 1)(nx + 2) + (i + 1).
 */
#ifndef TF_REGION_LAYOUT_H
#define TF_REGION_LAYOUT_H

#include <stdint.h>

#include "tfit.h"

#define TF_REGION_CHART 12u
#define TF_REGION_LAW_SCALARS 7u
#define TF_REGION_SURFACE_SCALARS 8u
#define TF_REGION_LAW_CTRL (TF_REGION_CHART + TF_REGION_LAW_SCALARS)
#define TF_REGION_FORCE_MAP (TF_REGION_CHART + TF_REGION_SURFACE_SCALARS)
#define TF_REGION_SURFACE_CTRL (TF_REGION_FORCE_MAP + TFIT_INPUT_MAP_FLOATS)
#define TF_REGION_NEAR_FLOATS 10u /* a near-field entry: j, D[3][3] */
/* indices into the scalars (after the chart) */
enum { TF_REGION_INV_HA, TF_REGION_INV_HB, TF_REGION_HA, TF_REGION_HB, TF_REGION_SU,
       TF_REGION_U_SCALE, TF_REGION_MU, TF_REGION_INV_RF };

/* Terms of the law's potential (degrees 2 .. P) and of the surface's
 * amplitude polynomials (degrees 1 .. p); floats per control point. */
uint32_t tf_region_law_terms(uint32_t degree);
uint32_t tf_region_surface_terms(uint32_t degree);
uint32_t tf_region_law_stride(const uint32_t *dims);
uint32_t tf_region_surface_stride(const uint32_t *dims);
/* (nx + 2)(ny + 2) for dims {nx, ny, ...} */
uint32_t tf_region_control_points(const uint32_t *dims);

/* coef[] length of a law (dims {nx, ny, P}) and of a surface (dims {nx,
 * ny, r, p, has_site_modes, near}) with n_out outputs; 0 if invalid (the
 * count of dims is the caller's: model.c checks it against the form). */
uint32_t tf_region_law_ncoef(uint32_t n_out, const uint32_t *dims);
uint32_t tf_region_surface_ncoef(uint32_t n_out, const uint32_t *dims);
/* Where a surface's near field starts in coef[]. */
uint32_t tf_region_surface_near_at(const uint32_t *dims);

#endif /* TF_REGION_LAYOUT_H */
