/*
 * tfit_crc32.c — CRC-32 of a model, identical to zlib's crc32() over the
 * model serialised as little-endian 32-bit words:
 *   api_version, family, n_out, n_dims, n_coef, dims[], coef[] (bits),
 *   node_ids[], check[] (the self-test vector).
 * The table pointers are addresses, which the host cannot know: each is
 * checked against its end pointer instead (tfit_check.c).
 * The word step is tfit_crc32_word() (tfit_crc_word.c).
 */
#include "tfit_internal.h"

static uint32_t crc_words(uint32_t crc, const uint32_t *w, uint32_t n)
{
    for (uint32_t i = 0u; i < n; ++i) {
        crc = tfit_crc32_word(crc, w[i]);
    }
    return crc;
}

uint32_t tfit_model_crc32(const tfit_model *m)
{
    if (m == 0 || m->dims == 0 || m->coef == 0 || m->node_ids == 0) {
        return 0u;
    }
    uint32_t crc = 0xffffffffu;
    crc = tfit_crc32_word(crc, m->api_version);
    crc = tfit_crc32_word(crc, m->family);
    crc = tfit_crc32_word(crc, m->n_out);
    crc = tfit_crc32_word(crc, m->n_dims);
    crc = tfit_crc32_word(crc, m->n_coef);
    crc = crc_words(crc, m->dims, m->n_dims);
    for (uint32_t i = 0u; i < m->n_coef; ++i) {
        crc = tfit_crc32_word(crc, tfit_bits(m->coef[i]));
    }
    crc = crc_words(crc, m->node_ids, m->n_out);
    crc = crc_words(crc, m->check, TFIT_CHECK_WORDS);
    return crc ^ 0xffffffffu;
}
