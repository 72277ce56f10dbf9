/*
 * tfit_region_spline.c — the tensor-product uniform cubic B-splines that
 * carry every per-site quantity of a region model (docs/header-format.md
 * §5.10): the cell and its local coordinate, the weights and their
 * derivatives, and the blends.
 *
 * A quantity Q is stored as control values c[j][i], i = -1 .. nx,
 * j = -1 .. ny (row-major, i fastest, each control point a block of
 * `stride` floats), and
 *   Q(g) = sum_{l=0..3} B_l(tb) r_l,  r_l = sum_{k=0..3} B_k(ta) c[jb-1+l][ia-1+k]
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
 * Every sum of four runs left to right from its k = 0 (l = 0) product.
 * The sums are taken row by row (the tensor product's separable form): the
 * eight weights stay in registers, and no 4 x 4 table of weight products
 * is formed (on the Cortex-M4F this took the law's tick from 11,031 to
 * 7,229 cycles, docs/firmware.md §12).
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
    float ta, tb;
    const uint32_t ia = tfit_region_cell(ga, dims[0], &ta);
    const uint32_t jb = tfit_region_cell(gb, dims[1], &tb);
    weights(ta, at->ba, at->da);
    weights(tb, at->bb, at->db);
    at->first = jb * (dims[0] + 2u) + ia; /* control point (ia - 1, jb - 1) */
    at->row = dims[0] + 2u;
}

/* sum_k w_k c[k stride], left to right */
static inline float four(float w0, float w1, float w2, float w3, const float *c, uint32_t stride)
{
    return ((w0 * c[0] + w1 * c[stride]) + w2 * c[2u * stride]) + w3 * c[3u * stride];
}

/* The weights are copied into locals: stores into q may alias the site
 * for all the compiler knows, and it would load them again for every
 * quantity. */
void tfit_region_blend(const float *ctrl, uint32_t stride, const tfit_region_site *at,
                       uint32_t nq, float *q)
{
    const float a0 = at->ba[0], a1 = at->ba[1], a2 = at->ba[2], a3 = at->ba[3];
    const float b0 = at->bb[0], b1 = at->bb[1], b2 = at->bb[2], b3 = at->bb[3];
    const uint32_t row = at->row * stride;
    const float *c = ctrl + at->first * stride;
    for (uint32_t i = 0u; i < nq; ++i, ++c) {
        const float r0 = four(a0, a1, a2, a3, c, stride);
        const float r1 = four(a0, a1, a2, a3, c + row, stride);
        const float r2 = four(a0, a1, a2, a3, c + 2u * row, stride);
        const float r3 = four(a0, a1, a2, a3, c + 3u * row, stride);
        q[i] = ((b0 * r0 + b1 * r1) + b2 * r2) + b3 * r3;
    }
}

void tfit_region_blend_grad(const float *ctrl, uint32_t stride, const tfit_region_site *at,
                            uint32_t nq, float *q, float *qa, float *qb)
{
    const float a0 = at->ba[0], a1 = at->ba[1], a2 = at->ba[2], a3 = at->ba[3];
    const float d0 = at->da[0], d1 = at->da[1], d2 = at->da[2], d3 = at->da[3];
    const float b0 = at->bb[0], b1 = at->bb[1], b2 = at->bb[2], b3 = at->bb[3];
    const float e0 = at->db[0], e1 = at->db[1], e2 = at->db[2], e3 = at->db[3];
    const uint32_t row = at->row * stride;
    const float *c = ctrl + at->first * stride;
    for (uint32_t i = 0u; i < nq; ++i, ++c) {
        const float r0 = four(a0, a1, a2, a3, c, stride);
        const float r1 = four(a0, a1, a2, a3, c + row, stride);
        const float r2 = four(a0, a1, a2, a3, c + 2u * row, stride);
        const float r3 = four(a0, a1, a2, a3, c + 3u * row, stride);
        const float s0 = four(d0, d1, d2, d3, c, stride);
        const float s1 = four(d0, d1, d2, d3, c + row, stride);
        const float s2 = four(d0, d1, d2, d3, c + 2u * row, stride);
        const float s3 = four(d0, d1, d2, d3, c + 3u * row, stride);
        q[i] = ((b0 * r0 + b1 * r1) + b2 * r2) + b3 * r3;
        qa[i] = ((b0 * s0 + b1 * s1) + b2 * s2) + b3 * s3;
        qb[i] = ((e0 * r0 + e1 * r1) + e2 * r2) + e3 * r3;
    }
}
