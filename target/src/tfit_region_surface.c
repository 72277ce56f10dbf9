/*
 * tfit_region_surface.c — the surface for the current contact of a region
 * (TFIT_FAMILY_REGION_SURFACE, docs/header-format.md §5.11).
 *
 * coef = o[3] R[9] | the law's 7 scalars, 1/R_F | force map (12: x0 = 0,
 * W = R / R_F) | (nx+2)(ny+2) control points {A[r][T], Phi_site[3][r] when
 * has_site_modes} | (nx+2)(ny+2) x near entries {j, D[3][3]} |
 * Phi[3 n_out][r]; dims = {nx, ny, r, p, has_site_modes, near}.
 *
 *   f = the force map's projection of the force (§4): the chart-frame force
 *       over the envelope radius R_F, on the unit ball
 *   a_k = sum_t A_kt(g) phi_t(f), phi_t the monomials of degrees 1 .. p,
 *       A_kt(g) blended by the splines at the state's proxy site g
 *   out = Phi a (the modes shared by every site; rank r)
 *       + sum over the cell's 16 control points c of B(g)_c D_cj f for
 *         each of c's near entries {j, D_cj} (the near field: the peak
 *         under the probe, which the shared modes do not follow)
 * Memory grows with r and with the control points times the outputs near
 * one, not with sites x outputs.  Phi_site(g) (3 x r) are
 * the modes' patch-averaged values at the site: Phi_site(g1) A(g2) / R_F is
 * the compliance that couples two instruments (tfit_region_pair.c).
 */
#include "tfit_region.h"

void tfit_region_state_site(const uint32_t *dims, const float *state, tfit_region_site *at,
                            float g[2])
{
    g[0] = tfit_region_clamp(state[0], (float)(dims[0] - 1u));
    g[1] = tfit_region_clamp(state[1], (float)(dims[1] - 1u));
    tfit_region_at(dims, g[0], g[1], at);
}

void tfit_region_amplitudes(const tfit_model *m, const tfit_region_site *at, const float f[3],
                            uint32_t keep, float *a)
{
    float phi[TFIT_REGION_MAX_SURFACE_TERMS], coef[TFIT_REGION_MAX_SURFACE_TERMS];
    const uint32_t r = m->dims[2], p = m->dims[3];
    const uint32_t n_t = TFIT_REGION_SURFACE_TERMS(p);
    const uint32_t stride = r * n_t + 3u * r * m->dims[4];
    const float *ctrl = m->coef + TFIT_REGION_SURFACE_CTRL;
    tfit_region_monomials(1u, p, f, phi);
    for (uint32_t k = 0u; k < r; ++k) {
        tfit_region_blend(ctrl + k * n_t, stride, at, n_t, coef);
        a[k] = tfit_masked(tfit_region_dot(coef, phi, n_t), keep);
    }
}

uint32_t tfit_region_near_count(const tfit_model *m)
{
    return m->n_dims > 5u ? m->dims[5] : 0u;
}

/* The near field (§5.11): for the 16 control points of the site's cell,
 * weight w = B_l(tb) B_k(ta), and each of their `near` entries {j, D},
 * out_j += w (D f), term by term.  The entries of points outside the
 * window are added to nothing (their sums are discarded by a mask, not a
 * branch: every call runs the same instructions). */
void tfit_region_near(const tfit_model *m, const tfit_region_site *at, const float f[3],
                      uint32_t keep, uint32_t first, uint32_t count, float *out)
{
    const uint32_t n = tfit_region_near_count(m);
    const uint32_t points = (m->dims[0] + 2u) * (m->dims[1] + 2u);
    const uint32_t stride = m->dims[2] * TFIT_REGION_SURFACE_TERMS(m->dims[3]) +
                            3u * m->dims[2] * m->dims[4];
    const float *table = &m->coef[TFIT_REGION_SURFACE_CTRL + (points * stride)];
    for (uint32_t l = 0u; l < 4u; ++l) {
        for (uint32_t k = 0u; k < 4u; ++k) {
            const float w = at->bb[l] * at->ba[k];
            const uint32_t block = (at->first + (l * at->row) + k) * n;
            for (uint32_t q = 0u; q < n; ++q) {
                const float *e = &table[(block + q) * TFIT_REGION_NEAR_FLOATS];
                const uint32_t j = (uint32_t)e[0] - first;
                const uint32_t in = tfit_mask(j < count);
                const uint32_t o = 3u * (j & in);
                for (uint32_t i = 0u; i < 3u; ++i) {
                    const uint32_t d = 1u + (3u * i);
                    const float v = w * (((e[d] * f[0]) + (e[d + 1u] * f[1])) + (e[d + 2u] * f[2]));
                    out[o + i] = tfit_select(in, out[o + i] + tfit_masked(v, keep), out[o + i]);
                }
            }
        }
    }
}

/* The modes end the table: output point j's rows are found from the end,
 * so that a view holding fewer points (the self-test's) finds them too.
 * The rows are the modal family's (§5.3): on Cortex-M4F/M7 ranks 1 .. 8 in
 * its assembly (tfit_modal_armv7em.c), whose zero rows need the amplitudes
 * masked with keep as well (they are: tfit_region_amplitudes). */
void tfit_region_rows(const tfit_model *m, const float *a, uint32_t first, uint32_t count,
                      uint32_t keep, float *out)
{
    const uint32_t r = m->dims[2];
    const float *u = m->coef + (m->n_coef - 3u * r * m->n_out) + 3u * r * first;
#if TFIT_DEGREE1_ASM
    if (r <= TFIT_MODAL_ASM_MAX_RANK) {
        tfit_modal_rows_asm(r, u, a, count, keep, out);
        return;
    }
#endif
    tfit_modal_rows_c(u, a, r, count, keep, out);
}

static tfit_status arguments(const tfit_model *m, const void *state, const float *force,
                             const float *out)
{
    if ((m == 0) | (state == 0) | (force == 0) | (out == 0)) {
        return TFIT_ERR_ARG;
    }
    if ((m->dims == 0) | (m->coef == 0)) {
        return TFIT_ERR_ARG;
    }
    return m->family == TFIT_FAMILY_REGION_SURFACE ? TFIT_OK : TFIT_ERR_FAMILY;
}

/* -1 for a NaN/Inf force, else 1 when it was projected, else 0. */
static tfit_status status_of(uint32_t clamped, uint32_t bad)
{
    return (tfit_status)((int)(clamped & ~bad & 1u) - (int)(bad & 1u));
}

tfit_status tfit_region_surface(const tfit_model *surf, const float *state, const float force[3],
                                float *out)
{
    const tfit_status s = arguments(surf, state, force, out);
    if (s != TFIT_OK) {
        return s;
    }
    float f[3], g[2], a[TFIT_REGION_MAX_RANK];
    uint32_t bad;
    tfit_region_site at;
    const uint32_t clamped = tfit_input_map(surf->coef + TFIT_REGION_FORCE_MAP, force, f, &bad);
    tfit_region_state_site(surf->dims, state, &at, g);
    tfit_region_amplitudes(surf, &at, f, ~bad, a);
    tfit_region_rows(surf, a, 0u, surf->n_out, ~bad, out);
    if (tfit_region_near_count(surf) != 0u) { /* the model's shape, not the input */
        tfit_region_near(surf, &at, f, ~bad, 0u, surf->n_out, out);
    }
    return status_of(clamped, bad);
}

tfit_status tfit_region_surface_pair(const tfit_model *surf, const float *state2,
                                     const float force2[6], float *out)
{
    const tfit_status s = arguments(surf, state2, force2, out);
    if (s != TFIT_OK) {
        return s;
    }
    if (surf->dims[3] != 1u) { /* superposition holds for affine models only */
        return TFIT_ERR_FAMILY;
    }
    float f[3], f2[3], g[2], a[TFIT_REGION_MAX_RANK], b[TFIT_REGION_MAX_RANK];
    uint32_t bad, bad2;
    tfit_region_site at, at2;
    uint32_t clamped = tfit_input_map(surf->coef + TFIT_REGION_FORCE_MAP, force2, f, &bad);
    tfit_region_state_site(surf->dims, state2, &at, g);
    tfit_region_amplitudes(surf, &at, f, ~bad, a);
    clamped |= tfit_input_map(surf->coef + TFIT_REGION_FORCE_MAP, force2 + 3, f2, &bad2);
    tfit_region_state_site(surf->dims, state2 + TFIT_REGION_STATE_WORDS, &at2, g);
    tfit_region_amplitudes(surf, &at2, f2, ~bad2, b);
    for (uint32_t k = 0u; k < surf->dims[2]; ++k) { /* masked: the rows' assembly needs it */
        a[k] = tfit_masked(a[k] + b[k], ~(bad | bad2));
    }
    tfit_region_rows(surf, a, 0u, surf->n_out, ~(bad | bad2), out);
    if (tfit_region_near_count(surf) != 0u) {
        tfit_region_near(surf, &at, f, ~(bad | bad2), 0u, surf->n_out, out);
        tfit_region_near(surf, &at2, f2, ~(bad | bad2), 0u, surf->n_out, out);
    }
    return status_of(clamped, bad | bad2);
}
