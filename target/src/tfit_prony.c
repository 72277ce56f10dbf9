/*
 * tfit_prony.c — the prony form's filter: viscoelastic creep under force
 * control, one fixed-cost step per tick with caller-owned state
 * (docs/header-format.md §5.6), stepped by tfit_stateful.c.
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
 * selection.  The projection, the static map and the public entry points'
 * checks are the stateful forms' one stepping path (tfit_stateful.c).  The clamp only acts on rounding: with w_k >= 0 and
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

/* Terms (header-format.md §8): 0 <= a_k <= 1 - 2^-20 and |D_k| <= 2^64.
 * Then the state stays finite for every input sequence: |d_i| <= 2 (1 +
 * 2^-20) after the projection, so |z| <= (1 + 2^-24)^2 (a |z| + 2.0001 |D|)
 * at every step, whose fixed point is below 2^23 |D| <= 2^87 because
 * 1 - a (1 + 2^-24)^2 > 2^-21; h is the clamped g - sum z.  The static map
 * then sees |h_i| <= 1, as the nodal and modal proofs assume. */
int tfit_prony_terms_ok(const tfit_model *m)
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    for (uint32_t k = 0u; k < m->dims[2]; ++k) {
        const float a = pt[2u * k], dk = tfit_abs(pt[2u * k + 1u]);
        if (!(a >= 0.0f && a <= 1.0f - 0x1p-20f) || !(dk <= 0x1p64f)) {
            return 0;
        }
    }
    return 1;
}

/* A term is {a_k, D_k}; its state is z_k[3]. */
const tfit_filter tfit_filter_prony = {2u, 3u, TFIT_PRONY_MAX_TERMS};

tfit_status tfit_prony_reset(const tfit_model *m, float *state)
{
    return tfit_stateful_reset(TFIT_FAMILY_PRONY, m, state);
}

tfit_status tfit_prony_step(const tfit_model *m, float *state, const float force[3], float *out)
{
    const tfit_status refused = tfit_stateful_refuse(TFIT_FAMILY_PRONY, m, state, force, out);
    return refused != TFIT_OK ? refused : tfit_stateful_step(m, state, force, out);
}
