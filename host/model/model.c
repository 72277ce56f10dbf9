/*
 * model.c — host-side model tables: allocation, input map, CRC, validation
 * and operation counts.  The sizes and bounds here are written from
 * docs/header-format.md, independently of target/src, so that the tests
 * compare two implementations of one specification.
 */
#include "model/model.h"

#include "model/oscillator.h"
#include "model/region_layout.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

/* One bit of margin under the target's limits (2^100, 2^64, 2^56): the
 * target sums in float, the host in double. */
#define BOUND_LIMIT 0x1p99
#define X0_LIMIT 0x1p63
#define W_LIMIT 0x1p55

uint32_t tf_terms(uint32_t p)
{
    return (p + 1) * (p + 2) * (p + 3) / 6;
}

static uint32_t zhou_rows(const uint32_t *dims, int pair)
{
    return dims[3 + 3 * pair] + dims[4 + 3 * pair] + 1;
}

uint32_t tf_model_ncoef(tfit_family family, uint32_t n_out, const uint32_t *dims, uint32_t n_dims)
{
    if (n_out == 0 || n_out > (1u << 20)) {
        return 0;
    }
    uint64_t n = TFIT_INPUT_MAP_FLOATS;
    switch (family) {
    case TFIT_FAMILY_CONTACT: /* same layout as nodal, one output point */
    case TFIT_FAMILY_NODAL:
        if (n_dims != 1 || dims[0] > TFIT_MAX_DEGREE || (family == TFIT_FAMILY_CONTACT && n_out != 1)) {
            return 0;
        }
        n += 3ull * n_out * tf_terms(dims[0]);
        break;
    case TFIT_FAMILY_MODAL:
        if (n_dims != 2 || dims[0] > TFIT_MAX_DEGREE || dims[1] == 0 || dims[1] > TFIT_MAX_RANK) {
            return 0;
        }
        n += (uint64_t)dims[1] * tf_terms(dims[0]) + 3ull * n_out * dims[1];
        break;
    case TFIT_FAMILY_MODAL_Q15: /* {p >= 1, 8}: At[T][8], v[8], S, 3 n_out rows of 4 words */
        if (n_dims != TFIT_MODAL_Q15_DIMS || dims[0] == 0 || dims[0] > TFIT_MAX_DEGREE ||
            dims[1] != TFIT_MODAL_Q15_RANK) {
            return 0;
        }
        n += (uint64_t)TFIT_MODAL_Q15_RANK * (tf_terms(dims[0]) + 1) + 1 +
             3ull * n_out * TFIT_MODAL_Q15_WORDS;
        break;
    case TFIT_FAMILY_PRONY: /* {p, r, K, tick_ns}: K pairs, then nodal (r = 0) or modal */
        if (n_dims != TFIT_PRONY_DIMS || dims[0] > TFIT_MAX_DEGREE || dims[1] > TFIT_MAX_RANK ||
            dims[2] > TFIT_PRONY_MAX_TERMS || dims[3] == 0) {
            return 0;
        }
        n += 2ull * dims[2];
        n += dims[1] == 0 ? 3ull * n_out * tf_terms(dims[0])
                          : (uint64_t)dims[1] * tf_terms(dims[0]) + 3ull * n_out * dims[1];
        break;
    case TFIT_FAMILY_RESONANT: /* {p, r, K, tick_ns}: K modes of 7, then as prony */
        if (n_dims != TFIT_RESONANT_DIMS || dims[0] > TFIT_MAX_DEGREE ||
            dims[1] > TFIT_MAX_RANK || dims[2] > TFIT_RESONANT_MAX_MODES || dims[3] == 0) {
            return 0;
        }
        n += 7ull * dims[2];
        n += dims[1] == 0 ? 3ull * n_out * tf_terms(dims[0])
                          : (uint64_t)dims[1] * tf_terms(dims[0]) + 3ull * n_out * dims[1];
        break;
    case TFIT_FAMILY_CUT: /* {p, K}: K + 1 nodal tables, knots s = k / K */
        if (n_dims != TFIT_CUT_DIMS || dims[0] > TFIT_MAX_DEGREE || dims[1] == 0 ||
            dims[1] > TFIT_CUT_MAX_INTERVALS) {
            return 0;
        }
        n += (dims[1] + 1ull) * 3ull * n_out * tf_terms(dims[0]);
        break;
    case TFIT_FAMILY_ZHOU2017:
        if (n_dims != TFIT_ZHOU2017_DIMS) {
            return 0;
        }
        for (int a = 0; a < 3; ++a) {
            if (dims[a] > TFIT_MAX_DEGREE) {
                return 0;
            }
            n += dims[a] + 2;
        }
        for (int pair = 0; pair < 9; ++pair) {
            const uint32_t *o = dims + 3 + 3 * pair;
            if (o[0] > TFIT_ZHOU_MAX_ORDER || o[1] > TFIT_ZHOU_MAX_ORDER || o[2] > TFIT_MAX_DEGREE) {
                return 0;
            }
            n += (uint64_t)zhou_rows(dims, pair) * (o[2] + 1);
        }
        n += 2ull * n_out;
        break;
    case TFIT_FAMILY_REGION: /* region_layout.c */
    case TFIT_FAMILY_REGION_SURFACE:
        return tf_region_ncoef(family, n_out, dims, n_dims);
    default:
        return 0;
    }
    return n > UINT32_MAX ? 0 : (uint32_t)n;
}

tf_model *tf_model_new(const char *name, tfit_family family, uint32_t n_out, const uint32_t *dims,
                       uint32_t n_dims, char *err, size_t errlen)
{
    uint32_t n_coef = tf_model_ncoef(family, n_out, dims, n_dims);
    if (n_coef == 0) {
        snprintf(err, errlen, "model '%s': invalid shape for family %d (n_out %u, %u dims)", name,
                 (int)family, n_out, n_dims);
        return NULL;
    }
    if (strlen(name) >= TF_NAME_MAX) {
        snprintf(err, errlen, "model name '%s' longer than %d characters", name, TF_NAME_MAX - 1);
        return NULL;
    }
    tf_model *m = calloc(1, sizeof *m);
    float *coef = calloc(n_coef, sizeof *coef);
    uint32_t *ids = calloc(n_out, sizeof *ids);
    if (m == NULL || coef == NULL || ids == NULL) {
        free(m);
        free(coef);
        free(ids);
        snprintf(err, errlen, "out of memory for model '%s' (%u coefficients)", name, n_coef);
        return NULL;
    }
    snprintf(m->name, sizeof m->name, "%s", name);
    m->family = family;
    m->n_out = n_out;
    m->n_dims = n_dims;
    memcpy(m->dims, dims, n_dims * sizeof *dims);
    m->n_coef = n_coef;
    m->coef = coef;
    m->node_ids = ids;
    m->envelope_radius = 0.0;
    m->heldout_max = m->heldout_rms = m->heldout_rel_max = m->heldout_q31_max = NAN;
    m->stiffness_min = m->stiffness_max = m->discretisation_max = NAN;
    const double zero[3] = {0, 0, 0};
    tf_model_set_ball(m, zero, 1.0);
    return m;
}

void tf_model_free(tf_model *m)
{
    if (m != NULL) {
        free(m->coef);
        free(m->node_ids);
        free(m);
    }
}

tf_model *tf_model_clone(const tf_model *m)
{
    tf_model *c = malloc(sizeof *c);
    float *coef = malloc(m->n_coef * sizeof *coef);
    uint32_t *ids = malloc(m->n_out * sizeof *ids);
    if (c == NULL || coef == NULL || ids == NULL) {
        free(c);
        free(coef);
        free(ids);
        return NULL;
    }
    *c = *m;
    memcpy(coef, m->coef, m->n_coef * sizeof *coef);
    memcpy(ids, m->node_ids, m->n_out * sizeof *ids);
    c->coef = coef;
    c->node_ids = ids;
    return c;
}

void tf_model_set_map(tf_model *m, const double x0[3], const double w[9])
{
    for (int i = 0; i < 3; ++i) {
        m->coef[i] = (float)x0[i];
    }
    for (int i = 0; i < 9; ++i) {
        m->coef[3 + i] = (float)w[i];
    }
    m->envelope_radius = 0.0;
}

void tf_model_set_ball(tf_model *m, const double centre[3], double radius)
{
    const double w[9] = {1 / radius, 0, 0, 0, 1 / radius, 0, 0, 0, 1 / radius};
    tf_model_set_map(m, centre, w);
    m->envelope_radius = radius;
}

float *tf_model_tables(tf_model *m)
{
    return m->coef + TFIT_INPUT_MAP_FLOATS;
}

uint32_t tf_crc32_u32(uint32_t crc, uint32_t w)
{
    const unsigned char b[4] = {(unsigned char)w, (unsigned char)(w >> 8), (unsigned char)(w >> 16),
                                (unsigned char)(w >> 24)};
    return (uint32_t)crc32(crc, b, 4);
}

uint32_t tf_model_crc32(const tf_model *m)
{
    uint32_t crc = (uint32_t)crc32(0L, Z_NULL, 0);
    crc = tf_crc32_u32(crc, TFIT_API_VERSION);
    crc = tf_crc32_u32(crc, (uint32_t)m->family);
    crc = tf_crc32_u32(crc, m->n_out);
    crc = tf_crc32_u32(crc, m->n_dims);
    crc = tf_crc32_u32(crc, m->n_coef);
    for (uint32_t i = 0; i < m->n_dims; ++i) {
        crc = tf_crc32_u32(crc, m->dims[i]);
    }
    for (uint32_t i = 0; i < m->n_coef; ++i) {
        uint32_t bits;
        memcpy(&bits, &m->coef[i], sizeof bits);
        crc = tf_crc32_u32(crc, bits);
    }
    for (uint32_t i = 0; i < m->n_out; ++i) {
        crc = tf_crc32_u32(crc, m->node_ids[i]);
    }
    return crc;
}

/* Sum of |c_k| tau^k, the bound of a polynomial for |x| <= tau. */
static double abs_poly(const float *c, uint32_t order, double tau)
{
    double s = 0, pw = 1;
    for (uint32_t k = 0; k <= order; ++k, pw *= tau) {
        s += fabs((double)c[k]) * pw;
    }
    return s;
}

static int bound_fail(double b, const char *what, const tf_model *m, uint32_t index, char *err,
                      size_t errlen)
{
    if (b <= BOUND_LIMIT) {
        return 0;
    }
    snprintf(err, errlen,
             "model '%s': %s %u can reach %g, beyond the float-safe bound 2^99 (non-finite or "
             "ill-scaled coefficients)",
             m->name, what, index, b);
    return 1;
}

static int validate_prony(const tf_model *m, char *err, size_t errlen);
static int validate_resonant(const tf_model *m, char *err, size_t errlen);

/* modal_q15 (header-format.md §5.9): the amplitudes bounded as modal's,
 * the scales finite (a_k v_k may overflow to +-Inf: it saturates), S in
 * [0, 2^64], every row word's halves within [-16255, 16255] (so that the
 * sums cannot overflow and no word is a NaN or Inf pattern). */
static int validate_modal_q15(const tf_model *m, char *err, size_t errlen)
{
    const uint32_t t = tf_terms(m->dims[0]), r = TFIT_MODAL_Q15_RANK;
    const float *at = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *v = at + (size_t)r * t;
    for (uint32_t k = 0; k < r; ++k) {
        double b = 0;
        for (uint32_t j = 0; j < t; ++j) {
            b += fabs((double)at[(size_t)j * r + k]);
        }
        if (bound_fail(b, "mode amplitude", m, k, err, errlen)) {
            return 1;
        }
        if (!(fabs((double)v[k]) <= BOUND_LIMIT)) {
            snprintf(err, errlen, "model '%s': Q15 scale of mode %u is %g (not finite)", m->name,
                     k, (double)v[k]);
            return 1;
        }
    }
    if (!(v[r] >= 0.0f && v[r] <= 0x1p64f)) {
        snprintf(err, errlen, "model '%s': Q15 output scale %g outside [0, 2^64]", m->name,
                 (double)v[r]);
        return 1;
    }
    const float *rows = v + r + 1;
    for (uint32_t i = 0; i < 3 * m->n_out * TFIT_MODAL_Q15_WORDS; ++i) {
        uint32_t w;
        memcpy(&w, &rows[i], sizeof w);
        const int32_t lo = (int32_t)(int16_t)(uint16_t)(w & 0xffffu);
        const int32_t hi = (int32_t)(w >> 16) - 16384;
        if (lo < -16255 || lo > 16255 || hi < -16255 || hi > 16255) {
            snprintf(err, errlen, "model '%s': Q15 row word %u holds %d, %d beyond +-16255",
                     m->name, i, lo, hi);
            return 1;
        }
    }
    return 0;
}

static int validate_ranges(const tf_model *m, char *err, size_t errlen)
{
    const float *c = m->coef + TFIT_INPUT_MAP_FLOATS;
    if (m->family == TFIT_FAMILY_MODAL_Q15) {
        return validate_modal_q15(m, err, errlen);
    }
    if (m->family == TFIT_FAMILY_PRONY) {
        return validate_prony(m, err, errlen);
    }
    if (m->family == TFIT_FAMILY_RESONANT) {
        return validate_resonant(m, err, errlen);
    }
    if (m->family == TFIT_FAMILY_NODAL || m->family == TFIT_FAMILY_CONTACT ||
        m->family == TFIT_FAMILY_CUT) { /* a cut model: every knot's rows */
        uint32_t t = tf_terms(m->dims[0]);
        uint32_t knots = m->family == TFIT_FAMILY_CUT ? m->dims[1] + 1 : 1;
        for (uint32_t o = 0; o < 3 * m->n_out * knots; ++o) {
            if (bound_fail(abs_poly(c + o * t, t - 1, 1.0), "output", m, o, err, errlen)) {
                return 1;
            }
        }
    } else if (m->family == TFIT_FAMILY_MODAL) {
        uint32_t t = tf_terms(m->dims[0]), r = m->dims[1];
        double amax[TFIT_MAX_RANK];
        for (uint32_t k = 0; k < r; ++k) {
            amax[k] = abs_poly(c + k * t, t - 1, 1.0);
            if (bound_fail(amax[k], "mode amplitude", m, k, err, errlen)) {
                return 1;
            }
        }
        const float *u = c + r * t;
        for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
            double b = 0;
            for (uint32_t k = 0; k < r; ++k) {
                b += fabs((double)u[o * r + k]) * amax[k];
            }
            if (bound_fail(b, "output", m, o, err, errlen)) {
                return 1;
            }
        }
    } else {
        double tau[3], comp[3] = {0, 0, 0};
        for (int a = 0; a < 3; ++a) {
            double d = abs_poly(c, m->dims[a], 1.0);
            c += m->dims[a] + 1;
            double t = d * fabs((double)*c++);
            if (bound_fail(d, "contact displacement of axis", m, (uint32_t)a, err, errlen) ||
                bound_fail(t, "normalised contact displacement of axis", m, (uint32_t)a, err,
                           errlen)) {
                return 1;
            }
            /* Chebyshev series in |t| <= tau: |T_k|, |U_k| <= (2 tau)^k
             * (header-format.md §8) */
            tau[a] = 2 * (t > 1 ? t : 1);
        }
        for (int pair = 0; pair < 9; ++pair) {
            uint32_t rows = zhou_rows(m->dims, pair), k = m->dims[5 + 3 * pair];
            for (uint32_t i = 0; i < rows; ++i, c += k + 1) {
                comp[pair % 3] += abs_poly(c, k, tau[pair / 3]);
            }
        }
        for (uint32_t j = 0; j < 2 * m->n_out; ++j) {
            if (!(fabs((double)c[j]) <= 1.0)) {
                snprintf(err, errlen,
                         "model '%s': normalised node coordinate %u is %g, outside [-1, 1]",
                         m->name, j, (double)c[j]);
                return 1;
            }
        }
        for (uint32_t k = 0; k < 3; ++k) {
            if (bound_fail(comp[k], "displacement component", m, k, err, errlen)) {
                return 1;
            }
        }
    }
    return 0;
}

tf_model tf_prony_static_view(const tf_model *m)
{
    return tf_stateful_static_view(m);
}

tf_model tf_stateful_static_view(const tf_model *m)
{
    tf_model v = *m;
    const uint32_t skip = (m->family == TFIT_FAMILY_RESONANT ? 7 : 2) * m->dims[2];
    v.family = m->dims[1] == 0 ? TFIT_FAMILY_NODAL : TFIT_FAMILY_MODAL;
    v.n_dims = m->dims[1] == 0 ? 1 : 2;
    v.coef = m->coef + skip; /* its tables at coef + 12, as the family's own */
    v.n_coef = m->n_coef - skip;
    return v;
}

/* Prony terms (header-format.md §8): 0 <= a_k <= 1 - 2^-19 (the target's
 * limit is 1 - 2^-20: a bit of margin) and |D_k| <= 2^63; then the static
 * map as its own family. */
static int validate_prony(const tf_model *m, char *err, size_t errlen)
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        double a = pt[2 * k], d = fabs((double)pt[2 * k + 1]);
        if (!(a >= 0 && a <= 1 - 0x1p-19) || !(d <= 0x1p63)) {
            snprintf(err, errlen,
                     "model '%s': prony term %u has decay %g and gain %g (decay in [0, 1 - 2^-19] "
                     "and |gain| <= 2^63 keep the state finite)",
                     m->name, k, a, (double)pt[2 * k + 1]);
            return 1;
        }
    }
    tf_model v = tf_prony_static_view(m);
    return validate_ranges(&v, err, errlen);
}

/* Resonant modes: the device's magnitude limits (tfit_check.c), and the
 * contraction of the rounded transition matrix that keeps the state finite
 * (model/resonant.h); then the static map as its own family. */
static int validate_resonant(const tf_model *m, char *err, size_t errlen)
{
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        if (tf_resonant_floats_check(m->coef + TFIT_INPUT_MAP_FLOATS + 7 * k, m->name, k, err,
                                     errlen) != 0) {
            return 1;
        }
    }
    tf_model v = tf_stateful_static_view(m);
    return validate_ranges(&v, err, errlen);
}

int tf_model_validate(const tf_model *m, char *err, size_t errlen)
{
    if (tf_model_ncoef(m->family, m->n_out, m->dims, m->n_dims) != m->n_coef) {
        snprintf(err, errlen, "model '%s': table size %u does not match its family and orders",
                 m->name, m->n_coef);
        return 1;
    }
    for (int i = 0; i < TFIT_INPUT_MAP_FLOATS; ++i) {
        double v = fabs((double)m->coef[i]);
        if (!(v <= (i < 3 ? X0_LIMIT : W_LIMIT))) {
            snprintf(err, errlen, "model '%s': input map entry %d is %g (envelope degenerate?)",
                     m->name, i, (double)m->coef[i]);
            return 1;
        }
    }
    for (uint32_t i = 0; i < m->n_coef; ++i) {
        if (!isfinite(m->coef[i])) {
            snprintf(err, errlen, "model '%s': coefficient %u is not finite", m->name, i);
            return 1;
        }
    }
    return validate_ranges(m, err, errlen);
}

/* Input projection (docs/header-format.md §4): 33 mul, 14 add, no division. */
static tf_opcount input_ops(void)
{
    return (tf_opcount){.add = 14, .mul = 33, .div = 0};
}

/* Float operations of the Chebyshev basis of degree p (§5.1, §6): per
 * variable h = g + g and p - 1 recurrence steps (mul, sub) when p >= 2;
 * p (p - 1) / 2 inner products T_b T_c with b, c >= 1, b + c <= p (one per
 * pair, shared by every a) and T(p - 1) - p outer products T_a (..) with
 * a >= 1, b + c >= 1 (a factor T_0 = 1 is exact and not multiplied). */
static void basis_ops(uint32_t p, tf_opcount *ops)
{
    if (p >= 2) {
        ops->add += 3 * (1 + (uint64_t)(p - 1));
        ops->mul += 3 * (uint64_t)(p - 1) + (uint64_t)p * (p - 1) / 2 + tf_terms(p - 1) - p;
    }
}

/* Clenshaw (§5.4): the tail sum_{k=1..n} c_k T_k takes n + 1 mul and
 * 2n + 2 add (h, n steps of a product, a difference and a sum, then
 * (x b_1) - b_2), n = 0 included; the full series one add more (+ c_0). */
static uint64_t tail_add(uint32_t n)
{
    return 2 * (uint64_t)n + 2;
}

static uint64_t series_add(uint32_t n)
{
    return tail_add(n) + 1;
}

tf_opcount tf_model_ops(const tf_model *m)
{
    if (m->family == TFIT_FAMILY_RESONANT) {
        /* the filter (§5.8): 3 differences, then per mode and axis 5 mul
         * and 4 add; then the static map */
        tf_model v = tf_stateful_static_view(m);
        tf_opcount ops = tf_model_ops(&v);
        ops.add += 3 + 12ull * m->dims[2];
        ops.mul += 15ull * m->dims[2];
        return ops;
    }
    if (m->family == TFIT_FAMILY_PRONY) {
        /* the filter (§5.6): 3 differences, then per term 6 mul and 3 add
         * for the state and 3 subtractions for h; then the static map */
        tf_model v = tf_prony_static_view(m);
        tf_opcount ops = tf_model_ops(&v);
        ops.add += 3 + 6ull * m->dims[2];
        ops.mul += 6ull * m->dims[2];
        return ops;
    }
    tf_opcount ops = input_ops();
    const uint64_t rows = 3ull * m->n_out;
    if (m->family == TFIT_FAMILY_NODAL || m->family == TFIT_FAMILY_CONTACT) {
        uint64_t t = tf_terms(m->dims[0]);
        basis_ops(m->dims[0], &ops);
        ops.mul += rows * (t - 1);
        ops.add += rows * (t - 1);
    } else if (m->family == TFIT_FAMILY_CUT) {
        /* §5.7: t = s K, w = t - j; two rows per output, then a + w (b - a) */
        uint64_t t = tf_terms(m->dims[0]);
        basis_ops(m->dims[0], &ops);
        ops.mul += 1 + rows * (2 * (t - 1) + 1);
        ops.add += 1 + rows * (2 * (t - 1) + 2);
    } else if (m->family == TFIT_FAMILY_MODAL) {
        uint64_t t = tf_terms(m->dims[0]), r = m->dims[1];
        basis_ops(m->dims[0], &ops);
        ops.mul += r * (t - 1) + rows * r;
        ops.add += r * (t - 1) + rows * (r - 1);
    } else if (m->family == TFIT_FAMILY_MODAL_Q15) {
        /* float operations only: the amplitudes, a_k v_k, and S per output
         * (the mode sums are integer) */
        uint64_t t = tf_terms(m->dims[0]), r = TFIT_MODAL_Q15_RANK;
        basis_ops(m->dims[0], &ops);
        ops.mul += r * (t - 1) + r + rows;
        ops.add += r * (t - 1);
    } else {
        for (int a = 0; a < 3; ++a) {
            ops.mul += m->dims[a] + 2; /* the series, then t_a = d_a s_a */
            ops.add += series_add(m->dims[a]);
        }
        for (int pair = 0; pair < 9; ++pair) {
            const uint32_t *o = m->dims + 3 + 3 * pair;
            const uint64_t rows_p = zhou_rows(m->dims, pair);
            ops.mul += rows_p * (o[2] + 1ull) +
                       m->n_out * ((o[0] + 1ull) + (o[1] > 0 ? o[1] + 1ull : 0));
            ops.add += rows_p * series_add(o[2]) +
                       m->n_out * (series_add(o[0]) + (o[1] > 0 ? tail_add(o[1]) + 1 : 0) +
                                   (pair >= 3 ? 1 : 0));
        }
    }
    return ops;
}

uint32_t tf_model_table_bytes(const tf_model *m)
{
    return 4 * (m->n_coef + m->n_dims + m->n_out);
}
