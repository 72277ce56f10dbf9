/*
 * tfit_resonant.c — the resonant family: a body with inertia under force
 * control, one fixed-cost step per tick with caller-owned state
 * (docs/header-format.md §5.7, docs/fitting.md §8).
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
    float d[3], hh[3];
    const float *q = state + 3;
    float *qn = dst + 3;

    for (uint32_t i = 0u; i < 3u; ++i) {
        d[i] = g[i] - state[i];
        hh[i] = g[i];
    }
    for (uint32_t k = 0u; k < modes; ++k) {
        const float f11 = pt[0], f12 = pt[1], f21 = pt[2], f22 = pt[3];
        for (uint32_t i = 0u; i < 3u; ++i) {
            const float e1 = q[i] - d[i];
            const float e2 = q[3u + i];
            const float s = (f11 * e1) + (f12 * e2);
            qn[i] = s;
            qn[3u + i] = (f21 * e1) + (f22 * e2);
            hh[i] = hh[i] + pt[4u + i] * s;
        }
        pt += MODE_FLOATS;
        q += 6;
        qn += 6;
    }
    for (uint32_t i = 0u; i < 3u; ++i) {
        dst[i] = g[i];
        h[i] = tfit_clamp_unit(hh[i]);
    }
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
