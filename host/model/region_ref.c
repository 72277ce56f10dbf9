/*
 * region_ref.c — reference evaluator of the region models (region_ref.h),
 * from docs/header-format.md §5.10-§5.12: each float operation in double,
 * rounded to float immediately; selections are branches.
 */
#include "model/region_ref.h"

#include <math.h>
#include <string.h>

#include "model/ref_eval.h"
#include "model/region_layout.h"

#define MAXD 4                             /* TFIT_REGION_MAX_DEGREE */
#define MAX_LAW_T (35 - 4)                 /* T(4) - 4 */
#define MAX_SURF_T (20 - 1)                /* T(3) - 1 */

/* --- float arithmetic, one rounding per operation -------------------------- */
static float add(float a, float b)
{
    return (float)((double)a + (double)b);
}

static float sub(float a, float b)
{
    return (float)((double)a - (double)b);
}

static float mul(float a, float b)
{
    return (float)((double)a * (double)b);
}

static uint32_t bits(float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static float from_bits(uint32_t u)
{
    float x;
    memcpy(&x, &u, sizeof x);
    return x;
}

/* §4 step 8: 1/sqrt(s) from 0x5f3759df - (bits(s) >> 1) and three Newton
 * steps t = (s y) y, t = 3 - t, y = (0.5 y) t. */
static float rsqrt(float s)
{
    float y = from_bits(0x5f3759dfu - (bits(s) >> 1));
    for (int i = 0; i < 3; ++i) {
        float t = mul(mul(s, y), y);
        t = sub(3.0f, t);
        y = mul(mul(0.5f, y), t);
    }
    return y;
}

/* §4 steps 6-9 on v: a power of two brings the largest magnitude into
 * [1, 2) when it is above 1; outside the unit ball, v / |v|.  *factor is
 * that power of two times the 1/|v| factor (or 1). */
static int onto_ball(const float v[3], float out[3], float *factor)
{
    float g[3] = {v[0], v[1], v[2]}, big = 0.0f;
    for (int i = 0; i < 3; ++i) {
        big = fabsf(g[i]) > big ? fabsf(g[i]) : big;
    }
    const int far = big > 1.0f;
    const float unit = far ? ldexpf(1.0f, -(int)((bits(big) >> 23) - 127u)) : 1.0f;
    for (int i = 0; i < 3; ++i) {
        g[i] = mul(g[i], unit);
    }
    const float s = add(add(mul(g[0], g[0]), mul(g[1], g[1])), mul(g[2], g[2]));
    const int outside = far || s > 1.0f;
    const float y = outside ? rsqrt(s) : 1.0f;
    for (int i = 0; i < 3; ++i) {
        out[i] = mul(g[i], y);
    }
    *factor = mul(unit, y);
    return outside;
}

static float clamp_grid(float x, float hi)
{
    const float lo = x > 0.0f ? x : 0.0f;
    return lo > hi ? hi : lo;
}

/* --- the splines (§5.10 "Splines") ---------------------------------------- */
typedef struct site {
    float b[2][4], d[2][4]; /* B_k and dB_k/dt in a (0) and b (1) */
    size_t first, row;
} site;

static void spline_weights(float t, float b[4], float d[4])
{
    const float sixth = 0x1.555556p-3f, two_thirds = 0x1.555556p-1f;
    const float s = sub(1.0f, t), t2 = mul(t, t), s2 = mul(s, s);
    b[0] = mul(mul(s2, s), sixth);
    b[1] = add(mul(sub(mul(0.5f, t), 1.0f), t2), two_thirds);
    b[2] = add(mul(sub(mul(0.5f, s), 1.0f), s2), two_thirds);
    b[3] = mul(mul(t2, t), sixth);
    d[0] = -mul(0.5f, s2);
    d[1] = mul(sub(mul(1.5f, t), 2.0f), t);
    d[2] = -mul(sub(mul(1.5f, s), 2.0f), s);
    d[3] = mul(0.5f, t2);
}

/* g clamped onto the grid already */
static void site_at(const uint32_t *dims, float ga, float gb, site *st)
{
    uint32_t cell[2];
    const float g[2] = {ga, gb};
    for (int a = 0; a < 2; ++a) {
        uint32_t i = (uint32_t)floorf(g[a]);
        if (i > dims[a] - 2) {
            i = dims[a] - 2;
        }
        cell[a] = i;
        spline_weights(sub(g[a], (float)i), st->b[a], st->d[a]);
    }
    st->row = dims[0] + 2;
    st->first = (size_t)cell[1] * st->row + cell[0];
}

/* ((w0 x0 + w1 x1) + w2 x2) + w3 x3 */
static float sum4(const float w[4], const float x[4])
{
    return add(add(add(mul(w[0], x[0]), mul(w[1], x[1])), mul(w[2], x[2])), mul(w[3], x[3]));
}

/* Quantity q of the control blocks (stride floats each): the rows' sums
 * in a with the weights wa, then their sum in b with wb (§5.10). */
static float blend(const float *ctrl, size_t stride, const site *st, const float wa[4],
                   const float wb[4], size_t q)
{
    float r[4];
    for (int l = 0; l < 4; ++l) {
        float c[4];
        for (int k = 0; k < 4; ++k) {
            c[k] = ctrl[(st->first + (size_t)l * st->row + (size_t)k) * stride + q];
        }
        r[l] = sum4(wa, c);
    }
    return sum4(wb, r);
}

/* --- the potential (§5.10 "Potential") ------------------------------------ */
/* Monomials of degrees lo .. hi at v, graded order (decreasing exponent of
 * v_a, then of v_b); when grad is not NULL their partial derivatives too. */
static int monomials(int lo, int hi, const float v[3], float *m, float (*grad)[3])
{
    float pw[3][MAXD + 1], dp[3][MAXD + 1];
    for (int c = 0; c < 3; ++c) {
        pw[c][0] = 1.0f;
        pw[c][1] = v[c];
        dp[c][0] = 0.0f;
        dp[c][1] = 1.0f;
        for (int n = 2; n <= hi; ++n) {
            pw[c][n] = mul(pw[c][n - 1], v[c]);
            dp[c][n] = mul((float)n, pw[c][n - 1]);
        }
    }
    int t = 0;
    for (int deg = lo; deg <= hi; ++deg) {
        for (int i = deg; i >= 0; --i) {
            for (int j = deg - i; j >= 0; --j, ++t) {
                const int k = deg - i - j;
                const float bc = mul(pw[1][j], pw[2][k]);
                m[t] = mul(pw[0][i], bc);
                if (grad != NULL) {
                    grad[t][0] = mul(dp[0][i], bc);
                    grad[t][1] = mul(pw[0][i], mul(dp[1][j], pw[2][k]));
                    grad[t][2] = mul(pw[0][i], mul(pw[1][j], dp[2][k]));
                }
            }
        }
    }
    return t;
}

/* sum_t c_t x_t left to right, starting from c_0 x_0; x with stride. */
static float series(const float *c, const float *x, size_t stride, int n)
{
    float acc = mul(c[0], x[0]);
    for (int t = 1; t < n; ++t) {
        acc = add(acc, mul(c[t], x[(size_t)t * stride]));
    }
    return acc;
}

/* --- the law (§5.10 "One tick") ------------------------------------------- */
typedef struct law_site {
    float q[MAX_LAW_T + 1]; /* h, e_1 .. e_T */
    float w[3], v[3], factor, f[3];
    int clamped;
    float mono[MAX_LAW_T];
} law_site;

/* w = s_u (q - x), v = w onto the unit ball, the monomials at v and the
 * force s_u grad E(v). */
static void law_eval(const tf_model *m, const float qc[3], float ga, float gb, law_site *ls)
{
    const float *sc = m->coef + TF_REGION_CHART;
    const int P = (int)m->dims[2], T = (int)tf_region_law_terms(m->dims[2]);
    float grad[MAX_LAW_T][3];
    const float x[3] = {mul(ga, sc[TF_REGION_HA]), mul(gb, sc[TF_REGION_HB]), ls->q[0]};
    for (int i = 0; i < 3; ++i) {
        ls->w[i] = mul(sub(qc[i], x[i]), sc[TF_REGION_SU]);
    }
    ls->clamped = onto_ball(ls->w, ls->v, &ls->factor);
    monomials(2, P, ls->v, ls->mono, grad);
    for (int c = 0; c < 3; ++c) {
        ls->f[c] = mul(sc[TF_REGION_SU], series(ls->q + 1, &grad[0][c], 3, T));
    }
}

/* The guard's energy: E at c w. */
static float guard_energy(const tf_model *m, const law_site *ls, float c)
{
    float cw[3], mono[MAX_LAW_T];
    for (int i = 0; i < 3; ++i) {
        cw[i] = mul(c, ls->w[i]);
    }
    const int T = monomials(2, (int)m->dims[2], cw, mono, NULL);
    return series(ls->q + 1, mono, 1, T);
}

typedef struct law_tick {
    float force[3]; /* chart frame */
    float state[3];
    float v[3];
    float e2[6];
    int touch, bad, status;
} law_tick;

static float tip_clamp(float x, int *far)
{
    if (fabsf(x) > 0x1p30f) {
        *far = 1;
        return x < 0.0f ? -0x1p30f : 0x1p30f;
    }
    return x;
}

static void law_step(const tf_model *m, const float *state, const float tip[3], law_tick *t)
{
    const float *o = m->coef, *rot = m->coef + 3, *sc = m->coef + TF_REGION_CHART;
    const float *ctrl = m->coef + TF_REGION_LAW_CTRL;
    const uint32_t *dims = m->dims;
    const size_t S = tf_region_law_stride(dims);
    const int T = (int)S - 1;
    const float ga_max = (float)(dims[0] - 1), gb_max = (float)(dims[1] - 1);
    site st;

    /* the tip: NaN/Inf anywhere -> 0; beyond 2^30 clamped */
    t->bad = !(isfinite(tip[0]) && isfinite(tip[1]) && isfinite(tip[2]));
    int off = 0;
    float d[3], qc[3];
    for (int i = 0; i < 3; ++i) {
        d[i] = sub(tip_clamp(t->bad ? 0.0f : tip[i], &off), o[i]);
    }
    for (int i = 0; i < 3; ++i) {
        qc[i] = add(add(mul(rot[3 * i], d[0]), mul(rot[3 * i + 1], d[1])),
                    mul(rot[3 * i + 2], d[2]));
    }
    /* the tip's site */
    float gt[2] = {mul(qc[0], sc[TF_REGION_INV_HA]), mul(qc[1], sc[TF_REGION_INV_HB])};
    if (gt[0] < 0.0f || gt[0] > ga_max || gt[1] < 0.0f || gt[1] > gb_max) {
        off = 1;
    }
    gt[0] = clamp_grid(gt[0], ga_max);
    gt[1] = clamp_grid(gt[1], gb_max);
    site_at(dims, gt[0], gt[1], &st);
    const float ht = blend(ctrl, S, &st, st.b[0], st.b[1], 0);
    t->touch = sub(ht, qc[2]) > 0.0f;
    /* the proxy */
    const int was = bits(state[2]) == bits(1.0f);
    float gp[2];
    if (was && t->touch) {
        gp[0] = clamp_grid(state[0], ga_max);
        gp[1] = clamp_grid(state[1], gb_max);
    } else {
        gp[0] = gt[0];
        gp[1] = gt[1];
    }
    /* the law at the proxy and its derivatives in g */
    law_site at_p, at_n;
    float qa[MAX_LAW_T + 1], qb[MAX_LAW_T + 1];
    site_at(dims, gp[0], gp[1], &st);
    for (size_t q = 0; q < S; ++q) {
        at_p.q[q] = blend(ctrl, S, &st, st.b[0], st.b[1], q);
        qa[q] = blend(ctrl, S, &st, st.d[0], st.b[1], q);
        qb[q] = blend(ctrl, S, &st, st.b[0], st.d[1], q);
    }
    law_eval(m, qc, gp[0], gp[1], &at_p);
    const float *f = at_p.f;
    const float ha = sc[TF_REGION_HA], hb = sc[TF_REGION_HB];
    const float G0 = sub(series(qa + 1, at_p.mono, 1, T), add(mul(ha, f[0]), mul(qa[0], f[2])));
    const float G1 = sub(series(qb + 1, at_p.mono, 1, T), add(mul(hb, f[1]), mul(qb[0], f[2])));
    /* Gauss-Newton: H = J^T K2 J */
    const float *e = at_p.q + 1;
    const float c = mul(sc[TF_REGION_SU], sc[TF_REGION_SU]);
    const float k00 = mul(add(e[0], e[0]), c), k01 = mul(e[1], c), k02 = mul(e[2], c);
    const float k11 = mul(add(e[3], e[3]), c), k12 = mul(e[4], c), k22 = mul(add(e[5], e[5]), c);
    const float h_a = qa[0], h_b = qb[0];
    const float ja0 = add(mul(k00, ha), mul(k02, h_a));
    const float ja1 = add(mul(k01, ha), mul(k12, h_a));
    const float ja2 = add(mul(k02, ha), mul(k22, h_a));
    const float jb1 = add(mul(k11, hb), mul(k12, h_b));
    const float jb2 = add(mul(k12, hb), mul(k22, h_b));
    const float haa = add(mul(ha, ja0), mul(h_a, ja2));
    const float hab = add(mul(hb, ja1), mul(h_b, ja2));
    const float hbb = add(mul(hb, jb1), mul(h_b, jb2));
    const float det = sub(mul(haa, hbb), mul(hab, hab));
    float dg[2] = {0.0f, 0.0f};
    if (det > 0x1p-60f) {
        const float y = rsqrt(det), rdet = mul(y, y);
        dg[0] = mul(sub(mul(hab, G1), mul(hbb, G0)), rdet);
        dg[1] = mul(sub(mul(hab, G0), mul(haa, G1)), rdet);
    }
    /* Coulomb: the slip fraction at the surface normal */
    const float pa = mul(h_a, sc[TF_REGION_INV_HA]), pb = mul(h_b, sc[TF_REGION_INV_HB]);
    const float rn = rsqrt(add(add(mul(pa, pa), mul(pb, pb)), 1.0f));
    const float n[3] = {-mul(pa, rn), -mul(pb, rn), rn};
    const float fn = add(add(mul(f[0], n[0]), mul(f[1], n[1])), mul(f[2], n[2]));
    const float load = fn < 0.0f ? -fn : 0.0f;
    float ft[3];
    for (int i = 0; i < 3; ++i) {
        ft[i] = sub(f[i], mul(fn, n[i]));
    }
    float t2 = add(add(mul(ft[0], ft[0]), mul(ft[1], ft[1])), mul(ft[2], ft[2]));
    if (!(t2 > 0x1p-100f)) {
        t2 = 0x1p-100f;
    }
    float alpha = sub(1.0f, mul(mul(sc[TF_REGION_MU], load), rsqrt(t2)));
    if (!(alpha > 0.0f)) {
        alpha = 0.0f;
    }
    /* the candidate: one cell at most, on the grid */
    float gn[2];
    const float gmax[2] = {ga_max, gb_max};
    for (int a = 0; a < 2; ++a) {
        const float step = fabsf(dg[a]) > 1.0f ? copysignf(1.0f, dg[a]) : dg[a];
        gn[a] = clamp_grid(add(gp[a], mul(alpha, step)), gmax[a]);
    }
    site_at(dims, gn[0], gn[1], &st);
    for (size_t q = 0; q < S; ++q) {
        at_n.q[q] = blend(ctrl, S, &st, st.b[0], st.b[1], q);
    }
    law_eval(m, qc, gn[0], gn[1], &at_n);
    const float shrink = at_n.factor < at_p.factor ? at_n.factor : at_p.factor;
    const int accept = guard_energy(m, &at_n, shrink) <= guard_energy(m, &at_p, shrink);
    const law_site *fin = accept ? &at_n : &at_p;
    const int keep = t->touch && !t->bad;
    for (int i = 0; i < 3; ++i) {
        t->force[i] = keep ? fin->f[i] : 0.0f;
        t->v[i] = fin->v[i];
    }
    memcpy(t->e2, fin->q + 1, sizeof t->e2);
    /* the state and the status */
    if (t->bad) {
        memcpy(t->state, state, sizeof t->state);
    } else if (t->touch) {
        t->state[0] = accept ? gn[0] : gp[0];
        t->state[1] = accept ? gn[1] : gp[1];
        t->state[2] = 1.0f;
    } else {
        t->state[0] = gt[0];
        t->state[1] = gt[1];
        t->state[2] = 0.0f;
    }
    t->status = t->bad ? TFIT_ERR_INPUT
                : !t->touch ? TFIT_NO_CONTACT
                : (off || fin->clamped) ? TFIT_CLAMPED
                : TFIT_OK;
}

/* R^T f, or +0 when not kept */
static void to_scene(const tf_model *m, const float f[3], int keep, float out[3])
{
    const float *rot = m->coef + 3;
    for (int j = 0; j < 3; ++j) {
        const float v = add(add(mul(rot[j], f[0]), mul(rot[3 + j], f[1])), mul(rot[6 + j], f[2]));
        out[j] = keep ? v : 0.0f;
    }
}

void tf_region_ref_reset(float *state)
{
    state[0] = state[1] = state[2] = 0.0f;
}

tfit_status tf_region_ref_force(const tf_model *law, float *state, const float tip[3],
                                float force[3])
{
    law_tick t;
    law_step(law, state, tip, &t);
    to_scene(law, t.force, t.touch && !t.bad, force);
    memcpy(state, t.state, sizeof t.state);
    return (tfit_status)t.status;
}

/* --- the surface (§5.11) ---------------------------------------------------- */
/* f: §4 with the force map; the site of the state; the amplitudes. */
static void amplitudes(const tf_model *m, const float *state, const float force[3], float *a,
                       int *clamped, int *bad, float f[3], site *at)
{
    tf_model map = *m; /* a view whose input map is the force map */
    map.coef = m->coef + TF_REGION_FORCE_MAP;
    float phi[MAX_SURF_T];
    tf_ref_input(&map, force, f, clamped, bad, NULL);
    const uint32_t r = m->dims[2];
    const size_t stride = tf_region_surface_stride(m->dims);
    const int n_t = (int)tf_region_surface_terms(m->dims[3]);
    site st;
    site_at(m->dims, clamp_grid(state[0], (float)(m->dims[0] - 1)),
            clamp_grid(state[1], (float)(m->dims[1] - 1)), &st);
    *at = st;
    monomials(1, (int)m->dims[3], f, phi, NULL);
    const float *ctrl = m->coef + TF_REGION_SURFACE_CTRL;
    for (uint32_t k = 0; k < r; ++k) {
        float coef[MAX_SURF_T] = {0};
        for (int t = 0; t < n_t; ++t) {
            coef[t] = blend(ctrl, stride, &st, st.b[0], st.b[1],
                            (size_t)k * (size_t)n_t + (size_t)t);
        }
        a[k] = *bad ? 0.0f : series(coef, phi, 1, n_t);
    }
}

/* out_j += w (D f) for the near entries {j, D} of the site's 16 control
 * points, w = B_l(tb) B_k(ta) (§5.11): ((D_i0 f0 + D_i1 f1) + D_i2 f2)
 * times w, added term by term in the control points' order (l, then k)
 * and the entries'. */
static void near_field(const tf_model *m, const site *st, const float f[3], int keep, float *out)
{
    const uint32_t n = m->dims[5];
    const float *table = m->coef + tf_region_surface_near_at(m->dims);
    for (size_t l = 0; l < 4; ++l) {
        for (size_t k = 0; k < 4; ++k) {
            const float w = mul(st->b[1][l], st->b[0][k]);
            const float *e = table + (st->first + l * st->row + k) * n * TF_REGION_NEAR_FLOATS;
            for (uint32_t q = 0; q < n; ++q, e += TF_REGION_NEAR_FLOATS) {
                const size_t j = (size_t)e[0];
                for (size_t i = 0; i < 3; ++i) {
                    const float *d = e + 1 + 3 * i;
                    const float v =
                        mul(w, add(add(mul(d[0], f[0]), mul(d[1], f[1])), mul(d[2], f[2])));
                    out[3 * j + i] = add(out[3 * j + i], keep ? v : 0.0f);
                }
            }
        }
    }
}

static void rows(const tf_model *m, const float *a, int keep, float *out)
{
    const uint32_t r = m->dims[2];
    const float *u = m->coef + (m->n_coef - 3 * r * m->n_out);
    for (size_t o = 0; o < 3 * (size_t)m->n_out; ++o) {
        const float v = series(u + o * r, a, 1, (int)r);
        out[o] = keep ? v : 0.0f;
    }
}

tfit_status tf_region_ref_surface(const tf_model *surf, const float *state, const float force[3],
                                  float *out)
{
    float a[TFIT_REGION_MAX_RANK], f[3];
    int clamped, bad;
    site st;
    amplitudes(surf, state, force, a, &clamped, &bad, f, &st);
    rows(surf, a, !bad, out);
    near_field(surf, &st, f, !bad, out);
    return bad ? TFIT_ERR_INPUT : clamped ? TFIT_CLAMPED : TFIT_OK;
}

tfit_status tf_region_ref_surface_pair(const tf_model *surf, const float *state2,
                                       const float force2[6], float *out)
{
    if (surf->dims[3] != 1) {
        return TFIT_ERR_FAMILY;
    }
    float a[TFIT_REGION_MAX_RANK], b[TFIT_REGION_MAX_RANK], f1[3], f2[3];
    int cl1, bad1, cl2, bad2;
    site st1, st2;
    amplitudes(surf, state2, force2, a, &cl1, &bad1, f1, &st1);
    amplitudes(surf, state2 + 3, force2 + 3, b, &cl2, &bad2, f2, &st2);
    for (uint32_t k = 0; k < surf->dims[2]; ++k) {
        a[k] = (bad1 || bad2) ? 0.0f : add(a[k], b[k]);
    }
    rows(surf, a, !(bad1 || bad2), out);
    near_field(surf, &st1, f1, !(bad1 || bad2), out);
    near_field(surf, &st2, f2, !(bad1 || bad2), out);
    return (bad1 || bad2) ? TFIT_ERR_INPUT : (cl1 || cl2) ? TFIT_CLAMPED : TFIT_OK;
}

/* --- two instruments (§5.12) -------------------------------------------------- */
static float dot3(const float *a, const float *b)
{
    return add(add(mul(a[0], b[0]), mul(a[1], b[1])), mul(a[2], b[2]));
}

static void mat_vec(const float a[9], const float x[3], float y[3])
{
    for (int i = 0; i < 3; ++i) {
        y[i] = dot3(a + 3 * i, x);
    }
}

static void mat_mat(const float a[9], const float b[9], float c[9])
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const float col[3] = {b[j], b[3 + j], b[6 + j]};
            c[3 * i + j] = dot3(a + 3 * i, col);
        }
    }
}

static void stiffness(float su, const float e[6], float k[9])
{
    const float c = mul(su, su);
    const float d0 = mul(add(e[0], e[0]), c), d1 = mul(add(e[3], e[3]), c);
    const float d2 = mul(add(e[5], e[5]), c);
    const float kk[9] = {d0, mul(e[1], c), mul(e[2], c), mul(e[1], c), d1, mul(e[4], c),
                         mul(e[2], c), mul(e[4], c), d2};
    memcpy(k, kk, sizeof kk);
}

/* Phi_site(g_i) A(g_j) / R_F from the blended blocks {A[r][3], Phi_site[3][r]} */
static void cross(const float *bi, const float *bj, uint32_t r, float inv_rf, float c[9])
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            c[3 * i + j] = mul(series(bi + 3 * r + (size_t)i * r, bj + j, 3, (int)r), inv_rf);
        }
    }
}

tfit_status tf_region_ref_pair(const tf_model *law, const tf_model *surf, float *state2,
                               const float tip2[6], float force2[6])
{
    if (law->dims[2] != 2 || surf->dims[3] != 1 || surf->dims[4] != 1 ||
        law->dims[0] != surf->dims[0] || law->dims[1] != surf->dims[1]) {
        return TFIT_ERR_FAMILY;
    }
    const float *sc = law->coef + TF_REGION_CHART;
    const uint32_t r = surf->dims[2];
    const size_t stride = tf_region_surface_stride(surf->dims);
    law_tick t[2];
    float blk[2][6 * TFIT_REGION_MAX_RANK], u[2][3], k[2][9];
    for (int i = 0; i < 2; ++i) {
        law_step(law, state2 + 3 * i, tip2 + 3 * i, &t[i]);
        for (int c = 0; c < 3; ++c) {
            u[i][c] = mul(t[i].v[c], sc[TF_REGION_U_SCALE]);
        }
        stiffness(sc[TF_REGION_SU], t[i].e2, k[i]);
        site st;
        site_at(surf->dims, clamp_grid(t[i].state[0], (float)(surf->dims[0] - 1)),
                clamp_grid(t[i].state[1], (float)(surf->dims[1] - 1)), &st);
        for (size_t q = 0; q < stride; ++q) {
            blk[i][q] = blend(surf->coef + TF_REGION_SURFACE_CTRL, stride, &st, st.b[0], st.b[1],
                              q);
        }
    }
    const float inv_rf = surf->coef[TF_REGION_CHART + TF_REGION_INV_RF];
    float c12[9], c21[9];
    cross(blk[0], blk[1], r, inv_rf, c12);
    cross(blk[1], blk[0], r, inv_rf, c21);
    /* F2 = (I - K2 C21 K1 C12)^-1 K2 (u2 - C21 K1 u1), F1 = K1 (u1 - C12 F2) */
    float y[3], w[3], z[3], rhs[3], a[9], b[9], mm[9], f1[3], f2[3];
    mat_vec(k[0], u[0], y);
    mat_vec(c21, y, w);
    for (int i = 0; i < 3; ++i) {
        z[i] = sub(u[1][i], w[i]);
    }
    mat_vec(k[1], z, rhs);
    mat_mat(k[0], c12, a);
    mat_mat(c21, a, b);
    mat_mat(k[1], b, a);
    for (int i = 0; i < 9; ++i) {
        mm[i] = sub(i % 4 == 0 ? 1.0f : 0.0f, a[i]);
    }
    float cof[9];
    for (int i = 0; i < 3; ++i) {
        const int i1 = 3 * ((i + 1) % 3), i2 = 3 * ((i + 2) % 3);
        for (int j = 0; j < 3; ++j) {
            const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            cof[3 * i + j] = sub(mul(mm[i1 + j1], mm[i2 + j2]), mul(mm[i1 + j2], mm[i2 + j1]));
        }
    }
    const float det = dot3(mm, cof);
    const int ok = det >= 0x1p-10f && det <= 4.0f;
    const float yd = rsqrt(ok ? det : 1.0f), rdet = mul(yd, yd);
    for (int i = 0; i < 3; ++i) {
        const float col[3] = {cof[i], cof[3 + i], cof[6 + i]};
        f2[i] = mul(dot3(col, rhs), rdet);
    }
    mat_vec(c12, f2, w);
    for (int i = 0; i < 3; ++i) {
        z[i] = sub(u[0][i], w[i]);
    }
    mat_vec(k[0], z, f1);
    int within = 1;
    for (int i = 0; i < 3; ++i) {
        within = within && fabsf(f1[i]) <= 0x1p64f && fabsf(f2[i]) <= 0x1p64f;
    }
    const int both = t[0].touch && t[1].touch && !t[0].bad && !t[1].bad;
    const int coupled = both && ok && within;
    const float *fc[2] = {f1, f2};
    for (int i = 0; i < 2; ++i) {
        to_scene(law, coupled ? fc[i] : t[i].force, t[i].touch && !t[i].bad, force2 + 3 * i);
        memcpy(state2 + 3 * i, t[i].state, sizeof t[i].state);
    }
    if (t[0].bad || t[1].bad) {
        return TFIT_ERR_INPUT;
    }
    if (!t[0].touch && !t[1].touch) {
        return TFIT_NO_CONTACT;
    }
    return (t[0].status == TFIT_CLAMPED || t[1].status == TFIT_CLAMPED || (both && !coupled))
               ? TFIT_CLAMPED
               : TFIT_OK;
}

/* --- golden vectors (§7) ------------------------------------------------------- */
void tf_region_ref_golden_state(const tf_model *surf, uint32_t v, float state[3])
{
    static const uint32_t frac[16] = TFIT_CUT_GOLDEN_S_BITS;
    state[0] = mul(from_bits(frac[v % 16]), (float)(surf->dims[0] - 1));
    state[1] = mul(from_bits(frac[(7 * v + 3) % 16]), (float)(surf->dims[1] - 1));
    state[2] = 1.0f;
}
