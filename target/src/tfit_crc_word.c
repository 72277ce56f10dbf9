/*
 * tfit_crc_word.c — one step of CRC-32/IEEE (zlib's crc32, reflected
 * polynomial 0xEDB88320) over a 32-bit word taken as four little-endian
 * bytes, bit by bit (no table: 1 KB of flash saved; it runs once at boot).
 * Shared by the float and the Q31 model checks.
 */
#include "tfit_q31_internal.h"

#define CRC32_POLY 0xedb88320u

uint32_t tfit_crc32_word(uint32_t crc, uint32_t w)
{
    for (uint32_t byte = 0u; byte < 4u; ++byte) {
        crc ^= (w >> (8u * byte)) & 0xffu;
        for (int bit = 0; bit < 8; ++bit) {
            crc = (crc >> 1) ^ (CRC32_POLY & (0u - (crc & 1u)));
        }
    }
    return crc;
}
