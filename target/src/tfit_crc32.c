/*
 * tfit_crc32.c — CRC-32 of a model, identical to zlib's crc32() over the
 * model serialised as little-endian 32-bit words:
 *   api_version, family, n_out, n_dims, n_coef, dims[], coef[] (bits), node_ids[].
 * Bitwise (no table: 1 KB of flash saved; it runs once at boot).
 */
#include "tfit_internal.h"

#define CRC32_POLY 0xedb88320u /* IEEE 802.3, reflected */

static uint32_t crc_word(uint32_t crc, uint32_t w)
{
    for (uint32_t byte = 0u; byte < 4u; ++byte) {
        crc ^= (w >> (8u * byte)) & 0xffu;
        for (int bit = 0; bit < 8; ++bit) {
            crc = (crc >> 1) ^ (CRC32_POLY & (0u - (crc & 1u)));
        }
    }
    return crc;
}

static uint32_t crc_words(uint32_t crc, const uint32_t *w, uint32_t n)
{
    for (uint32_t i = 0u; i < n; ++i) {
        crc = crc_word(crc, w[i]);
    }
    return crc;
}

uint32_t tfit_model_crc32(const tfit_model *m)
{
    if (m == 0 || m->dims == 0 || m->coef == 0 || m->node_ids == 0) {
        return 0u;
    }
    uint32_t crc = 0xffffffffu;
    crc = crc_word(crc, m->api_version);
    crc = crc_word(crc, m->family);
    crc = crc_word(crc, m->n_out);
    crc = crc_word(crc, m->n_dims);
    crc = crc_word(crc, m->n_coef);
    crc = crc_words(crc, m->dims, m->n_dims);
    for (uint32_t i = 0u; i < m->n_coef; ++i) {
        crc = crc_word(crc, tfit_bits(m->coef[i]));
    }
    crc = crc_words(crc, m->node_ids, m->n_out);
    return crc ^ 0xffffffffu;
}
