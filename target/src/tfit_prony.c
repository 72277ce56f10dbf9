/*
 * tfit_prony.c — the prony family: viscoelastic creep under force control,
 * one fixed-cost step per tick with caller-owned state
 * (docs/header-format.md §5.6).
 *
 * coef = input map (12) | K pairs {a_k, D_k} | the static map's tables
 * (nodal rows when r = 0, else modal A and U), dims = {p, r, K, tick_ns}.
 * state = gp[3] (the previous tick's projected input) | z[K][3].
 *
 * One tick, force f:
 *   g = projection of f (§4), bad = NaN/Inf in f
 *   d_i = g_i - gp_i                                (the input's increment)
 *   z_ki <- (a_k z_ki) + (D_k d_i)                  (every term, every axis)
 *   h_i = (((g_i - z_0i) - z_1i) - ...) clamped to [-1, 1]
 *   out = the static map at h (nodal §5.2 or modal §5.3), masked with ~bad
 *   gp <- g; unless bad: then the state is left as it was
 * Each term k is the exact first-order-hold update of e = g - x, where x
 * lags the input with time constant tau_k (tau x' = g - x), and
 * h = g - sum_k w_k e_k is the creep response g_0 g + sum_k w_k x_k with
 * g_0 = 1 - sum w_k: the relaxed (long-term) static map sees the input
 * filtered by the normalised creep function (docs/fitting.md).  The host
 * computes a_k = exp(-T/tau_k) and D_k = w_k (1 - a_k) / (T/tau_k).
 *
 * No branch on the input or the state: a NaN/Inf tick writes its new state
 * into a scratch copy instead of the caller's (a pointer selected with a
 * mask), so the caller's state keeps every bit; the clamp of h is a bitwise
 * selection.  The clamp only acts on rounding: with w_k >= 0 and
 * sum w_k <= 1 (the host fits them so) h is a weighted mean of past inputs,
 * inside the unit ball; it makes the static map's overflow proof
 * (tfit_check.c) hold for every state.
 */
#include "tfit_internal.h"

void tfit_prony_filter(const tfit_model *m, const float g[3], uint32_t keep, float *state,
                       float h[3])
{
    float scratch[TFIT_PRONY_MAX_STATE];
    float *dst = tfit_select_ptr(keep, state, scratch);
    const uint32_t terms = m->dims[2];
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float d0 = g[0] - state[0], d1 = g[1] - state[1], d2 = g[2] - state[2];
    float h0 = g[0], h1 = g[1], h2 = g[2];
    const float *z = state + 3;
    float *zn = dst + 3;

    for (uint32_t k = 0u; k < terms; ++k) {
        const float a = pt[0], dk = pt[1];
        const float z0 = a * z[0] + dk * d0;
        const float z1 = a * z[1] + dk * d1;
        const float z2 = a * z[2] + dk * d2;
        zn[0] = z0;
        zn[1] = z1;
        zn[2] = z2;
        h0 = h0 - z0;
        h1 = h1 - z1;
        h2 = h2 - z2;
        pt += 2;
        z += 3;
        zn += 3;
    }
    dst[0] = g[0];
    dst[1] = g[1];
    dst[2] = g[2];
    h[0] = tfit_clamp_unit(h0);
    h[1] = tfit_clamp_unit(h1);
    h[2] = tfit_clamp_unit(h2);
}

void tfit_prony_static(const tfit_model *m, tfit_model *v)
{
    const uint32_t skip = 2u * m->dims[2];
    v->family = m->dims[1] == 0u ? TFIT_FAMILY_NODAL : TFIT_FAMILY_MODAL;
    v->n_out = m->n_out;
    v->n_dims = m->dims[1] == 0u ? TFIT_NODAL_DIMS : TFIT_MODAL_DIMS;
    v->dims = m->dims;
    v->coef = m->coef + skip;
    v->n_coef = m->n_coef - skip;
    v->node_ids = m->node_ids;
}

/* The static map of a p = 1 model: the assembly of tfit_degree1_armv7em.c
 * on Cortex-M4F/M7, else the same operations in C. */
static void degree1_rows(const float *rows, const float h[3], uint32_t n_out, uint32_t keep,
                         float *out)
{
#if TFIT_DEGREE1_ASM
    tfit_degree1_rows_asm(rows, h, n_out, keep, out);
#else
    tfit_rows_degree1(rows, h, n_out, keep, out);
#endif
}

tfit_status tfit_prony_reset(const tfit_model *m, float *state)
{
    if ((m == 0) | (state == 0)) {
        return TFIT_ERR_ARG;
    }
    if ((m->dims == 0) | (m->coef == 0)) {
        return TFIT_ERR_ARG;
    }
    if (m->family != TFIT_FAMILY_PRONY) {
        return TFIT_ERR_FAMILY;
    }
    const float zero[3] = {0.0f, 0.0f, 0.0f};
    uint32_t bad;
    /* volatile: GCC would make the zeroing loop a call to memset, which a
     * freestanding library cannot make (check-freestanding: nm -u) */
    volatile float *terms = state + 3;
    (void)tfit_input_map(m->coef, zero, state, &bad); /* the projected zero force */
    for (uint32_t w = 0u; w < 3u * m->dims[2]; ++w) {
        terms[w] = 0.0f;
    }
    return TFIT_OK;
}

tfit_status tfit_prony_step(const tfit_model *m, float *state, const float force[3], float *out)
{
    if ((m == 0) | (state == 0) | (force == 0) | (out == 0)) {
        return TFIT_ERR_ARG;
    }
    if ((m->dims == 0) | (m->coef == 0)) {
        return TFIT_ERR_ARG;
    }
    if (m->family != TFIT_FAMILY_PRONY) {
        return TFIT_ERR_FAMILY;
    }
    float g[3], h[3];
    uint32_t bad;
    tfit_model v;
    const uint32_t clamped = tfit_input_map(m->coef, force, g, &bad);
    tfit_prony_filter(m, g, ~bad, state, h);
    tfit_prony_static(m, &v);
    if (v.family == TFIT_FAMILY_MODAL) {
        tfit_eval_modal(&v, h, ~bad, out);
    } else if (m->dims[0] != 1u) {
        tfit_eval_nodal(&v, h, ~bad, out);
    } else { /* p = 1: rows of {1, h0, h1, h2} (docs/firmware.md §5.4) */
        degree1_rows(v.coef + TFIT_INPUT_MAP_FLOATS, h, m->n_out, ~bad, out);
    }
    return (tfit_status)((int)(clamped & ~bad & 1u) - (int)(bad & 1u));
}
