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
#include "tfit_region.h"

#define BOUND_LIMIT 0x1p100f
#define X0_LIMIT 0x1p64f
#define W_LIMIT 0x1p56f

static int within(float b, float limit)
{
    return b <= limit; /* false for NaN */
}

static float abs_sum(const float *c, uint32_t n)
{
    float s = 0.0f;
    for (uint32_t i = 0u; i < n; ++i) {
        s = s + tfit_abs(c[i]);
    }
    return s;
}

/* sum_k |c_k| tau^k (Horner on the magnitudes), tau >= 1. */
static float abs_poly(const float *c, uint32_t n, float tau)
{
    float s = tfit_abs(c[n]);
    for (uint32_t i = n; i > 0u; --i) {
        s = s * tau + tfit_abs(c[i - 1u]);
    }
    return s;
}

static int map_ok(const float *map)
{
    for (uint32_t i = 0u; i < 3u; ++i) {
        if (!within(tfit_abs(map[i]), X0_LIMIT)) {
            return 0;
        }
    }
    for (uint32_t i = 3u; i < TFIT_INPUT_MAP_FLOATS; ++i) {
        if (!within(tfit_abs(map[i]), W_LIMIT)) {
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
    return tfit_modes_bounded(modes, amax, r, 3u * m->n_out);
}

int tfit_modes_bounded(const float *modes, const float *amax, uint32_t r, uint32_t rows)
{
    for (uint32_t o = 0u; o < rows; ++o) {
        float b = 0.0f;
        for (uint32_t k = 0u; k < r; ++k) {
            b = b + tfit_abs(modes[o * r + k]) * amax[k];
        }
        if (!within(b, BOUND_LIMIT)) {
            return 0;
        }
    }
    return 1;
}

/* modal_q15 (header-format.md §5.9): the amplitudes bounded as modal's
 * (At transposed); v_k finite (a_k v_k may still overflow to +-Inf: the
 * conversion saturates it); 0 <= S <= 2^64, so |sum| S < 2^95; every row
 * word's halves within +-16255, which bounds every sum below 2^31 and
 * keeps the word from being a NaN or Inf pattern. */
static int modal_q15_ok(const tfit_model *m)
{
    const uint32_t n_terms = TFIT_TERMS(m->dims[0]);
    const float *at = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *v = at + TFIT_MODAL_Q15_RANK * n_terms;
    const float *rows = v + TFIT_MODAL_Q15_RANK + 1u;
    for (uint32_t k = 0u; k < TFIT_MODAL_Q15_RANK; ++k) {
        float b = 0.0f;
        for (uint32_t t = 0u; t < n_terms; ++t) {
            b = b + tfit_abs(at[t * TFIT_MODAL_Q15_RANK + k]);
        }
        if (!within(b, BOUND_LIMIT) || !within(tfit_abs(v[k]), BOUND_LIMIT)) {
            return 0;
        }
    }
    const float s = v[TFIT_MODAL_Q15_RANK];
    if (!(s >= 0.0f && s <= 0x1p64f)) {
        return 0;
    }
    for (uint32_t i = 0u; i < 3u * m->n_out * TFIT_MODAL_Q15_WORDS; ++i) {
        const uint32_t w = tfit_bits(rows[i]);
        const uint32_t lo = (w + 16255u) & 0xffffu; /* q + 16255 for q in range */
        const uint32_t hi = w >> 16;                /* q + 16384 */
        if (lo > 32510u || hi < 129u || hi > 32639u) {
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
        if (!within(tfit_abs(xy[j]), 1.0f)) {
            return 0;
        }
    }
    for (uint32_t a = 0u; a < 3u; ++a) {
        float d = abs_sum(c, dm[a] + 1u);
        c += dm[a] + 1u;
        float t = d * tfit_abs(c[0]);
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

/* A cut model's K + 1 tables as one nodal table of (K + 1) n_out points:
 * each row's bound holds at every knot, and a + w (b - a) with w in [0, 1]
 * stays within twice the larger, far below float's range. */
static int cut_ok(const tfit_model *m)
{
    tfit_model v;
    v.n_out = (m->dims[1] + 1u) * m->n_out;
    v.dims = m->dims;
    v.coef = m->coef;
    return nodal_ok(&v);
}

/* A stateful model: its filter's terms (tfit_prony.c, tfit_resonant.c
 * give the bounds that keep the state finite), then its static map as its
 * own family: h is clamped to [-1, 1] before it. */
static int stateful_ok(const tfit_model *m)
{
    tfit_model v;
    tfit_stateful_static(m, &v);
    return tfit_stateful_terms_ok(m) && (v.family == TFIT_FAMILY_NODAL ? nodal_ok(&v) : modal_ok(&v));
}

static int range_ok(const tfit_model *m)
{
    if (m->family == TFIT_FAMILY_REGION || m->family == TFIT_FAMILY_REGION_SURFACE) {
        return tfit_region_range_ok(m); /* their first 12 floats are a chart */
    }
    if (!map_ok(m->coef)) {
        return 0;
    }
    switch (m->family) {
    case TFIT_FAMILY_PRONY:
    case TFIT_FAMILY_RESONANT:
        return stateful_ok(m);
    case TFIT_FAMILY_CUT:
        return cut_ok(m);
    case TFIT_FAMILY_MODAL:
        return modal_ok(m);
    case TFIT_FAMILY_MODAL_Q15:
        return modal_q15_ok(m);
    case TFIT_FAMILY_ZHOU2017:
        return zhou2017_ok(m);
    default:
        return nodal_ok(m);
    }
}

/* Each table pointer against its end pointer, as integers (no pointer
 * arithmetic on a possibly damaged value): a single flipped bit in either
 * breaks the equality. */
static int ends_match(const tfit_model *m)
{
    return (uintptr_t)m->dims_end - (uintptr_t)m->dims == (uintptr_t)m->n_dims * 4u &&
           (uintptr_t)m->coef_end - (uintptr_t)m->coef == (uintptr_t)m->n_coef * 4u &&
           (uintptr_t)m->node_ids_end - (uintptr_t)m->node_ids == (uintptr_t)m->n_out * 4u;
}

/* Output point j of m at the projected input g, into out[3]: the family's
 * own evaluator on a view of the model that holds point j alone (its rows
 * for nodal and contact, its row of U for modal, its coordinates for
 * zhou2017; the rest of the table is where the evaluator expects it).
 * Always the C evaluators: the degree-1 assembly has nothing a compiler
 * could contract. */
static void point(const tfit_model *m, const float g[3], uint32_t keep, uint32_t j, float out[3])
{
    tfit_model v; /* the fields evaluation reads, one by one: a struct copy
                   * would be a memcpy call, which a freestanding library
                   * cannot make */
    const uint32_t after = m->n_out - 1u - j; /* output points after j */
    v.family = m->family;
    v.n_out = 1u;
    v.n_dims = m->n_dims;
    v.n_coef = m->n_coef;
    v.dims = m->dims;
    v.coef = m->coef;
    v.node_ids = m->node_ids;
    switch (m->family) {
    case TFIT_FAMILY_MODAL:
        v.n_coef = m->n_coef - 3u * m->dims[1] * after;
        tfit_eval_modal(&v, g, keep, out);
        break;
    case TFIT_FAMILY_MODAL_Q15: /* the rows end the table, as modal's U */
        v.n_coef = m->n_coef - 3u * TFIT_MODAL_Q15_WORDS * after;
        tfit_eval_modal_q15(&v, g, keep, out);
        break;
    case TFIT_FAMILY_ZHOU2017:
        v.n_coef = m->n_coef - 2u * after;
        tfit_eval_zhou2017(&v, g, out);
        for (uint32_t i = 0u; i < 3u; ++i) {
            out[i] = tfit_masked(out[i], keep);
        }
        break;
    default: /* nodal, contact: the rows at coef + 12 + 3 T j */
        v.coef = m->coef + 3u * TFIT_TERMS(m->dims[0]) * j;
        tfit_eval_nodal(&v, g, keep, out);
        break;
    }
}

/* Far input k of the self-test (header-format.md §8), the host's too: a
 * linear congruential sequence gives three signed 24-bit integers, exact as
 * floats, times 2^77 (exact): beyond 2^64, so §4 scales them, and beyond any
 * envelope, so the Newton step runs. */
uint32_t tfit_far_input(uint32_t state, float in[3])
{
    for (uint32_t i = 0u; i < 3u; ++i) {
        state = state * 1664525u + 1013904223u;
        const int32_t v = (int32_t)(state >> 8) - 0x800000; /* [-2^23, 2^23) */
        in[i] = (float)v * 0x1p77f;
    }
    return state;
}

/* The self-test: at each carried input the status and every output, point
 * by point (no buffer of 3 n_out floats), and at the far inputs the
 * projected g, each folded into a CRC-32 that must equal the host's.  A
 * stateful model (prony, resonant) takes the inputs as ticks from a reset
 * state: after the status, each tick's new state words, and the static map
 * sees the filtered input h.  A cut model evaluates input k at the cut progress
 * s_k = k / 4 - 1/4 (both ends clamped). */
static tfit_status self_test(const tfit_model *m)
{
    float in[3], g[3], h[3], out[3], st[TFIT_STATEFUL_MAX_STATE];
    uint32_t bad, crc = 0xffffffffu;
    const int stateful = tfit_filter_of(m->family) != 0;
    uint32_t state_words = 0u;
    const int cut = m->family == TFIT_FAMILY_CUT;
    float phi[TFIT_MAX_TERMS], sw = 0.0f;
    uint32_t knot = 0u;
    tfit_model static_map;
    const tfit_model *eval = m;
    if (stateful) {
        (void)tfit_stateful_reset(m->family, m, st);
        tfit_stateful_static(m, &static_map);
        eval = &static_map;
        state_words = tfit_stateful_words(m);
    }
    for (uint32_t k = 0u; k < (uint32_t)TFIT_CHECK_INPUTS; ++k) {
        for (uint32_t i = 0u; i < 3u; ++i) {
            in[i] = tfit_float(m->check[3u * k + i]);
        }
        uint32_t clamped = tfit_input_map(m->coef, in, g, &bad);
        if (cut) { /* at s_k = k/4 - 1/4: -0.25 (clamped), 0, ..., 1.5 (clamped) */
            uint32_t sbad;
            clamped |= tfit_cut_progress((float)k * 0.25f - 0.25f, m->dims[1], &knot, &sw, &sbad);
            tfit_basis(m->dims[0], g, phi);
        }
        crc = tfit_crc32_word(crc, (clamped & ~bad & 1u) - (bad & 1u)); /* the status */
        if (stateful) { /* the new state, then the static map at h */
            tfit_stateful_filter(m, g, ~bad, st, h);
            for (uint32_t w = 0u; w < state_words; ++w) {
                crc = tfit_crc32_word(crc, tfit_bits(st[w]));
            }
            g[0] = h[0];
            g[1] = h[1];
            g[2] = h[2];
        }
        for (uint32_t j = 0u; j < m->n_out; ++j) {
            if (cut) {
                tfit_cut_rows(m, phi, knot, sw, j, 1u, ~bad, out);
            } else {
                point(eval, g, ~bad, j, out);
            }
            for (uint32_t i = 0u; i < 3u; ++i) {
                crc = tfit_crc32_word(crc, tfit_bits(out[i]));
            }
        }
    }
    uint32_t state = 1u, far = 0xffffffffu;
    for (uint32_t k = 0u; k < (uint32_t)TFIT_CHECK_FAR; ++k) {
        state = tfit_far_input(state, in);
        (void)tfit_input_map(m->coef, in, g, &bad);
        for (uint32_t i = 0u; i < 3u; ++i) {
            far = tfit_crc32_word(far, tfit_bits(g[i]));
        }
    }
    const uint32_t *want = m->check + 3u * TFIT_CHECK_INPUTS;
    return ((crc ^ 0xffffffffu) == want[0] && (far ^ 0xffffffffu) == want[1]) ? TFIT_OK
                                                                              : TFIT_ERR_ARITH;
}

tfit_status tfit_model_check(const tfit_model *m)
{
    if (m == 0 || m->dims == 0 || m->coef == 0 || m->node_ids == 0) {
        return TFIT_ERR_ARG;
    }
    if (!ends_match(m)) {
        return TFIT_ERR_CORRUPT;
    }
    if (m->api_version != (uint32_t)TFIT_API_VERSION) {
        return TFIT_ERR_VERSION;
    }
    if (m->family < (uint32_t)TFIT_FAMILY_FIRST || m->family > (uint32_t)TFIT_FAMILY_LAST) {
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
    if (!range_ok(m)) {
        return TFIT_ERR_RANGE;
    }
    if (m->family == TFIT_FAMILY_REGION || m->family == TFIT_FAMILY_REGION_SURFACE) {
        return tfit_region_self_test(m);
    }
    return self_test(m);
}
