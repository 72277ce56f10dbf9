/*
 * tfit_resonant.c — the resonant family: a body with inertia under force
 * control, one fixed-cost step per tick with caller-owned state
 * (docs/header-format.md §5.8, docs/fitting.md §8).
 *
 * coef = input map (12) | K modes {f11, f12, f21, f22, w0, w1, w2}
 *        | the static map's tables (nodal rows when r = 0, else modal A, U),
 * dims = {p, r, K, tick_ns}.
 * state = gp[3] (the previous tick's projected input) | per mode k:
 *         s[3] (position less the previous input), v[3] (velocity / omega).
 *
 * Mode k is a unit-gain damped oscillator per input axis,
 *     y'' + 2 zeta w y' + w^2 y = w^2 g,
 * in the scaled state q = (y, y'/w): q' = w [[0, 1], [-1, -2 zeta]] q + w (0, g).
 * The input is held over the tick (zero-order hold: the force of tick n
 * acts from the tick's start to its end, as the solver that trains the
 * model applies it, tf_solver_history), and the outputs are the state at
 * the tick's end.  Then the deviation q - (g, 0) decays by
 * F = exp(T w [[0, 1], [-1, -2 zeta]]) (computed by the host,
 * model/resonant.c) and one tick is, per axis i, with d = g_i - gp_i:
 *   e1 = s_i - d,  e2 = v_i
 *   s_i <- (f11 e1) + (f12 e2)                (y at the tick's end less g_i)
 *   v_i <- (f21 e1) + (f22 e2)
 *   h_i <- h_i + w_ki s_i                     (h starts at g_i)
 * and h, clamped to [-1, 1], is the static map's input: the body's static
 * response at the input as its modes have carried it.  At rest s = v = 0 and
 * h = g for any weights, so the static limit is the static map's, exactly.
 *
 * No branch on the input or the state (as tfit_prony.c): a NaN/Inf tick
 * writes its new state into a scratch copy, so the caller's keeps every
 * bit.  The clamp acts only beyond the envelope: the host fits the static
 * map on it and the histories' forces peak well inside it (docs/fitting.md
 * §8), so a strike's overshoot stays in the static map's domain; the clamp
 * keeps the static map's overflow proof (tfit_check.c) for every state.
 */
#include "tfit_internal.h"

#define MODE_FLOATS 7u

void tfit_resonant_filter(const tfit_model *m, const float g[3], uint32_t keep, float *state,
                          float h[3])
{
    float scratch[TFIT_RESONANT_MAX_STATE];
    float *dst = tfit_select_ptr(keep, state, scratch);
    const uint32_t modes = m->dims[2];
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float d0 = g[0] - state[0], d1 = g[1] - state[1], d2 = g[2] - state[2];
    float h0 = g[0], h1 = g[1], h2 = g[2];
    const float *q = state + 3;
    float *qn = dst + 3;

    for (uint32_t k = 0u; k < modes; ++k) { /* the three axes written out, as tfit_prony.c */
        const float f11 = pt[0], f12 = pt[1], f21 = pt[2], f22 = pt[3];
        const float a0 = q[0] - d0, a1 = q[1] - d1, a2 = q[2] - d2;
        const float v0 = q[3], v1 = q[4], v2 = q[5];
        const float s0 = (f11 * a0) + (f12 * v0);
        const float s1 = (f11 * a1) + (f12 * v1);
        const float s2 = (f11 * a2) + (f12 * v2);
        qn[0] = s0;
        qn[1] = s1;
        qn[2] = s2;
        qn[3] = (f21 * a0) + (f22 * v0);
        qn[4] = (f21 * a1) + (f22 * v1);
        qn[5] = (f21 * a2) + (f22 * v2);
        h0 = h0 + pt[4] * s0;
        h1 = h1 + pt[5] * s1;
        h2 = h2 + pt[6] * s2;
        pt += MODE_FLOATS;
        q += 6;
        qn += 6;
    }
    dst[0] = g[0];
    dst[1] = g[1];
    dst[2] = g[2];
    h[0] = tfit_clamp_unit(h0);
    h[1] = tfit_clamp_unit(h1);
    h[2] = tfit_clamp_unit(h2);
}

void tfit_resonant_static(const tfit_model *m, tfit_model *v)
{
    tfit_stateful_static(m, MODE_FLOATS * m->dims[2], v);
}

tfit_status tfit_resonant_reset(const tfit_model *m, float *state)
{
    if ((m == 0) | (state == 0)) {
        return TFIT_ERR_ARG;
    }
    if ((m->dims == 0) | (m->coef == 0)) {
        return TFIT_ERR_ARG;
    }
    if (m->family != TFIT_FAMILY_RESONANT) {
        return TFIT_ERR_FAMILY;
    }
    const float zero[3] = {0.0f, 0.0f, 0.0f};
    uint32_t bad;
    /* volatile: no memset call in a freestanding library (as tfit_prony.c) */
    volatile float *modes = state + 3;
    (void)tfit_input_map(m->coef, zero, state, &bad); /* the projected zero force */
    for (uint32_t w = 0u; w < 6u * m->dims[2]; ++w) {
        modes[w] = 0.0f;
    }
    return TFIT_OK;
}

tfit_status tfit_resonant_step(const tfit_model *m, float *state, const float force[3],
                               float *out)
{
    if ((m == 0) | (state == 0) | (force == 0) | (out == 0)) {
        return TFIT_ERR_ARG;
    }
    if ((m->dims == 0) | (m->coef == 0)) {
        return TFIT_ERR_ARG;
    }
    if (m->family != TFIT_FAMILY_RESONANT) {
        return TFIT_ERR_FAMILY;
    }
    float g[3], h[3];
    uint32_t bad;
    tfit_model v;
    const uint32_t clamped = tfit_input_map(m->coef, force, g, &bad);
    tfit_resonant_filter(m, g, ~bad, state, h);
    tfit_resonant_static(m, &v);
    tfit_stateful_eval(&v, h, ~bad, out);
    return (tfit_status)((int)(clamped & ~bad & 1u) - (int)(bad & 1u));
}
