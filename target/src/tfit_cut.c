/*
 * tfit_cut.c — the cut family (docs/header-format.md §5.7): displacements
 * as a function of (force, s), s the cut progress along the incision's path.
 *
 * coef = input map (12) | K + 1 nodal tables, knot k = 0..K at s_k = k / K,
 * each C_k[3 n_out][T] as the nodal family's (T = C(p+3, 3)).  With s
 * clamped onto [0, 1]: t = s * K, j = min(trunc(t), K - 1), w = t - j
 * (exact), and every output component
 *     a = row of C_j,  b = row of C_{j+1} (each summed as tfit_row),
 *     out = a + w * (b - a).
 * Piecewise linear in s: the displacement is not smooth in s where the cut
 * front crosses a node's support, and the knots' models are each exact in
 * the force for linear elasticity at p = 1 (docs/cutting.md compares this
 * with a polynomial in s).  The instruction stream does not depend on s:
 * only which two tables are read.
 */
#include "tfit_internal.h"

#define ABS_MASK 0x7fffffffu
#define EXP_MASK 0x7f800000u

uint32_t tfit_cut_progress(float s, uint32_t intervals, uint32_t *knot, float *w, uint32_t *bad)
{
    const uint32_t nonfinite = tfit_mask((tfit_bits(s) & ABS_MASK) >= EXP_MASK);
    const float s0 = tfit_masked(s, ~nonfinite); /* NaN/Inf -> +0 */
    const uint32_t below = tfit_mask(s0 < 0.0f);
    const float s1 = tfit_select(below, 0.0f, s0);
    const uint32_t above = tfit_mask(s1 > 1.0f);
    const float s2 = tfit_select(above, 1.0f, s1);
    const float t = s2 * (float)intervals; /* in [0, K] */
    const uint32_t i = (uint32_t)t;
    const uint32_t last = intervals - 1u;
    const uint32_t j = i ^ ((i ^ last) & tfit_mask(i > last)); /* min(i, K - 1) */
    *knot = j;
    *w = t - (float)j;
    *bad = nonfinite;
    return below | above;
}

/* p = 1: phi = {1, g0, g1, g2} with phi_k = g_{k-1} exactly, so the rows
 * are ((C0 + C1 g0) + C2 g1) + C3 g2 as tfit_rows_degree1 computes them:
 * both knots' three rows of a point side by side, six sums in flight. */
static void points_degree1(const float *a, uint32_t block, const float *g, float w, uint32_t n,
                           uint32_t keep, float *out)
{
    const float g0 = g[0], g1 = g[1], g2 = g[2];
    for (uint32_t j = 0u; j < n; ++j) {
        const float *b = a + block;
        float xa = a[0] + a[1] * g0, ya = a[4] + a[5] * g0, za = a[8] + a[9] * g0;
        float xb = b[0] + b[1] * g0, yb = b[4] + b[5] * g0, zb = b[8] + b[9] * g0;
        xa = xa + a[2] * g1;
        ya = ya + a[6] * g1;
        za = za + a[10] * g1;
        xb = xb + b[2] * g1;
        yb = yb + b[6] * g1;
        zb = zb + b[10] * g1;
        xa = xa + a[3] * g2;
        ya = ya + a[7] * g2;
        za = za + a[11] * g2;
        xb = xb + b[3] * g2;
        yb = yb + b[7] * g2;
        zb = zb + b[11] * g2;
        out[0] = tfit_masked(xa + w * (xb - xa), keep);
        out[1] = tfit_masked(ya + w * (yb - ya), keep);
        out[2] = tfit_masked(za + w * (zb - za), keep);
        a += 12;
        out += 3;
    }
}

/* Any p: per point the six rows (two knots, three components), each summed
 * left to right as tfit_row. */
static void points_any_degree(const float *a, uint32_t block, const float *phi, uint32_t n_terms,
                              float w, uint32_t n, uint32_t keep, float *out)
{
    for (uint32_t j = 0u; j < n; ++j) {
        const float *b = a + block;
        float xa = a[0], ya = a[n_terms], za = a[2u * n_terms];
        float xb = b[0], yb = b[n_terms], zb = b[2u * n_terms];
        for (uint32_t t = 1u; t < n_terms; ++t) {
            const float f = phi[t];
            xa = xa + a[t] * f;
            ya = ya + a[n_terms + t] * f;
            za = za + a[2u * n_terms + t] * f;
            xb = xb + b[t] * f;
            yb = yb + b[n_terms + t] * f;
            zb = zb + b[2u * n_terms + t] * f;
        }
        out[0] = tfit_masked(xa + w * (xb - xa), keep);
        out[1] = tfit_masked(ya + w * (yb - ya), keep);
        out[2] = tfit_masked(za + w * (zb - za), keep);
        a += 3u * n_terms;
        out += 3;
    }
}

void tfit_cut_rows(const tfit_model *m, const float *phi, uint32_t knot, float w, uint32_t first,
                   uint32_t count, uint32_t keep, float *out)
{
    const uint32_t n_terms = TFIT_TERMS(m->dims[0]);
    const uint32_t block = 3u * m->n_out * n_terms; /* one knot's table */
    const float *a = m->coef + TFIT_INPUT_MAP_FLOATS + knot * block + 3u * n_terms * first;
    if (m->dims[0] == 1u) {
        points_degree1(a, block, phi + 1, w, count, keep, out);
    } else {
        points_any_degree(a, block, phi, n_terms, w, count, keep, out);
    }
}

tfit_status tfit_displacements_cut(const tfit_model *m, const float force[3], float s, float *out)
{
    if ((m == 0) | (force == 0) | (out == 0)) {
        return TFIT_ERR_ARG;
    }
    if ((m->dims == 0) | (m->coef == 0)) {
        return TFIT_ERR_ARG;
    }
    if (m->family != TFIT_FAMILY_CUT) {
        return TFIT_ERR_FAMILY;
    }
    float g[3], w, phi[TFIT_MAX_TERMS];
    uint32_t bad, sbad, knot;
    const uint32_t clamped = tfit_input_map(m->coef, force, g, &bad);
    const uint32_t s_clamped = tfit_cut_progress(s, m->dims[1], &knot, &w, &sbad);
    bad |= sbad;
    tfit_basis(m->dims[0], g, phi);
    tfit_cut_rows(m, phi, knot, w, 0u, m->n_out, ~bad, out);
    return (tfit_status)((int)((clamped | s_clamped) & ~bad & 1u) - (int)(bad & 1u));
}
