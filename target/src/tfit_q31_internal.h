/*
 * tfit_q31_internal.h — integer helpers of the Q31 evaluator (not
 * installed).  docs/q31-format.md defines every operation; these helpers
 * implement it with 32-bit operations, 64-bit additions and the two words
 * of 64-bit values, never a variable 64-bit shift, a division or a
 * comparison that could become a branch — so that Armv6-M needs no libgcc
 * helper and every core runs the same instruction count for every input.
 *
 * 64-bit intermediates are held as uint64_t (two's complement, arithmetic
 * modulo 2^64: no signed overflow anywhere); int32_t results are converted
 * from uint32_t, which every compiler we support does as two's complement.
 */
#ifndef TFIT_Q31_INTERNAL_H
#define TFIT_Q31_INTERNAL_H

#include <stdint.h>

#include "tfit_q31.h"

#define TFIT_Q31_MAX_DEGREE 8u
#define TFIT_Q31_MAX_TERMS 165u /* T(8) */
#define TFIT_Q31_MAX_OUT (1u << 20)
#define TFIT_Q31_ONE (1 << 30) /* 1.0 in Q30 (g and the basis) */

/* All ones when x != 0, else zero (no comparison). */
static inline uint32_t q_nonzero(uint32_t x)
{
    return 0u - ((x | (0u - x)) >> 31);
}

/* All ones when x < 0 (as int32), else zero. */
static inline uint32_t q_negative(uint32_t x)
{
    return 0u - (x >> 31);
}

static inline uint32_t q_select(uint32_t mask, uint32_t a, uint32_t b)
{
    return (a & mask) | (b & ~mask);
}

static inline uint32_t q_lo(uint64_t v)
{
    return (uint32_t)v;
}

static inline uint32_t q_hi(uint64_t v)
{
    return (uint32_t)(v >> 32);
}

static inline uint64_t q_words(uint32_t hi, uint32_t lo)
{
    return ((uint64_t)hi << 32) | lo;
}

/* Carry out of a + b (Hacker's Delight 2-13). */
static inline uint32_t q_carry(uint32_t a, uint32_t b, uint32_t sum)
{
    return ((a & b) | ((a | b) & ~sum)) >> 31;
}

/* a * b, unsigned 32 x 32 -> 64.  Armv6-M has no long multiply: four
 * 16 x 16 products (MULS) instead of a libgcc call. */
static inline uint64_t q_umul(uint32_t a, uint32_t b)
{
#if defined(__ARM_ARCH_6M__) || defined(TFIT_Q31_PORTABLE_MUL)
    const uint32_t al = a & 0xffffu, ah = a >> 16, bl = b & 0xffffu, bh = b >> 16;
    const uint32_t ll = al * bl, lh = al * bh, hl = ah * bl, hh = ah * bh;
    const uint32_t mid = lh + hl;
    const uint32_t mid_carry = q_carry(lh, hl, mid);
    const uint32_t lo = ll + (mid << 16);
    const uint32_t lo_carry = q_carry(ll, mid << 16, lo);
    return q_words(hh + (mid >> 16) + (mid_carry << 16) + lo_carry, lo);
#else
    return (uint64_t)a * b;
#endif
}

/* a * b, signed 32 x 32 -> 64 (as uint64_t).  Without a long multiply:
 * the unsigned product minus 2^32 b for a negative a and 2^32 a for a
 * negative b (mod 2^64). */
static inline uint64_t q_smul(int32_t a, int32_t b)
{
#if defined(__ARM_ARCH_6M__) || defined(TFIT_Q31_PORTABLE_MUL)
    const uint32_t ua = (uint32_t)a, ub = (uint32_t)b;
    const uint64_t p = q_umul(ua, ub);
    return p - ((uint64_t)((ub & q_negative(ua)) + (ua & q_negative(ub))) << 32);
#else
    return (uint64_t)((int64_t)a * b);
#endif
}

/* a * b, signed a times unsigned b (|a| b < 2^63). */
static inline uint64_t q_sumul(int32_t a, uint32_t b)
{
    const uint32_t ua = (uint32_t)a;
    return q_umul(ua, b) - ((uint64_t)(b & q_negative(ua)) << 32);
}

/* floor(x / 2^k) for an int32 x, 0 <= k <= 31, without relying on >> of a
 * negative value. */
static inline int32_t q_sra32(uint32_t x, uint32_t k)
{
    const uint32_t fill = q_negative(x) << (31u - k) << 1;
    return (int32_t)((x >> k) | fill);
}

/* The low 32 bits of v >> k, 1 <= k <= 31 (a logical shift of the 64-bit
 * pattern: the low word is the same as for an arithmetic one). */
static inline uint32_t q_shr64_lo(uint64_t v, uint32_t k)
{
    return (q_lo(v) >> k) | (q_hi(v) << (32u - k));
}

/* Number of significant bits of x >= 1, in five fixed steps. */
static inline uint32_t q_bit_length(uint32_t x)
{
    uint32_t n = 1u;
    for (uint32_t step = 16u; step > 0u; step >>= 1) {
        const uint32_t big = q_nonzero(x >> step);
        n += step & big;
        x = q_select(big, x >> step, x);
    }
    return n;
}

/* T(p) = C(p+3, 3), p <= TFIT_Q31_MAX_DEGREE, by table: Armv6-M has no
 * divide instruction. */
static inline uint32_t q_terms(uint32_t p)
{
    static const uint8_t terms[TFIT_Q31_MAX_DEGREE + 1u] = {1, 4, 10, 20, 35, 56, 84, 120, 165};
    return terms[p];
}

/* The evaluator's parts (docs/q31-format.md §3-§5). */
uint32_t tfit_q31_input_map(const int32_t *map, const int32_t x[3], int32_t g[3]);
void tfit_q31_basis(uint32_t p, const int32_t g[3], int32_t *phi);
uint32_t tfit_q31_expected_words(uint32_t n_out, uint32_t degree);
/* The rows starting at r (q-format §5) at the normalised input g (Q30). */
void tfit_q31_rows(const tfit_model_q31 *m, const int32_t *r, const int32_t g[3], int32_t *out);

/* A prony model's table (q-format §8): K at q[13], then K pairs {a_k, D_k},
 * then the rows. */
#define TFIT_Q31_PRONY_K_WORD TFIT_Q31_MAP_WORDS
#define TFIT_Q31_PRONY_MAX_A 0x7fffc000 /* 2^31 - 2^14: 1 - a >= 2^-17 */
#define TFIT_Q31_PRONY_MAX_D 0x40000000u /* 2^30: |D| <= 1 */
static inline const int32_t *q_prony_rows(const int32_t *q, uint32_t terms)
{
    return q + TFIT_Q31_MAP_WORDS + 1u + 2u * terms;
}

/* CRC-32 (IEEE, reflected) of one little-endian word, bitwise
 * (tfit_crc_word.c; shared with the float library's tfit_model_crc32). */
uint32_t tfit_crc32_word(uint32_t crc, uint32_t w);

#endif /* TFIT_Q31_INTERNAL_H */
