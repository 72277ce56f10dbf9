/*
 * tfit_resonant.c — the resonant form's filter: a body with inertia under
 * force control, one fixed-cost step per tick with caller-owned state
 * (docs/header-format.md §5.8, docs/fitting.md §8), stepped by
 * tfit_stateful.c.
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
 * host/model/forms/resonant.c) and one tick is, per axis i, with d = g_i - gp_i:
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

/* Modes: |f_ij| <= 1 and |w| <= 2^10.  The bound that keeps the state
 * finite is the host's: it refuses a model whose rounded F has a spectral
 * norm above 1 - 2^-20 (host/model/forms/resonant.c), so the deviation
 * (s - d, v) shrinks every tick and |s|, |v| stay below about 2^22 (|d| <= 2
 * each tick over the contraction's margin 2^-20, plus rounding); the CRC
 * makes the table the host's.  Here the magnitudes are checked again (a
 * table within them cannot overflow in one tick), and h is clamped before
 * the static map. */
int tfit_resonant_terms_ok(const tfit_model *m)
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    for (uint32_t k = 0u; k < m->dims[2]; ++k, pt += MODE_FLOATS) {
        for (uint32_t i = 0u; i < 4u; ++i) {
            if (!(tfit_abs(pt[i]) <= 1.0f)) {
                return 0;
            }
        }
        for (uint32_t i = 4u; i < MODE_FLOATS; ++i) {
            if (!(tfit_abs(pt[i]) <= 0x1p10f)) {
                return 0;
            }
        }
    }
    return 1;
}

/* A mode is {f11, f12, f21, f22, w0, w1, w2}; its state is s[3], v[3]. */
const tfit_filter tfit_filter_resonant = {MODE_FLOATS, 6u, TFIT_RESONANT_MAX_MODES};

tfit_status tfit_resonant_reset(const tfit_model *m, float *state)
{
    return tfit_stateful_reset(TFIT_FAMILY_RESONANT, m, state);
}

tfit_status tfit_resonant_step(const tfit_model *m, float *state, const float force[3], float *out)
{
    const tfit_status refused = tfit_stateful_refuse(TFIT_FAMILY_RESONANT, m, state, force, out);
    return refused != TFIT_OK ? refused : tfit_stateful_step(m, state, force, out);
}
