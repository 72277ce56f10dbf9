/*
 * tfit_crc_word.c — one step of CRC-32/IEEE (zlib's crc32, reflected
 * polynomial 0xEDB88320) over a 32-bit word taken as four little-endian
 * bytes.  Reflected, the word's bits enter lowest first, so xor-ing the
 * whole word in and then shifting 32 bits out is the byte-wise algorithm;
 * the bits go four at a time through a 16-entry table (64 bytes, which the
 * compiler computes from the polynomial below, rather than the usual 1 KB
 * byte table): eight steps per word instead of 32, which matters since
 * tfit_model_check()'s self-test folds every output of eight evaluations
 * into a CRC.  Shared by the float and the Q31 model checks.
 */
#include "tfit_q31_internal.h"

#define CRC32_POLY 0xedb88320u
#define BIT(c) (((c) >> 1) ^ (CRC32_POLY & (0u - ((c) & 1u))))
#define NIBBLE(i) BIT(BIT(BIT(BIT((uint32_t)(i)))))

static const uint32_t nibble_table[16] = {
    NIBBLE(0),  NIBBLE(1),  NIBBLE(2),  NIBBLE(3),  NIBBLE(4),  NIBBLE(5),  NIBBLE(6),  NIBBLE(7),
    NIBBLE(8),  NIBBLE(9),  NIBBLE(10), NIBBLE(11), NIBBLE(12), NIBBLE(13), NIBBLE(14), NIBBLE(15)};

uint32_t tfit_crc32_word(uint32_t crc, uint32_t w)
{
    crc ^= w;
    for (int step = 0; step < 8; ++step) {
        crc = (crc >> 4) ^ nibble_table[crc & 15u];
    }
    return crc;
}
