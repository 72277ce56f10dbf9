/*
 * tfit_q31_check.c — tfit_model_check_q31() and the CRC of a Q31 model
 * (docs/q31-format.md §6): version, family, sizes, CRC-32, then the range
 * proof that no intermediate of §3-§5 overflows for any input.
 */
#include "tfit_q31_internal.h"

#define MAX_ROW_SUM 0x7fff8000u /* 2^31 - 2^15: sum of |c| of one row */
#define MAX_W 0x40000000u       /* 2^30 */
#define MAX_X0 0x20000000u      /* 2^29 */

uint32_t tfit_q31_expected_words(uint32_t n_out, uint32_t degree)
{
    if (degree > TFIT_Q31_MAX_DEGREE) {
        return 0u;
    }
    return TFIT_Q31_MAP_WORDS + 3u * n_out * (q_terms(degree) + 1u);
}

uint32_t tfit_model_crc32_q31(const tfit_model_q31 *m)
{
    if (m == 0 || m->q == 0 || m->node_ids == 0) {
        return 0u;
    }
    uint32_t crc = 0xffffffffu;
    crc = tfit_crc32_word(crc, m->api_version);
    crc = tfit_crc32_word(crc, m->family);
    crc = tfit_crc32_word(crc, m->n_out);
    crc = tfit_crc32_word(crc, m->degree);
    crc = tfit_crc32_word(crc, m->n_words);
    for (uint32_t i = 0u; i < m->n_words; ++i) {
        crc = tfit_crc32_word(crc, (uint32_t)m->q[i]);
    }
    for (uint32_t i = 0u; i < m->n_out; ++i) {
        crc = tfit_crc32_word(crc, m->node_ids[i]);
    }
    return crc ^ 0xffffffffu;
}

static uint32_t magnitude(int32_t v)
{
    const uint32_t u = (uint32_t)v;
    return (u ^ q_negative(u)) - q_negative(u);
}

static int map_ok(const int32_t *map)
{
    for (int j = 0; j < 3; ++j) {
        if (magnitude(map[j]) > MAX_X0) {
            return 0;
        }
    }
    for (int i = 3; i < 12; ++i) {
        if (magnitude(map[i]) > MAX_W) {
            return 0;
        }
    }
    return map[12] >= 2 && map[12] <= 14;
}

/* K of a prony model (q[13], read once n_words >= 14 is known), else 0. */
static uint32_t prony_terms(const tfit_model_q31 *m)
{
    if (m->family != (uint32_t)TFIT_FAMILY_PRONY || m->n_words <= TFIT_Q31_PRONY_K_WORD) {
        return 0u;
    }
    return (uint32_t)m->q[TFIT_Q31_PRONY_K_WORD];
}

static const int32_t *first_row(const tfit_model_q31 *m)
{
    return m->family == (uint32_t)TFIT_FAMILY_PRONY ? q_prony_rows(m->q, prony_terms(m))
                                                      : m->q + TFIT_Q31_MAP_WORDS;
}

/* Each term: 0 <= a <= 2^31 - 2^14 (the rounding drift of z stays below
 * 2^16 units, §8) and |D| <= 2^30 (|D| <= 1). */
static int terms_ok(const tfit_model_q31 *m)
{
    const int32_t *pt = m->q + TFIT_Q31_PRONY_K_WORD + 1;
    for (uint32_t k = 0u; k < prony_terms(m); ++k, pt += 2) {
        if (pt[0] < 0 || pt[0] > TFIT_Q31_PRONY_MAX_A || magnitude(pt[1]) > TFIT_Q31_PRONY_MAX_D) {
            return 0;
        }
    }
    return 1;
}

static int rows_ok(const tfit_model_q31 *m)
{
    const uint32_t n_terms = q_terms(m->degree);
    const int32_t *r = first_row(m);
    for (uint32_t o = 0u; o < 3u * m->n_out; ++o, r += n_terms + 1u) {
        if (r[0] < 33 || r[0] > 62) {
            return 0;
        }
        uint32_t sum = 0u;
        for (uint32_t t = 1u; t <= n_terms; ++t) {
            const uint32_t a = magnitude(r[t]);
            if (a > MAX_ROW_SUM - sum) {
                return 0;
            }
            sum += a;
        }
    }
    return 1;
}

/* Each table pointer against its end, as integers (tfit_check.c). */
static int ends_match(const tfit_model_q31 *m)
{
    return (uintptr_t)m->q_end - (uintptr_t)m->q == (uintptr_t)m->n_words * 4u &&
           (uintptr_t)m->node_ids_end - (uintptr_t)m->node_ids == (uintptr_t)m->n_out * 4u;
}

tfit_status tfit_model_check_q31(const tfit_model_q31 *m)
{
    if (m == 0 || m->q == 0 || m->node_ids == 0) {
        return TFIT_ERR_ARG;
    }
    if (!ends_match(m)) {
        return TFIT_ERR_CORRUPT;
    }
    if (m->api_version != (uint32_t)TFIT_Q31_API_VERSION) {
        return TFIT_ERR_VERSION;
    }
    if (m->family != (uint32_t)TFIT_FAMILY_NODAL && m->family != (uint32_t)TFIT_FAMILY_CONTACT &&
        m->family != (uint32_t)TFIT_FAMILY_PRONY) {
        return TFIT_ERR_FAMILY;
    }
    const uint32_t terms = prony_terms(m);
    const uint32_t extra = m->family == (uint32_t)TFIT_FAMILY_PRONY ? 1u + 2u * terms : 0u;
    if (m->degree > TFIT_Q31_MAX_DEGREE || m->n_out == 0u || m->n_out > TFIT_Q31_MAX_OUT ||
        (m->family == (uint32_t)TFIT_FAMILY_CONTACT && m->n_out != 1u) ||
        terms > TFIT_PRONY_MAX_TERMS ||
        m->n_words != tfit_q31_expected_words(m->n_out, m->degree) + extra) {
        return TFIT_ERR_SIZE;
    }
    if (tfit_model_crc32_q31(m) != m->crc32) {
        return TFIT_ERR_CORRUPT;
    }
    return (map_ok(m->q) && terms_ok(m) && rows_ok(m)) ? TFIT_OK : TFIT_ERR_RANGE;
}
