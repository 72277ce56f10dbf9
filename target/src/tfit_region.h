/*
 * tfit_region.h — what the region sources share (not installed): the
 * tables' layout, the spline blends, the potential's monomials and the one
 * tick of a law (docs/header-format.md §5.10-§5.12).
 */
#ifndef TFIT_REGION_H
#define TFIT_REGION_H

#include "tfit_internal.h"

/* Layout (header-format.md §3): coef = chart (o[3], R[9]) | scalars | ...
 * law:     scalars[7] | control points (1 + T(P)) each: h, e_1 .. e_T
 * surface: scalars[8] | force map[12] | control points (r T(p) + 3 r s)
 *          each: A[r][T(p)], then (s = has_site_modes) Phi_site[3][r] |
 *          near field: per control point `near` entries {j, D[3][3]} |
 *          Phi[3 n_out][r] */
#define TFIT_REGION_CHART 12u
#define TFIT_REGION_INV_HA 0u /* scalar indices */
#define TFIT_REGION_INV_HB 1u
#define TFIT_REGION_HA 2u
#define TFIT_REGION_HB 3u
#define TFIT_REGION_SU 4u
#define TFIT_REGION_U_SCALE 5u
#define TFIT_REGION_MU 6u
#define TFIT_REGION_INV_RF 7u /* surface only */
#define TFIT_REGION_LAW_CTRL (TFIT_REGION_CHART + (uint32_t)TFIT_REGION_SCALARS)
#define TFIT_REGION_FORCE_MAP (TFIT_REGION_CHART + (uint32_t)TFIT_REGION_SURFACE_SCALARS)
#define TFIT_REGION_SURFACE_CTRL (TFIT_REGION_FORCE_MAP + TFIT_INPUT_MAP_FLOATS)

/* Floats of one near-field entry: the output point j (an integer), then
 * D (3 x 3, row-major: scene component x normalised force component). */
#define TFIT_REGION_NEAR_FLOATS 10u

/* Terms of the law's potential (degrees 2 .. P) and of the surface's
 * amplitude polynomials (degrees 1 .. p). */
#define TFIT_REGION_LAW_TERMS(P) (TFIT_TERMS(P) - 4u)
#define TFIT_REGION_SURFACE_TERMS(p) (TFIT_TERMS(p) - 1u)
#define TFIT_REGION_MAX_LAW_TERMS TFIT_REGION_LAW_TERMS((uint32_t)TFIT_REGION_MAX_DEGREE)
#define TFIT_REGION_MAX_SURFACE_TERMS                                                              \
    TFIT_REGION_SURFACE_TERMS((uint32_t)TFIT_REGION_SURFACE_MAX_DEGREE)
/* Tip coordinates beyond +-2^30 mm are clamped there (no overflow in the
 * chart map; such a tip is far off any region). */
#define TFIT_REGION_TIP_LIMIT_BITS 0x4e800000u

/* mask ? a : b for words. */
static inline uint32_t tfit_select_u(uint32_t mask, uint32_t a, uint32_t b)
{
    return (a & mask) | (b & ~mask);
}

/* The weights of a site g: B_k(ta), B_l(tb) and their derivatives, and
 * the index of control point (ia-1, jb-1). */
typedef struct tfit_region_site {
    float ba[4], da[4];
    float bb[4], db[4];
    uint32_t first;
    uint32_t row; /* nx + 2 control points per row */
} tfit_region_site;

/* x clamped onto [0, hi] (NaN and -0 to +0). */
float tfit_region_clamp(float x, float hi);
/* The cell i = min(floor(g), n - 2) of g in [0, n - 1], and *t = g - i. */
uint32_t tfit_region_cell(float g, uint32_t n, float *t);
/* The weights at the clamped grid coordinates (ga, gb); dims = {nx, ny}. */
void tfit_region_at(const uint32_t *dims, float ga, float gb, tfit_region_site *at);
/* q[i] = the blend of quantity i = 0 .. nq-1 of the control blocks of
 * `stride` floats at ctrl; _grad also its derivatives in ga and gb. */
void tfit_region_blend(const float *ctrl, uint32_t stride, const tfit_region_site *at,
                       uint32_t nq, float *q);
void tfit_region_blend_grad(const float *ctrl, uint32_t stride, const tfit_region_site *at,
                            uint32_t nq, float *q, float *qa, float *qb);

/* The monomials v_a^i v_b^j v_c^k of degrees lo .. hi in graded order
 * (header-format.md §5.10) into m. */
void tfit_region_monomials(uint32_t lo, uint32_t hi, const float v[3], float *m);
/* c_0 m_0 + c_1 m_1 + ... + c_{n-1} m_{n-1}, left to right, n >= 1. */
float tfit_region_dot(const float *c, const float *m, uint32_t n);

/* One tick of a law (§5.10), before its output and state are written. */
typedef struct tfit_region_tick {
    float force[3];  /* chart frame (+0.0f unless touching and the tip is finite) */
    float state[3];  /* the new state (the old one, bit for bit, for a NaN/Inf tip) */
    float v[3];      /* the normalised contact displacement of the returned force */
    float e2[6];     /* the potential's degree-2 coefficients at the returned proxy */
    uint32_t touch;  /* all ones when the tip touches the region */
    uint32_t bad;    /* all ones for a NaN/Inf tip */
    uint32_t status; /* the tfit_status, as a word */
} tfit_region_tick;
void tfit_region_step(const tfit_model *m, const float *state, const float tip[3],
                      tfit_region_tick *t);
/* force (chart frame) -> out (scene frame): R^T force, and-ed with keep
 * (after the rotation: the rotated zeros may be -0). */
void tfit_region_to_scene(const float *chart, const float f[3], uint32_t keep, float out[3]);

/* The amplitudes a[r] of a surface model at its normalised force f (on the
 * unit ball) and site, and-ed with keep (§5.11); and its rows first ..
 * first + count - 1 at a, and-ed with keep. */
void tfit_region_amplitudes(const tfit_model *m, const tfit_region_site *at, const float f[3],
                            uint32_t keep, float *a);
void tfit_region_rows(const tfit_model *m, const float *a, uint32_t first, uint32_t count,
                      uint32_t keep, float *out);
/* The near field's entries per control point (dims[5]; 0 for 5 dims). */
uint32_t tfit_region_near_count(const tfit_model *m);
/* out[3 (j - first) + i] += the near field of output points j in [first,
 * first + count) at the site and normalised force f, each term and-ed with
 * keep (§5.11); the entries of other points leave out unchanged, bit for
 * bit. */
void tfit_region_near(const tfit_model *m, const tfit_region_site *at, const float f[3],
                      uint32_t keep, uint32_t first, uint32_t count, float *out);
/* The clamped proxy site of a state (NaN as 0, beyond the region as its
 * edge) for a model's dims {nx, ny}. */
void tfit_region_state_site(const uint32_t *dims, const float *state, tfit_region_site *at,
                            float g[2]);

/* tfit_model_check()'s parts for the region families (tfit_region_check.c). */
uint32_t tfit_region_coefs(const tfit_model *m);
int tfit_region_range_ok(const tfit_model *m);
tfit_status tfit_region_self_test(const tfit_model *m);

#endif /* TFIT_REGION_H */
