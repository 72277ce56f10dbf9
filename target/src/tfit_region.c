/*
 * tfit_region.c — the contact law over a region (TFIT_FAMILY_REGION,
 * docs/header-format.md §5.10): the chart, the potential, the proxy's
 * Gauss-Newton step with Coulomb friction and the passivity guard, one
 * fixed-cost tick from the tool-tip position.
 *
 * coef = o[3] R[9] | 1/ha 1/hb ha hb s_u 1/s_u mu | (nx+2)(ny+2) control
 * points {h, e_1 .. e_T}; dims = {nx, ny, P}; state = {ga, gb, contact}.
 *
 * At a site g the law is a potential E(g, u) = sum_t e_t(g) m_t(v) of the
 * contact displacement u = q - x(g) (chart frame, x(g) = (ga ha, gb hb,
 * h(g)) the rest surface point), v = s_u u, m_t the monomials of degrees
 * 2 .. P; the force is its gradient F = s_u grad_v E, exactly a gradient
 * field at a fixed proxy.  Why a potential (Maxwell-Betti: the patch-
 * averaged displacement is the work-conjugate of the total force):
 * docs/header-format.md §5.10.
 *
 * The proxy g_p is where on the region the contact sits.  Each tick it
 * takes one Gauss-Newton step towards a stationary point of E over g,
 * dg = -H^-1 G (G = dE/dg through x(g) and e_t(g), H = J^T K2 J with J =
 * dx/dg and K2 the Hessian of E's quadratic part in u: SPD), limited to one
 * cell and shortened by Coulomb friction to the fraction
 * alpha = max(0, 1 - mu N / |F_t|) (N the compressive normal load, F_t the
 * tangential force): after the move the tangential force of a linear law
 * is (1 - alpha) F_t, on the friction cone's boundary.  Beyond the law's
 * envelope (|v| > 1) v is projected onto the unit ball: the force
 * saturates.  The move is kept only if it does not raise E (the passivity
 * guard, comparing both displacements shrunk by one factor onto the ball,
 * so that it holds beyond the envelope too): the energy the model
 * stores never grows by a proxy move, so it can return no more work than
 * the hand put in; with mu = 0 the proxy tracks a stationary point of E
 * over g, where the force is the gradient of min_g E(g, q - x(g)) in q
 * (envelope theorem): conservative up to the proxy's lag.
 *
 * No branch on the tip or the state: every choice is a bit mask, loops run
 * over the model's sizes only, and only the addresses of the control
 * points read depend on the input (as the cut family's knot tables do).
 */
#include "tfit_region.h"

/* The P = 2 copies of the potential below have their sizes as constants
 * only when the generic code is inlined into them. */
#if defined(__GNUC__)
#define ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define ALWAYS_INLINE inline
#endif

#define EXP_MASK 0x7f800000u
#define ABS_MASK 0x7fffffffu
#define SIGN_MASK 0x80000000u
#define BITS_ONE 0x3f800000u
#define DET_MIN 0x1p-60f    /* below it the proxy does not move */
#define TANGENT_MIN 0x1p-100f /* |F_t|^2 floor: 1/|F_t| stays finite */

/* Steps 6-9 of the input map (header-format.md §4) on v, into out: beyond
 * the unit cube a power of two brings the largest magnitude into [1, 2),
 * then outside the unit ball v / |v|.  Returns an all-ones mask when v was
 * projected, and the factor k = 2^-e y (or 1), so that out_i = v_i k
 * (rounded once either way: 2^-e is a power of two).  Kept apart from
 * tfit_input_map (tfit_input.c) so that its code, whose instructions the
 * cycle model counts, stays as it is. */
static uint32_t unit_ball(const float v[3], float out[3], float *factor)
{
    const uint32_t gmax = tfit_umax(tfit_umax(tfit_bits(v[0]) & ABS_MASK,
                                              tfit_bits(v[1]) & ABS_MASK),
                                    tfit_bits(v[2]) & ABS_MASK);
    const uint32_t far = tfit_mask(gmax > BITS_ONE);
    /* 2^(127 - E) for the biased exponent E of gmax: exact, normal here */
    const uint32_t scale = (254u - (gmax >> 23)) << 23;
    const float to_unit = tfit_float((scale & far) | (BITS_ONE & ~far));
    const float g[3] = {v[0] * to_unit, v[1] * to_unit, v[2] * to_unit};
    const float s = (g[0] * g[0] + g[1] * g[1]) + g[2] * g[2];
    const uint32_t outside = far | tfit_mask(s > 1.0f);
    const float y = tfit_select(outside, tfit_rsqrt(tfit_select(outside, s, 1.0f)), 1.0f);
    out[0] = g[0] * y;
    out[1] = g[1] * y;
    out[2] = g[2] * y;
    *factor = to_unit * y;
    return outside;
}

/* The tip coordinate clamped onto [-2^30, 2^30] (bitwise); *far is set to
 * all ones when it was beyond. */
static float clamp_tip(float x, uint32_t *far)
{
    const uint32_t b = tfit_bits(x);
    const uint32_t over = tfit_mask((b & ABS_MASK) > TFIT_REGION_TIP_LIMIT_BITS);
    *far |= over;
    return tfit_float((b & ~over) | (((b & SIGN_MASK) | TFIT_REGION_TIP_LIMIT_BITS) & over));
}

/* Row i of R d: ((R_i0 d0 + R_i1 d1) + R_i2 d2). */
static float row3(const float *r, const float d[3])
{
    return (r[0] * d[0] + r[1] * d[1]) + r[2] * d[2];
}

void tfit_region_to_scene(const float *chart, const float f[3], uint32_t keep, float out[3])
{
    const float *r = chart + 3;
    for (uint32_t j = 0u; j < 3u; ++j) {
        out[j] = tfit_masked((r[j] * f[0] + r[3u + j] * f[1]) + r[6u + j] * f[2], keep);
    }
}

/* The exponents (a, b, c) of the monomials of degrees 0 .. 4 in graded
 * order: by degree, then decreasing a, then decreasing b (the basis order
 * of §5.1); degree d starts at T(d - 1) = d (d + 1) (d + 2) / 6. */
static const uint8_t exponents[TFIT_TERMS(TFIT_REGION_MAX_DEGREE)][3] = {
    {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 0}, {1, 1, 0}, {1, 0, 1},
    {0, 2, 0}, {0, 1, 1}, {0, 0, 2}, {3, 0, 0}, {2, 1, 0}, {2, 0, 1}, {1, 2, 0},
    {1, 1, 1}, {1, 0, 2}, {0, 3, 0}, {0, 2, 1}, {0, 1, 2}, {0, 0, 3}, {4, 0, 0},
    {3, 1, 0}, {3, 0, 1}, {2, 2, 0}, {2, 1, 1}, {2, 0, 2}, {1, 3, 0}, {1, 2, 1},
    {1, 1, 2}, {1, 0, 3}, {0, 4, 0}, {0, 3, 1}, {0, 2, 2}, {0, 1, 3}, {0, 0, 4}};

/* v^n for n = 0 .. hi: 1, v, then (v^(n-1)) v. */
static ALWAYS_INLINE void powers(const float v[3], uint32_t hi,
                                 float pw[3][TFIT_REGION_MAX_DEGREE + 1])
{
    const float x = v[0], y = v[1], z = v[2];
    pw[0][0] = 1.0f;
    pw[1][0] = 1.0f;
    pw[2][0] = 1.0f;
    pw[0][1] = x;
    pw[1][1] = y;
    pw[2][1] = z;
    for (uint32_t n = 2u; n <= hi; ++n) {
        pw[0][n] = pw[0][n - 1u] * x;
        pw[1][n] = pw[1][n - 1u] * y;
        pw[2][n] = pw[2][n - 1u] * z;
    }
}

static ALWAYS_INLINE uint32_t monomials(uint32_t lo, uint32_t hi, const float v[3], float *m)
{
    float pw[3][TFIT_REGION_MAX_DEGREE + 1];
    powers(v, hi, pw);
    const uint32_t first = TFIT_TERMS(lo - 1u), n = TFIT_TERMS(hi) - first;
    uint32_t t = 0u;
    do { /* n >= 1 */
        const uint8_t *e = exponents[first + t];
        m[t] = pw[0][e[0]] * (pw[1][e[1]] * pw[2][e[2]]);
    } while (++t < n);
    return n;
}

static ALWAYS_INLINE uint32_t monomials_grad(uint32_t lo, uint32_t hi, const float v[3],
                                             float *m, float *ma, float *mb, float *mc)
{
    float pw[3][TFIT_REGION_MAX_DEGREE + 1], dp[3][TFIT_REGION_MAX_DEGREE + 1];
    powers(v, hi, pw);
    dp[0][0] = 0.0f; /* n v^(n-1) */
    dp[1][0] = 0.0f;
    dp[2][0] = 0.0f;
    dp[0][1] = 1.0f;
    dp[1][1] = 1.0f;
    dp[2][1] = 1.0f;
    for (uint32_t n = 2u; n <= hi; ++n) {
        const float fn = (float)n;
        dp[0][n] = fn * pw[0][n - 1u];
        dp[1][n] = fn * pw[1][n - 1u];
        dp[2][n] = fn * pw[2][n - 1u];
    }
    const uint32_t first = TFIT_TERMS(lo - 1u), n = TFIT_TERMS(hi) - first;
    uint32_t t = 0u;
    do { /* n >= 1 */
        const uint8_t *e = exponents[first + t];
        const float a = pw[0][e[0]], b = pw[1][e[1]], c = pw[2][e[2]];
        const float bc = b * c;
        m[t] = a * bc;
        ma[t] = dp[0][e[0]] * bc;
        mb[t] = a * (dp[1][e[1]] * c);
        mc[t] = a * (b * dp[2][e[2]]);
    } while (++t < n);
    return n;
}

static ALWAYS_INLINE float dot(const float *c, const float *m, uint32_t n)
{
    float acc = c[0] * m[0];
    for (uint32_t t = 1u; t < n; ++t) {
        acc = acc + c[t] * m[t];
    }
    return acc;
}

void tfit_region_monomials(uint32_t lo, uint32_t hi, const float v[3], float *m)
{
    (void)monomials(lo, hi, v, m);
}

float tfit_region_dot(const float *c, const float *m, uint32_t n)
{
    return dot(c, m, n);
}

/* The potential's sums at v (§5.10): the energy sum_t e_t m_t, its
 * gradient in v (sum_t e_t dm_t/dv), and sum_t ea_t m_t, sum_t eb_t m_t
 * (ea, eb: the coefficients' derivatives in g; NULL: not wanted).  Inline,
 * so that the P = 2 caller below gets it with its loops over constants. */
static ALWAYS_INLINE void potential(uint32_t P, const float *e, const float *ea,
                                    const float *eb, const float v[3], float *energy,
                                    float grad[3], float *e_a, float *e_b)
{
    float m[TFIT_REGION_MAX_LAW_TERMS], ma[TFIT_REGION_MAX_LAW_TERMS];
    float mb[TFIT_REGION_MAX_LAW_TERMS], mc[TFIT_REGION_MAX_LAW_TERMS];
    const uint32_t T = monomials_grad(2u, P, v, m, ma, mb, mc);
    *energy = dot(e, m, T);
    grad[0] = dot(e, ma, T);
    grad[1] = dot(e, mb, T);
    grad[2] = dot(e, mc, T);
    if (ea != 0) {
        *e_a = dot(ea, m, T);
        *e_b = dot(eb, m, T);
    }
}

static ALWAYS_INLINE float energy_only(uint32_t P, const float *e, const float v[3])
{
    float m[TFIT_REGION_MAX_LAW_TERMS];
    const uint32_t T = monomials(2u, P, v, m);
    return dot(e, m, T);
}

/* P = 2 (linear elasticity, the two-instrument form) written out: the
 * operations of potential() for the terms (2,0,0) (1,1,0) (1,0,1) (0,2,0)
 * (0,1,1) (0,0,2), without its products by 1 (exact: the same bits) and
 * with its products by 0 (they decide the sign of a sum that is zero).  On
 * the Cortex-M4F this halves the potential's cost (docs/firmware.md §12). */
static inline void terms_p2(const float v[3], float m[6], float ma[6], float mb[6], float mc[6])
{
    const float x = v[0], y = v[1], z = v[2];
    const float yz = y * z;
    m[0] = x * x;
    m[1] = x * y;
    m[2] = x * z;
    m[3] = y * y;
    m[4] = yz;
    m[5] = z * z;
    ma[0] = 2.0f * x;
    ma[1] = y;
    ma[2] = z;
    ma[3] = 0.0f * m[3];
    ma[4] = 0.0f * yz;
    ma[5] = 0.0f * m[5];
    mb[0] = m[0] * 0.0f;
    mb[1] = x;
    mb[2] = x * (0.0f * z);
    mb[3] = 2.0f * y;
    mb[4] = z;
    mb[5] = 0.0f * m[5];
    mc[0] = m[0] * 0.0f;
    mc[1] = x * (y * 0.0f);
    mc[2] = x;
    mc[3] = m[3] * 0.0f;
    mc[4] = y;
    mc[5] = 2.0f * z;
}

static inline float dot6(const float *c, const float m[6])
{
    return ((((c[0] * m[0] + c[1] * m[1]) + c[2] * m[2]) + c[3] * m[3]) + c[4] * m[4]) +
           c[5] * m[5];
}

static void potential_p2(const float *e, const float *ea, const float *eb, const float v[3],
                         float *energy, float grad[3], float *e_a, float *e_b)
{
    float m[6], ma[6], mb[6], mc[6];
    terms_p2(v, m, ma, mb, mc);
    *energy = dot6(e, m);
    grad[0] = dot6(e, ma);
    grad[1] = dot6(e, mb);
    grad[2] = dot6(e, mc);
    if (ea != 0) {
        *e_a = dot6(ea, m);
        *e_b = dot6(eb, m);
    }
}

static void potential_any(uint32_t P, const float *e, const float *ea, const float *eb,
                          const float v[3], float *energy, float grad[3], float *e_a, float *e_b)
{
    if (P == 2u) { /* the model's degree, not an input */
        potential_p2(e, ea, eb, v, energy, grad, e_a, e_b);
    } else {
        potential(P, e, ea, eb, v, energy, grad, e_a, e_b);
    }
}

static float energy_p2(const float *e, const float v[3])
{
    const float x = v[0], y = v[1], z = v[2];
    const float m[6] = {x * x, x * y, x * z, y * y, y * z, z * z};
    return dot6(e, m);
}

static float energy_any(uint32_t P, const float *e, const float v[3])
{
    return P == 2u ? energy_p2(e, v) : energy_only(P, e, v);
}

/* The law at one site (§5.10 step 7): the rest point x from the blended
 * height, the normalised displacement w = s_u (q - x) and v, w onto the
 * unit ball (*clamped; v = k w), the force (chart frame), and with qa, qb
 * (the quantities' derivatives in g) the sums of G.  q are the blended
 * quantities {h, e_1 .. e_T}.  Returns k. */
static float law_at(const float *sc, uint32_t P, const float qc[3], const float g[2],
                    const float *q, const float *qa, const float *qb, float w[3], float v[3],
                    uint32_t *clamped, float f[3], float *e_a, float *e_b)
{
    const float x[3] = {g[0] * sc[TFIT_REGION_HA], g[1] * sc[TFIT_REGION_HB], q[0]};
    const float su = sc[TFIT_REGION_SU];
    float k, energy, grad[3];
    for (uint32_t i = 0u; i < 3u; ++i) {
        w[i] = (qc[i] - x[i]) * su;
    }
    *clamped = unit_ball(w, v, &k);
    potential_any(P, q + 1, qa == 0 ? 0 : qa + 1, qb == 0 ? 0 : qb + 1, v, &energy, grad, e_a,
                  e_b);
    f[0] = su * grad[0];
    f[1] = su * grad[1];
    f[2] = su * grad[2];
    return k;
}

/* The energy sum_t e_t m_t(c w) of the displacement w shrunk by c (the
 * passivity guard's, §5.10 step 10). */
static float energy_at(uint32_t P, const float *e, float c, const float w[3])
{
    const float cw[3] = {c * w[0], c * w[1], c * w[2]};
    return energy_any(P, e, cw);
}

/* The Gauss-Newton step dg = -H^-1 G, H = J^T K2 J: J's columns
 * (ha, 0, h_a) and (0, hb, h_b), K2 = s_u^2 [[2e1 e2 e3] [e2 2e4 e5]
 * [e3 e5 2e6]] from the degree-2 coefficients e; by the adjugate and
 * one reciprocal of the determinant (no step when det <= 2^-60). */
static void newton_step(const float *sc, const float *e, float h_a, float h_b, const float G[2],
                        float dg[2])
{
    const float ha = sc[TFIT_REGION_HA], hb = sc[TFIT_REGION_HB];
    const float c = sc[TFIT_REGION_SU] * sc[TFIT_REGION_SU];
    const float k00 = (e[0] + e[0]) * c, k01 = e[1] * c, k02 = e[2] * c;
    const float k11 = (e[3] + e[3]) * c, k12 = e[4] * c, k22 = (e[5] + e[5]) * c;
    const float ja0 = k00 * ha + k02 * h_a; /* K2 J */
    const float ja1 = k01 * ha + k12 * h_a;
    const float ja2 = k02 * ha + k22 * h_a;
    const float jb1 = k11 * hb + k12 * h_b;
    const float jb2 = k12 * hb + k22 * h_b;
    const float haa = ha * ja0 + h_a * ja2; /* J^T K2 J */
    const float hab = hb * ja1 + h_b * ja2;
    const float hbb = hb * jb1 + h_b * jb2;
    const float det = haa * hbb - hab * hab;
    const uint32_t ok = tfit_mask(det > DET_MIN);
    const float y = tfit_rsqrt(tfit_select(ok, det, 1.0f));
    const float rdet = y * y;
    dg[0] = tfit_masked((hab * G[1] - hbb * G[0]) * rdet, ok);
    dg[1] = tfit_masked((hab * G[0] - haa * G[1]) * rdet, ok);
}

/* The slip fraction alpha = max(0, 1 - mu N / |F_t|) at the unit normal
 * of the height field, n ~ (-dh/da, -dh/db, 1); N = max(0, -F.n) is the
 * load pressing the tool into the surface (F is the force on the tissue). */
static float slip(const float *sc, float h_a, float h_b, const float f[3])
{
    const float pa = h_a * sc[TFIT_REGION_INV_HA], pb = h_b * sc[TFIT_REGION_INV_HB];
    const float rn = tfit_rsqrt((pa * pa + pb * pb) + 1.0f);
    const float n[3] = {-(pa * rn), -(pb * rn), rn};
    const float fn = (f[0] * n[0] + f[1] * n[1]) + f[2] * n[2];
    const float load = tfit_select(tfit_mask(fn < 0.0f), -fn, 0.0f);
    float ft[3];
    for (uint32_t i = 0u; i < 3u; ++i) {
        ft[i] = f[i] - fn * n[i];
    }
    float t2 = (ft[0] * ft[0] + ft[1] * ft[1]) + ft[2] * ft[2];
    t2 = tfit_select(tfit_mask(t2 > TANGENT_MIN), t2, TANGENT_MIN);
    const float alpha = 1.0f - (sc[TFIT_REGION_MU] * load) * tfit_rsqrt(t2);
    return tfit_select(tfit_mask(alpha > 0.0f), alpha, 0.0f);
}

void tfit_region_step(const tfit_model *m, const float *state, const float tip[3],
                      tfit_region_tick *t)
{
    float qs[TFIT_REGION_MAX_LAW_TERMS + 1u], qa[TFIT_REGION_MAX_LAW_TERMS + 1u];
    float qb[TFIT_REGION_MAX_LAW_TERMS + 1u], qn[TFIT_REGION_MAX_LAW_TERMS + 1u];
    tfit_region_site at;
    const float *o = m->coef, *r = m->coef + 3, *sc = m->coef + TFIT_REGION_CHART;
    const float *ctrl = m->coef + TFIT_REGION_LAW_CTRL;
    const uint32_t P = m->dims[2], S = TFIT_REGION_LAW_TERMS(P) + 1u;
    const float ga_max = (float)(m->dims[0] - 1u), gb_max = (float)(m->dims[1] - 1u);

    /* 1-2: a NaN/Inf tip is taken as 0; coordinates beyond 2^30 clamped */
    const uint32_t in_max = tfit_umax(tfit_umax(tfit_bits(tip[0]) & ABS_MASK,
                                                tfit_bits(tip[1]) & ABS_MASK),
                                      tfit_bits(tip[2]) & ABS_MASK);
    const uint32_t bad = tfit_mask(in_max >= EXP_MASK);
    uint32_t off = 0u;
    float d[3], qc[3];
    for (uint32_t i = 0u; i < 3u; ++i) {
        d[i] = clamp_tip(tfit_masked(tip[i], ~bad), &off) - o[i];
    }
    /* 3: chart coordinates q = R (p - o) */
    for (uint32_t i = 0u; i < 3u; ++i) {
        qc[i] = row3(r + 3u * i, d);
    }
    /* 4: the tip's own site, clamped onto the region (off its edge) */
    float gt[2] = {qc[0] * sc[TFIT_REGION_INV_HA], qc[1] * sc[TFIT_REGION_INV_HB]};
    off |= tfit_mask((gt[0] < 0.0f) | (gt[0] > ga_max) | (gt[1] < 0.0f) | (gt[1] > gb_max));
    gt[0] = tfit_region_clamp(gt[0], ga_max);
    gt[1] = tfit_region_clamp(gt[1], gb_max);
    /* 5: contact when the tip is below the surface there */
    float ht;
    tfit_region_at(m->dims, gt[0], gt[1], &at);
    tfit_region_blend(ctrl, S, &at, 1u, &ht);
    const uint32_t touch = tfit_mask((ht - qc[2]) > 0.0f);
    /* 6: the proxy: kept while in contact, else the tip's site */
    const uint32_t was = tfit_mask(tfit_bits(state[2]) == BITS_ONE);
    const uint32_t reset = ~(was & touch);
    const float gp[2] = {
        tfit_select(reset, gt[0], tfit_region_clamp(state[0], ga_max)),
        tfit_select(reset, gt[1], tfit_region_clamp(state[1], gb_max))};
    /* 7: the law at the proxy, with the derivatives in g */
    float w[3], v[3], f[3];
    uint32_t cl;
    tfit_region_at(m->dims, gp[0], gp[1], &at);
    tfit_region_blend_grad(ctrl, S, &at, S, qs, qa, qb);
    float e_a, e_b, unused;
    const float k = law_at(sc, P, qc, gp, qs, qa, qb, w, v, &cl, f, &e_a, &e_b);
    /* G = dE/dg = sum_t (de_t/dg) m_t - J^T F */
    const float G[2] = {e_a - (sc[TFIT_REGION_HA] * f[0] + qa[0] * f[2]),
                        e_b - (sc[TFIT_REGION_HB] * f[1] + qb[0] * f[2])};
    /* 8-9: the step, limited to one cell, shortened by friction */
    float dg[2];
    newton_step(sc, qs + 1, qa[0], qb[0], G, dg);
    const float alpha = slip(sc, qa[0], qb[0], f);
    const float gn[2] = {tfit_region_clamp(gp[0] + alpha * tfit_clamp_unit(dg[0]), ga_max),
                         tfit_region_clamp(gp[1] + alpha * tfit_clamp_unit(dg[1]), gb_max)};
    /* 10: the law there; kept only if the energy does not rise, the two
     * displacements shrunk by the same factor onto the unit ball (beyond
     * the envelope the force is the envelope's; for P = 2 this compares
     * the quadratic energies themselves, E(c w) = c^2 E(w)) */
    float wn[3], vn[3], fn[3];
    uint32_t cln;
    tfit_region_at(m->dims, gn[0], gn[1], &at);
    tfit_region_blend(ctrl, S, &at, S, qn);
    const float kn = law_at(sc, P, qc, gn, qn, 0, 0, wn, vn, &cln, fn, &unused, &unused);
    const float c = tfit_select(tfit_mask(kn < k), kn, k);
    const float energy = energy_at(P, qs + 1, c, w);
    const float energy_n = energy_at(P, qn + 1, c, wn);
    const uint32_t acc = tfit_mask(energy_n <= energy);
    const uint32_t keep = touch & ~bad;
    for (uint32_t i = 0u; i < 3u; ++i) {
        t->force[i] = tfit_masked(tfit_select(acc, fn[i], f[i]), keep);
        t->v[i] = tfit_select(acc, vn[i], v[i]);
    }
    for (uint32_t i = 0u; i < 6u; ++i) {
        t->e2[i] = tfit_select(acc, qn[1u + i], qs[1u + i]);
    }
    /* 11: the state (unchanged for a NaN/Inf tip) and the status */
    const float ns[3] = {tfit_select(touch, tfit_select(acc, gn[0], gp[0]), gt[0]),
                         tfit_select(touch, tfit_select(acc, gn[1], gp[1]), gt[1]),
                         tfit_masked(1.0f, touch)};
    for (uint32_t i = 0u; i < 3u; ++i) {
        t->state[i] = tfit_select(bad, state[i], ns[i]);
    }
    const uint32_t clamped = off | tfit_select_u(acc, cln, cl);
    uint32_t st = clamped & 1u;
    st = (st & touch) | (2u & ~touch);
    t->status = (st & ~bad) | bad; /* -1 as a word */
    t->touch = touch;
    t->bad = bad;
}

tfit_status tfit_region_reset(const tfit_model *law, float *state)
{
    if ((law == 0) | (state == 0)) {
        return TFIT_ERR_ARG;
    }
    if ((law->dims == 0) | (law->coef == 0)) {
        return TFIT_ERR_ARG;
    }
    if (law->family != TFIT_FAMILY_REGION) {
        return TFIT_ERR_FAMILY;
    }
    state[0] = 0.0f;
    state[1] = 0.0f;
    state[2] = 0.0f;
    return TFIT_OK;
}

tfit_status tfit_region_force(const tfit_model *law, float *state, const float tip[3],
                              float force[3])
{
    if ((law == 0) | (state == 0) | (tip == 0) | (force == 0)) {
        return TFIT_ERR_ARG;
    }
    if ((law->dims == 0) | (law->coef == 0)) {
        return TFIT_ERR_ARG;
    }
    if (law->family != TFIT_FAMILY_REGION) {
        return TFIT_ERR_FAMILY;
    }
    tfit_region_tick t;
    tfit_region_step(law, state, tip, &t);
    tfit_region_to_scene(law->coef, t.force, t.touch & ~t.bad, force);
    state[0] = t.state[0];
    state[1] = t.state[1];
    state[2] = t.state[2];
    return (tfit_status)(int32_t)t.status;
}
