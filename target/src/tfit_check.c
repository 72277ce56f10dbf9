/*
 * tfit_check.c — tfit_model_check(): version, family, sizes, CRC-32, and a
 * proof that evaluation cannot overflow.
 *
 * The overflow proof: after the envelope projection every |g_i| <= 1 (to a
 * few ulps), so every Chebyshev term |T_a T_b T_c| is <= 1 and every output
 * is bounded by sums of absolute coefficients.  zhou2017's surface
 * coefficients are Chebyshev series in t_a, |t_a| <= tau (tau >= 1): there
 * |T_k(t)| <= T_k(tau) <= (2 tau)^k and Clenshaw's b_k are sums of
 * c_j U_{j-k}(t), |U_m(t)| <= (2 tau)^m, so sum |c_k| (2 tau)^k bounds the
 * result and every intermediate.  The check computes those bounds (in float; any
 * overflow or NaN in them fails the check) and requires them below 2^100,
 * far enough under FLT_MAX (2^128) that rounding cannot matter.  With no Inf
 * reachable, no NaN is reachable either (no 0*Inf, Inf-Inf; divisors >= 1).
 */
#include "tfit_internal.h"

#define BOUND_LIMIT 0x1p100f
#define X0_LIMIT 0x1p64f
#define W_LIMIT 0x1p56f

static float fabs_(float x)
{
    return tfit_float(tfit_bits(x) & 0x7fffffffu);
}

static int within(float b, float limit)
{
    return b <= limit; /* false for NaN */
}

static float abs_sum(const float *c, uint32_t n)
{
    float s = 0.0f;
    for (uint32_t i = 0u; i < n; ++i) {
        s = s + fabs_(c[i]);
    }
    return s;
}

/* sum_k |c_k| tau^k (Horner on the magnitudes), tau >= 1. */
static float abs_poly(const float *c, uint32_t n, float tau)
{
    float s = fabs_(c[n]);
    for (uint32_t i = n; i > 0u; --i) {
        s = s * tau + fabs_(c[i - 1u]);
    }
    return s;
}

static int map_ok(const float *map)
{
    for (uint32_t i = 0u; i < 3u; ++i) {
        if (!within(fabs_(map[i]), X0_LIMIT)) {
            return 0;
        }
    }
    for (uint32_t i = 3u; i < TFIT_INPUT_MAP_FLOATS; ++i) {
        if (!within(fabs_(map[i]), W_LIMIT)) {
            return 0;
        }
    }
    return 1;
}

static int nodal_ok(const tfit_model *m)
{
    const uint32_t n_terms = TFIT_TERMS(m->dims[0]);
    const float *c = m->coef + TFIT_INPUT_MAP_FLOATS;
    for (uint32_t o = 0u; o < 3u * m->n_out; ++o) {
        if (!within(abs_sum(c + o * n_terms, n_terms), BOUND_LIMIT)) {
            return 0;
        }
    }
    return 1;
}

static int modal_ok(const tfit_model *m)
{
    float amax[TFIT_MAX_RANK];
    const uint32_t n_terms = TFIT_TERMS(m->dims[0]);
    const uint32_t r = m->dims[1];
    const float *amp = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *modes = amp + r * n_terms;
    for (uint32_t k = 0u; k < r; ++k) {
        amax[k] = abs_sum(amp + k * n_terms, n_terms);
        if (!within(amax[k], BOUND_LIMIT)) {
            return 0;
        }
    }
    for (uint32_t o = 0u; o < 3u * m->n_out; ++o) {
        float b = 0.0f;
        for (uint32_t k = 0u; k < r; ++k) {
            b = b + fabs_(modes[o * r + k]) * amax[k];
        }
        if (!within(b, BOUND_LIMIT)) {
            return 0;
        }
    }
    return 1;
}

static int zhou2017_ok(const tfit_model *m)
{
    const uint32_t *dm = m->dims;
    const float *c = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *xy = m->coef + (m->n_coef - 2u * m->n_out);
    float tau[3];
    float comp_bound[3] = {0.0f, 0.0f, 0.0f};

    for (uint32_t j = 0u; j < 2u * m->n_out; ++j) {
        if (!within(fabs_(xy[j]), 1.0f)) {
            return 0;
        }
    }
    for (uint32_t a = 0u; a < 3u; ++a) {
        float d = abs_sum(c, dm[a] + 1u);
        c += dm[a] + 1u;
        float t = d * fabs_(c[0]);
        c += 1;
        if (!within(d, BOUND_LIMIT) || !within(t, BOUND_LIMIT)) {
            return 0;
        }
        tau[a] = 2.0f * (t > 1.0f ? t : 1.0f); /* (2 tau)^k bounds T_k and U_k */
    }
    for (uint32_t a = 0u; a < 3u; ++a) {
        for (uint32_t comp = 0u; comp < 3u; ++comp) {
            const uint32_t *o = dm + 3u + 3u * (3u * a + comp);
            const uint32_t rows = o[0] + o[1] + 1u;
            float surface = 0.0f;
            for (uint32_t i = 0u; i < rows; ++i) {
                surface = surface + abs_poly(c + i * (o[2] + 1u), o[2], tau[a]);
            }
            c += rows * (o[2] + 1u);
            comp_bound[comp] = comp_bound[comp] + surface;
        }
    }
    for (uint32_t comp = 0u; comp < 3u; ++comp) {
        if (!within(comp_bound[comp], BOUND_LIMIT)) {
            return 0;
        }
    }
    return 1;
}

static int range_ok(const tfit_model *m)
{
    if (!map_ok(m->coef)) {
        return 0;
    }
    switch (m->family) {
    case TFIT_FAMILY_MODAL:
        return modal_ok(m);
    case TFIT_FAMILY_ZHOU2017:
        return zhou2017_ok(m);
    default:
        return nodal_ok(m);
    }
}

tfit_status tfit_model_check(const tfit_model *m)
{
    if (m == 0 || m->dims == 0 || m->coef == 0 || m->node_ids == 0) {
        return TFIT_ERR_ARG;
    }
    if (m->api_version != (uint32_t)TFIT_API_VERSION) {
        return TFIT_ERR_VERSION;
    }
    if (m->family < (uint32_t)TFIT_FAMILY_NODAL || m->family > (uint32_t)TFIT_FAMILY_CONTACT) {
        return TFIT_ERR_FAMILY;
    }
    /* Sizes before the CRC: the CRC reads n_coef floats. */
    const uint32_t expected = tfit_expected_coefs(m);
    if (expected == 0u || expected != m->n_coef) {
        return TFIT_ERR_SIZE;
    }
    if (tfit_model_crc32(m) != m->crc32) {
        return TFIT_ERR_CORRUPT;
    }
    return range_ok(m) ? TFIT_OK : TFIT_ERR_RANGE;
}
