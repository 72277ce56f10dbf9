/*
 * tfit_region_check.c — tfit_model_check()'s parts for the region families
 * (docs/header-format.md §3, §8): the table size, the proof that no tick
 * can overflow float, and the self-test.
 *
 * The overflow proof of a law.  The tip is clamped to |p_i| <= 2^30, the
 * chart to |o_i| <= 2^20 and |R_ij| <= 1 + 2^-10, the grid scalars to
 * [2^-20, 2^20], so |q_i| < 2^32, |u_i| < 2^33 and v = s_u u is finite
 * before §4's projection puts it on the unit ball.  The spline weights are
 * >= 0 and sum to 1 (to rounding), their derivatives' magnitudes to at most
 * 1.5, so a blended quantity and its derivatives are bounded by
 * 2 max |c| over the control points.  With Bh = 2 max |h|, Be = 2 sum_t
 * max |e_t|: |E| <= Be, |grad_v E| <= P Be, |F| <= Fb = s_u P Be,
 * J's entries <= Jb = max(ha, hb, Bh), K2's <= Kb = 2 s_u^2 Be, H's
 * <= Hb = 9 Jb^2 Kb, G's <= Gb = Be + 2 Jb Fb.  The check requires
 * Bh <= 2^30, Be <= 2^60, Fb <= 2^60, Hb <= 2^50 and Hb Gb <= 2^59: then
 * det <= 2^101 (its reciprocal is taken only above 2^-60, so it is at most
 * 2^60), the step's numerator <= 2^60 and the step <= 2^120 before it is
 * limited to one cell; |dh/da| <= 2^50, so the normal's squared norm stays
 * below 2^102, |F_t|^2 <= 12 Fb^2 < 2^124 and mu N / |F_t| < 2^122 (|F_t|^2
 * is floored at 2^-100).  Every bound is computed in float here; NaN or Inf
 * in one fails the check.
 *
 * A surface: its force map as §4's input map (|x0| <= 2^64, |W| <= 2^56),
 * |phi_t| <= 1 on the unit ball, so |a_k| <= Ba_k = 2 sum_t max |A_kt| and
 * every output <= sum_k |Phi_ok| Ba_k, required <= 2^100 as the modal
 * family's; Phi_site's entries <= 2^100 and 1/R_F in [2^-40, 2^40]; the
 * near field's entries as near_ok states (an output stays below 2^101).  The
 * pair's coupled forces are checked at run time (tfit_region_pair.c).
 */
#include "tfit_region.h"

#define BOUND_LIMIT 0x1p100f

static float fabs_(float x)
{
    return tfit_float(tfit_bits(x) & 0x7fffffffu);
}

static int within(float b, float limit)
{
    return b <= limit; /* false for NaN */
}

static int between(float x, float lo, float hi)
{
    return x >= lo && x <= hi; /* false for NaN */
}

uint32_t tfit_region_coefs(const tfit_model *m)
{
    const uint32_t *d = m->dims;
    const uint32_t want = m->family == TFIT_FAMILY_REGION ? (uint32_t)TFIT_REGION_DIMS
                                                          : (uint32_t)TFIT_REGION_SURFACE_DIMS;
    /* a surface of 5 dims: one without a near field */
    const uint32_t older = m->family == TFIT_FAMILY_REGION ? want : want - 1u;
    if ((m->n_dims != want && m->n_dims != older) || d[0] < 2u || d[0] > TFIT_REGION_MAX_GRID || d[1] < 2u ||
        d[1] > TFIT_REGION_MAX_GRID) {
        return 0u;
    }
    const uint32_t points = (d[0] + 2u) * (d[1] + 2u);
    if (m->family == TFIT_FAMILY_REGION) {
        if (m->n_out != 1u || d[2] < 2u || d[2] > TFIT_REGION_MAX_DEGREE) {
            return 0u;
        }
        return TFIT_REGION_LAW_CTRL + points * (1u + TFIT_REGION_LAW_TERMS(d[2]));
    }
    const uint32_t r = d[2], p = d[3], near = tfit_region_near_count(m);
    if (r == 0u || r > TFIT_REGION_MAX_RANK || p == 0u || p > TFIT_REGION_SURFACE_MAX_DEGREE ||
        d[4] > 1u || near > TFIT_REGION_MAX_NEAR || (near != 0u && p != 1u)) {
        return 0u;
    }
    const uint64_t n = (uint64_t)points * (r * TFIT_REGION_SURFACE_TERMS(p) + 3u * r * d[4] +
                                           near * TFIT_REGION_NEAR_FLOATS) +
                       3ULL * m->n_out * r + TFIT_REGION_SURFACE_CTRL;
    return n > 0xffffffffu ? 0u : (uint32_t)n;
}

/* |o_i| <= 2^20, |R_ij| <= 1 + 2^-10; the grid and law scalars. */
static int chart_ok(const float *c)
{
    for (uint32_t i = 0u; i < 3u; ++i) {
        if (!within(fabs_(c[i]), 0x1p20f)) {
            return 0;
        }
    }
    for (uint32_t i = 3u; i < TFIT_REGION_CHART; ++i) {
        if (!within(fabs_(c[i]), 1.0f + 0x1p-10f)) {
            return 0;
        }
    }
    const float *sc = c + TFIT_REGION_CHART;
    for (uint32_t i = 0u; i < TFIT_REGION_MU; ++i) {
        if (!between(sc[i], 0x1p-20f, 0x1p20f)) {
            return 0;
        }
    }
    return between(sc[TFIT_REGION_MU], 0.0f, 0x1p10f);
}

/* max over the control points of |c[i]|, each block `stride` floats. */
static float max_abs(const float *c, uint32_t points, uint32_t stride)
{
    float b = 0.0f;
    for (uint32_t j = 0u; j < points; ++j) {
        const float a = fabs_(c[j * stride]);
        b = a > b ? a : b;
    }
    return b;
}

static int law_ok(const tfit_model *m)
{
    const uint32_t points = (m->dims[0] + 2u) * (m->dims[1] + 2u);
    const uint32_t P = m->dims[2], T = TFIT_REGION_LAW_TERMS(P);
    const float *sc = m->coef + TFIT_REGION_CHART;
    const float *ctrl = m->coef + TFIT_REGION_LAW_CTRL;
    const float bh = 2.0f * max_abs(ctrl, points, T + 1u);
    float esum = 0.0f;
    for (uint32_t t = 1u; t <= T; ++t) {
        esum = esum + max_abs(ctrl + t, points, T + 1u);
    }
    const float be = 2.0f * esum;
    const float su = sc[TFIT_REGION_SU];
    float jb = sc[TFIT_REGION_HA] > sc[TFIT_REGION_HB] ? sc[TFIT_REGION_HA] : sc[TFIT_REGION_HB];
    jb = bh > jb ? bh : jb;
    const float fb = (su * (float)P) * be;
    const float kb = 2.0f * (su * su) * be;
    const float hb = 9.0f * (jb * jb) * kb;
    const float gb = be + 2.0f * jb * fb;
    return within(bh, 0x1p30f) && within(be, 0x1p60f) && within(fb, 0x1p60f) &&
           within(hb, 0x1p50f) && within(gb, BOUND_LIMIT) && within(hb * gb, 0x1p59f);
}

/* The near field's entries: j an integer in [0, n_out), |D_il| <= 2^80,
 * so that the 16 control points' near terms add at most 16 x 32 x 3 x
 * 2^80 < 2^91 to an output (|f_l| <= 1, the weights <= 1). */
static int near_ok(const tfit_model *m, const float *table)
{
    const uint32_t count = (m->dims[0] + 2u) * (m->dims[1] + 2u) * tfit_region_near_count(m);
    int ok = 1;
    for (uint32_t e = 0u; e < count; ++e) {
        const float *entry = &table[e * TFIT_REGION_NEAR_FLOATS];
        /* the conversion is defined for an entry in range only (||: not evaluated else) */
        if (!between(entry[0], 0.0f, (float)(m->n_out - 1u)) ||
            ((float)(uint32_t)entry[0] != entry[0])) {
            ok = 0;
        }
        for (uint32_t i = 1u; i < TFIT_REGION_NEAR_FLOATS; ++i) {
            if (!within(fabs_(entry[i]), 0x1p80f)) {
                ok = 0;
            }
        }
    }
    return ok;
}

static int surface_ok(const tfit_model *m)
{
    const uint32_t points = (m->dims[0] + 2u) * (m->dims[1] + 2u);
    const uint32_t r = m->dims[2], n_t = TFIT_REGION_SURFACE_TERMS(m->dims[3]);
    const uint32_t stride = r * n_t + 3u * r * m->dims[4];
    const float *map = m->coef + TFIT_REGION_FORCE_MAP;
    const float *ctrl = m->coef + TFIT_REGION_SURFACE_CTRL;
    const float *phi = m->coef + (m->n_coef - 3u * r * m->n_out);
    float ba[TFIT_REGION_MAX_RANK];
    if (!between(m->coef[TFIT_REGION_CHART + TFIT_REGION_INV_RF], 0x1p-40f, 0x1p40f)) {
        return 0;
    }
    for (uint32_t i = 0u; i < TFIT_INPUT_MAP_FLOATS; ++i) {
        if (!within(fabs_(map[i]), i < 3u ? 0x1p64f : 0x1p56f)) {
            return 0;
        }
    }
    for (uint32_t k = 0u; k < r; ++k) {
        float s = 0.0f;
        for (uint32_t t = 0u; t < n_t; ++t) {
            s = s + max_abs(ctrl + k * n_t + t, points, stride);
        }
        ba[k] = 2.0f * s;
        if (!within(ba[k], BOUND_LIMIT)) {
            return 0;
        }
    }
    for (uint32_t i = r * n_t; i < stride; ++i) { /* Phi_site */
        if (!within(max_abs(ctrl + i, points, stride), BOUND_LIMIT)) {
            return 0;
        }
    }
    return tfit_modes_bounded(phi, ba, r, 3u * m->n_out) && near_ok(m, ctrl + points * stride);
}

int tfit_region_range_ok(const tfit_model *m)
{
    if (!chart_ok(m->coef)) {
        return 0;
    }
    return m->family == TFIT_FAMILY_REGION ? law_ok(m) : surface_ok(m);
}

/* One law tick folded into the CRC: the status, the new state, the force
 * (scene frame). */
static uint32_t law_tick(const tfit_model *m, float st[3], const float tip[3], uint32_t crc)
{
    tfit_region_tick t;
    float f[3];
    tfit_region_step(m, st, tip, &t);
    tfit_region_to_scene(m->coef, t.force, t.touch & ~t.bad, f);
    crc = tfit_crc32_word(crc, t.status);
    for (uint32_t i = 0u; i < 3u; ++i) {
        st[i] = t.state[i];
        crc = tfit_crc32_word(crc, tfit_bits(st[i]));
    }
    for (uint32_t i = 0u; i < 3u; ++i) {
        crc = tfit_crc32_word(crc, tfit_bits(f[i]));
    }
    return crc;
}

/* A law's self-test: the 8 inputs as ticks from a reset state; then 64
 * ticks at check input 1 plus the far inputs times 2^-100 (exact: offsets
 * of +-1 mm in steps of 2^-23, generated as tfit_check.c's). */
static tfit_status law_self_test(const tfit_model *m)
{
    float st[3] = {0.0f, 0.0f, 0.0f}, in[3];
    uint32_t crc = 0xffffffffu, far = 0xffffffffu, lcg = 1u;
    for (uint32_t k = 0u; k < (uint32_t)TFIT_CHECK_INPUTS; ++k) {
        for (uint32_t i = 0u; i < 3u; ++i) {
            in[i] = tfit_float(m->check[3u * k + i]);
        }
        crc = law_tick(m, st, in, crc);
    }
    for (uint32_t k = 0u; k < (uint32_t)TFIT_CHECK_FAR; ++k) {
        lcg = tfit_far_input(lcg, in);
        for (uint32_t i = 0u; i < 3u; ++i) {
            in[i] = tfit_float(m->check[3u + i]) + in[i] * 0x1p-100f;
        }
        far = law_tick(m, st, in, far);
    }
    const uint32_t *want = m->check + 3u * TFIT_CHECK_INPUTS;
    return ((crc ^ 0xffffffffu) == want[0] && (far ^ 0xffffffffu) == want[1]) ? TFIT_OK
                                                                              : TFIT_ERR_ARITH;
}

/* A surface's self-test: input k at the proxy site of golden vector k
 * (tfit_golden.c), the outputs point by point (no 3 n_out buffer); then
 * the far inputs through the force map, as the other families' (§8). */
static tfit_status surface_self_test(const tfit_model *m)
{
    static const uint32_t frac[16] = TFIT_CUT_GOLDEN_S_BITS;
    const float *map = m->coef + TFIT_REGION_FORCE_MAP;
    float in[3], f[3], g[2], out[3], a[TFIT_REGION_MAX_RANK];
    uint32_t bad, crc = 0xffffffffu, far = 0xffffffffu, lcg = 1u;
    tfit_region_site at;
    for (uint32_t k = 0u; k < (uint32_t)TFIT_CHECK_INPUTS; ++k) {
        const float st[3] = {tfit_float(frac[k & 15u]) * (float)(m->dims[0] - 1u),
                             tfit_float(frac[(7u * k + 3u) & 15u]) * (float)(m->dims[1] - 1u),
                             1.0f};
        for (uint32_t i = 0u; i < 3u; ++i) {
            in[i] = tfit_float(m->check[3u * k + i]);
        }
        const uint32_t clamped = tfit_input_map(map, in, f, &bad);
        crc = tfit_crc32_word(crc, (clamped & ~bad & 1u) - (bad & 1u));
        tfit_region_state_site(m->dims, st, &at, g);
        tfit_region_amplitudes(m, &at, f, ~bad, a);
        const uint32_t near = tfit_region_near_count(m);
        for (uint32_t j = 0u; j < m->n_out; ++j) {
            tfit_region_rows(m, a, j, 1u, ~bad, out);
            if (near != 0u) {
                tfit_region_near(m, &at, f, ~bad, j, 1u, out);
            }
            for (uint32_t i = 0u; i < 3u; ++i) {
                crc = tfit_crc32_word(crc, tfit_bits(out[i]));
            }
        }
    }
    for (uint32_t k = 0u; k < (uint32_t)TFIT_CHECK_FAR; ++k) {
        lcg = tfit_far_input(lcg, in);
        (void)tfit_input_map(map, in, f, &bad);
        for (uint32_t i = 0u; i < 3u; ++i) {
            far = tfit_crc32_word(far, tfit_bits(f[i]));
        }
    }
    const uint32_t *want = m->check + 3u * TFIT_CHECK_INPUTS;
    return ((crc ^ 0xffffffffu) == want[0] && (far ^ 0xffffffffu) == want[1]) ? TFIT_OK
                                                                              : TFIT_ERR_ARITH;
}

tfit_status tfit_region_self_test(const tfit_model *m)
{
    return m->family == TFIT_FAMILY_REGION ? law_self_test(m) : surface_self_test(m);
}
