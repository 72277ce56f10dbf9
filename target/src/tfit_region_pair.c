/*
 * tfit_region_pair.c — two instruments on one region, with the elastic
 * coupling between their contacts (docs/header-format.md §5.12).
 *
 * Each proxy is stepped by its own law (tfit_region_step).  With K_i the
 * law's stiffness at proxy i (P = 2: the potential's Hessian in u) and u_i
 * the contact displacement of its force (u_i = v_i / s_u, so that the
 * uncoupled force is K_i u_i), the coupled forces solve
 *   u1 = K1^-1 F1 + C12 F2,   u2 = C21 F1 + K2^-1 F2,
 * C12 = Phi_site(g1) A(g2) / R_F the surface model's cross compliance (the
 * displacement at site 1 under a unit force at site 2; each instrument's
 * own compliance comes from its law).  Block elimination:
 *   F2 = (I - K2 C21 K1 C12)^-1 K2 (u2 - C21 K1 u1),  F1 = K1 (u1 - C12 F2),
 * the 3 x 3 inverse by the adjugate and one reciprocal of its determinant.
 * The coupling applies only when both instruments touch, the determinant is
 * in [2^-10, 4] (I - X has det in (0, 1] when the two-site compliance is
 * SPD) and every coupled force is within 2^64 N; otherwise each instrument
 * keeps its uncoupled force and the status says TFIT_CLAMPED.
 */
#include "tfit_region.h"

#define DET_LO 0x1p-10f
#define DET_HI 4.0f
#define FORCE_LIMIT_BITS 0x5f800000u /* 2^64 */

/* 3 x 3 matrices are 9 floats, row-major. */

static float dot3(const float a[3], const float b[3])
{
    return (a[0] * b[0] + a[1] * b[1]) + a[2] * b[2];
}

/* out = a x (out may not alias) */
static void mul_vec(const float a[9], const float x[3], float out[3])
{
    for (uint32_t i = 0u; i < 3u; ++i) {
        out[i] = dot3(a + 3u * i, x);
    }
}

/* out = a b */
static void mul_mat(const float a[9], const float b[9], float out[9])
{
    for (uint32_t i = 0u; i < 3u; ++i) {
        for (uint32_t j = 0u; j < 3u; ++j) {
            out[3u * i + j] = (a[3u * i] * b[j] + a[3u * i + 1u] * b[3u + j]) +
                              a[3u * i + 2u] * b[6u + j];
        }
    }
}

/* The law's stiffness in u from the degree-2 coefficients (as the proxy's
 * Hessian, tfit_region.c): s_u^2 [[2e1 e2 e3] [e2 2e4 e5] [e3 e5 2e6]]. */
static void stiffness(float su, const float e[6], float k[9])
{
    const float c = su * su;
    k[0] = (e[0] + e[0]) * c;
    k[1] = e[1] * c;
    k[2] = e[2] * c;
    k[4] = (e[3] + e[3]) * c;
    k[5] = e[4] * c;
    k[8] = (e[5] + e[5]) * c;
    k[3] = k[1];
    k[6] = k[2];
    k[7] = k[5];
}

/* C = Phi_site(at i) A(at j) / R_F from the blended blocks: A[r][3] first,
 * then Phi_site[3][r]; sums over the modes in order. */
static void cross(const float *bi, const float *bj, uint32_t r, float inv_rf, float c[9])
{
    const float *phi = bi + 3u * r;
    for (uint32_t i = 0u; i < 3u; ++i) {
        for (uint32_t j = 0u; j < 3u; ++j) {
            float acc = phi[i * r] * bj[j];
            for (uint32_t k = 1u; k < r; ++k) {
                acc = acc + phi[i * r + k] * bj[3u * k + j];
            }
            c[3u * i + j] = acc * inv_rf;
        }
    }
}

/* The coupled forces; returns all ones when the determinant is in range
 * and every force within 2^64. */
static uint32_t couple(const float k1[9], const float k2[9], const float c12[9],
                       const float c21[9], const float u1[3], const float u2[3], float f1[3],
                       float f2[3])
{
    float y[3], z[3], rhs[3], w[3], a[9], b[9], mm[9], cof[9];
    mul_vec(k1, u1, y);
    mul_vec(c21, y, w);
    for (uint32_t i = 0u; i < 3u; ++i) {
        z[i] = u2[i] - w[i];
    }
    mul_vec(k2, z, rhs);
    mul_mat(k1, c12, a);
    mul_mat(c21, a, b);
    mul_mat(k2, b, a);
    for (uint32_t i = 0u; i < 3u; ++i) {
        for (uint32_t j = 0u; j < 3u; ++j) {
            mm[3u * i + j] = (i == j ? 1.0f : 0.0f) - a[3u * i + j];
        }
    }
    /* cof[3 i + j]: the cofactor of M_ij, rows and columns taken cyclically */
    for (uint32_t i = 0u; i < 3u; ++i) {
        const uint32_t i1 = 3u * ((i + 1u) % 3u), i2 = 3u * ((i + 2u) % 3u);
        for (uint32_t j = 0u; j < 3u; ++j) {
            const uint32_t j1 = (j + 1u) % 3u, j2 = (j + 2u) % 3u;
            cof[3u * i + j] = mm[i1 + j1] * mm[i2 + j2] - mm[i1 + j2] * mm[i2 + j1];
        }
    }
    const float det = dot3(mm, cof);
    const uint32_t ok = tfit_mask((det >= DET_LO) & (det <= DET_HI));
    const float y0 = tfit_rsqrt(tfit_select(ok, det, 1.0f));
    const float rdet = y0 * y0;
    for (uint32_t i = 0u; i < 3u; ++i) { /* F2 = adj(M) rhs / det, adj = cof^T */
        f2[i] = ((cof[i] * rhs[0] + cof[3u + i] * rhs[1]) + cof[6u + i] * rhs[2]) * rdet;
    }
    mul_vec(c12, f2, w);
    for (uint32_t i = 0u; i < 3u; ++i) {
        z[i] = u1[i] - w[i];
    }
    mul_vec(k1, z, f1);
    uint32_t big = 0u;
    for (uint32_t i = 0u; i < 3u; ++i) {
        big = tfit_umax(big, tfit_umax(tfit_bits(f1[i]) & 0x7fffffffu,
                                       tfit_bits(f2[i]) & 0x7fffffffu));
    }
    return ok & tfit_mask(big <= FORCE_LIMIT_BITS);
}

static int pairable(const tfit_model *law, const tfit_model *surf)
{
    return law->family == TFIT_FAMILY_REGION && surf->family == TFIT_FAMILY_REGION_SURFACE &&
           law->dims[2] == 2u && surf->dims[3] == 1u && surf->dims[4] == 1u &&
           law->dims[0] == surf->dims[0] && law->dims[1] == surf->dims[1];
}

tfit_status tfit_region_pair(const tfit_model *law, const tfit_model *surf, float *state2,
                             const float tip2[6], float force2[6])
{
    if ((law == 0) | (surf == 0) | (state2 == 0) | (tip2 == 0) | (force2 == 0)) {
        return TFIT_ERR_ARG;
    }
    if ((law->dims == 0) | (law->coef == 0) | (surf->dims == 0) | (surf->coef == 0)) {
        return TFIT_ERR_ARG;
    }
    if (!pairable(law, surf)) {
        return TFIT_ERR_FAMILY;
    }
    tfit_region_tick t[2];
    float blk[2][6u * TFIT_REGION_MAX_RANK], u[2][3], g[2];
    float k[2][9], c12[9], c21[9];
    const uint32_t r = surf->dims[2], stride = 6u * r;
    const float *sc = law->coef + TFIT_REGION_CHART;
    tfit_region_site at;
    for (uint32_t i = 0u; i < 2u; ++i) {
        float *st = state2 + i * TFIT_REGION_STATE_WORDS;
        tfit_region_step(law, st, tip2 + 3u * i, &t[i]);
        for (uint32_t c = 0u; c < 3u; ++c) {
            u[i][c] = t[i].v[c] * sc[TFIT_REGION_U_SCALE];
        }
        stiffness(sc[TFIT_REGION_SU], t[i].e2, k[i]);
        tfit_region_state_site(surf->dims, t[i].state, &at, g);
        tfit_region_blend(surf->coef + TFIT_REGION_SURFACE_CTRL, stride, &at, stride, blk[i]);
    }
    const float inv_rf = surf->coef[TFIT_REGION_CHART + TFIT_REGION_INV_RF];
    cross(blk[0], blk[1], r, inv_rf, c12);
    cross(blk[1], blk[0], r, inv_rf, c21);
    float f[2][3];
    const uint32_t both = t[0].touch & t[1].touch & ~t[0].bad & ~t[1].bad;
    const uint32_t coupled = both & couple(k[0], k[1], c12, c21, u[0], u[1], f[0], f[1]);
    for (uint32_t i = 0u; i < 2u; ++i) {
        for (uint32_t c = 0u; c < 3u; ++c) {
            f[i][c] = tfit_select(coupled, f[i][c], t[i].force[c]);
        }
        tfit_region_to_scene(law->coef, f[i], t[i].touch & ~t[i].bad, force2 + 3u * i);
        for (uint32_t w = 0u; w < TFIT_REGION_STATE_WORDS; ++w) {
            state2[i * TFIT_REGION_STATE_WORDS + w] = t[i].state[w];
        }
    }
    /* -1 when either tip is bad; 2 when neither touches; 1 when either is
     * clamped or the coupling fell back; else 0 */
    const uint32_t clamped = tfit_mask((t[0].status == 1u) | (t[1].status == 1u)) |
                             (both & ~coupled);
    uint32_t st = clamped & 1u;
    st = tfit_select_u(~t[0].touch & ~t[1].touch, 2u, st);
    st = tfit_select_u(t[0].bad | t[1].bad, 0xffffffffu, st);
    return (tfit_status)(int32_t)st;
}
