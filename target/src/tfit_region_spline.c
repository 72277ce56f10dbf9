/*
 * tfit_region_spline.c — the tensor-product uniform cubic B-splines that
 * carry every per-site quantity of a region model (docs/header-format.md
 * §5.10): the cell and its local coordinate, the weights and their
 * derivatives, and the 16-point blends.
 *
 * A quantity Q is stored as control values c[j][i], i = -1 .. nx,
 * j = -1 .. ny (row-major, i fastest, each control point a block of
 * `stride` floats), and
 *   Q(g) = sum_{l=0..3} sum_{k=0..3} B_l(tb) B_k(ta) c[jb-1+l][ia-1+k]
 * with ia = min(floor(ga), nx - 2), ta = ga - ia (ga already clamped onto
 * [0, nx - 1]), the same in b.  The uniform cubic B-spline weights
 *   B0 = s^3/6, B1 = (3t^3 - 6t^2 + 4)/6, B2 = B1(s), B3 = t^3/6, s = 1 - t,
 * are >= 0 and sum to 1, so a blend of SPD matrices stays SPD and a blend
 * of convex potentials convex; the interpolant is C2 across cells.  They are
 * written in t and s = 1 - t (exact for t in [0, 1]) so that each is a
 * product of non-negative factors or a positive constant plus one:
 *   B0 = (s2 s) (1/6), B3 = (t2 t) (1/6), B1 = ((0.5 t - 1) t2) + 2/3,
 *   B2 = ((0.5 s - 1) s2) + 2/3, t2 = t t, s2 = s s;
 * their t-derivatives -(0.5 s2), (1.5 t - 2) t, -((1.5 s - 2) s), 0.5 t2.
 * A blend is w_00 c_00, then + w_lk c_lk in the order l outer, k inner
 * (no zero is added first: GCC would make a zeroing loop a memset call,
 * which a freestanding library cannot make).
 */
#include "tfit_region.h"

#define SIXTH 0x1.555556p-3f     /* 1/6 rounded to float */
#define TWO_THIRDS 0x1.555556p-1f /* 2/3 rounded to float */

/* x clamped onto [0, hi]: +0 below (and for -0 and NaN), hi above. */
float tfit_region_clamp(float x, float hi)
{
    const float lo = tfit_select(tfit_mask(x > 0.0f), x, 0.0f);
    return tfit_select(tfit_mask(lo > hi), hi, lo);
}

uint32_t tfit_region_cell(float g, uint32_t n, float *t)
{
    /* g in [0, n - 1]: the conversion truncates, which is floor here */
    const uint32_t i = tfit_umin((uint32_t)(int32_t)g, n - 2u);
    *t = g - (float)i; /* exact: g and i are within a factor of two, or i = 0 */
    return i;
}

static void weights(float t, float b[4], float d[4])
{
    const float s = 1.0f - t;
    const float t2 = t * t;
    const float s2 = s * s;
    b[0] = (s2 * s) * SIXTH;
    b[1] = ((0.5f * t - 1.0f) * t2) + TWO_THIRDS;
    b[2] = ((0.5f * s - 1.0f) * s2) + TWO_THIRDS;
    b[3] = (t2 * t) * SIXTH;
    d[0] = -(0.5f * s2);
    d[1] = (1.5f * t - 2.0f) * t;
    d[2] = -((1.5f * s - 2.0f) * s);
    d[3] = 0.5f * t2;
}

void tfit_region_at(const uint32_t *dims, float ga, float gb, tfit_region_site *at)
{
    float ta, tb, ba[4], bb[4], da[4], db[4];
    const uint32_t ia = tfit_region_cell(ga, dims[0], &ta);
    const uint32_t jb = tfit_region_cell(gb, dims[1], &tb);
    weights(ta, ba, da);
    weights(tb, bb, db);
    for (uint32_t l = 0u; l < 4u; ++l) {
        for (uint32_t k = 0u; k < 4u; ++k) {
            at->w[4u * l + k] = bb[l] * ba[k];
            at->wa[4u * l + k] = bb[l] * da[k];
            at->wb[4u * l + k] = db[l] * ba[k];
        }
    }
    at->first = jb * (dims[0] + 2u) + ia; /* control point (ia - 1, jb - 1) */
    at->row = dims[0] + 2u;
}

/* The control block of term lk = 4 l + k of the 4 x 4 neighbourhood. */
static const float *block(const float *ctrl, uint32_t stride, const tfit_region_site *at,
                          uint32_t lk)
{
    return ctrl + (at->first + (lk >> 2) * at->row + (lk & 3u)) * stride;
}

void tfit_region_blend(const float *ctrl, uint32_t stride, const tfit_region_site *at,
                       uint32_t nq, float *q)
{
    const float w0 = at->w[0];
    const float *c = block(ctrl, stride, at, 0u);
    for (uint32_t i = 0u; i < nq; ++i) {
        q[i] = w0 * c[i];
    }
    for (uint32_t lk = 1u; lk < 16u; ++lk) {
        const float w = at->w[lk];
        c = block(ctrl, stride, at, lk);
        for (uint32_t i = 0u; i < nq; ++i) {
            q[i] = q[i] + w * c[i];
        }
    }
}

void tfit_region_blend_grad(const float *ctrl, uint32_t stride, const tfit_region_site *at,
                            uint32_t nq, float *q, float *qa, float *qb)
{
    const float w0 = at->w[0], wa0 = at->wa[0], wb0 = at->wb[0];
    const float *c = block(ctrl, stride, at, 0u);
    for (uint32_t i = 0u; i < nq; ++i) {
        q[i] = w0 * c[i];
        qa[i] = wa0 * c[i];
        qb[i] = wb0 * c[i];
    }
    for (uint32_t lk = 1u; lk < 16u; ++lk) {
        const float w = at->w[lk], wa = at->wa[lk], wb = at->wb[lk];
        c = block(ctrl, stride, at, lk);
        for (uint32_t i = 0u; i < nq; ++i) {
            q[i] = q[i] + w * c[i];
            qa[i] = qa[i] + wa * c[i];
            qb[i] = qb[i] + wb * c[i];
        }
    }
}
