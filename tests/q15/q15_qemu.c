/*
 * q15_qemu.c — the Q15 rows prototype (q15_rows.h) under QEMU (M4F, M7):
 * the assembly against the C reference, bit for bit, on random tables and
 * amplitudes and on the extreme one (every q = +-32767 and c_k = -8192 with
 * matching signs: the largest sum the bound allows), and the saturating
 * amplitude conversion against C on edge values.  Exit status 0 when all
 * agree; prints the number of words compared.
 */
#include <stdint.h>

#include "q15_rows.h"
#include "tfit_internal.h"
#include "semihost.h"

#define N_OUT 121u
#define ROW_WORDS (3u * N_OUT * Q15_WORDS)

static uint32_t rng = 0x12345678u;
static uint32_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
}

static uint32_t pair(int32_t lo, int32_t hi)
{
    return ((uint32_t)lo & 0xffffu) | ((uint32_t)hi << 16);
}

/* a q in [-32767, 32767] */
static int32_t random_q(void)
{
    return (int32_t)(next() % 65535u) - 32767;
}

static uint32_t rows[ROW_WORDS];
static float out_c[3u * N_OUT], out_asm[3u * N_OUT];

/* n output points (odd and even counts: the assembly's odd point and its
 * pairs); the words past them must stay untouched */
static uint32_t compare(const uint32_t c[Q15_WORDS], float scale, uint32_t n)
{
    uint32_t bad = 0u;
    for (uint32_t o = 0u; o < 3u * N_OUT; ++o) {
        out_c[o] = out_asm[o] = -1.0f;
    }
    q15_rows_c(rows, c, n, scale, out_c);
    q15_rows_asm(rows, c, n, scale, out_asm);
    for (uint32_t o = 0u; o < 3u * N_OUT; ++o) {
        union {
            float f;
            uint32_t u;
        } x = {out_c[o]}, y = {out_asm[o]};
        bad += (uint32_t)(x.u != y.u);
    }
    return bad;
}

int main(void)
{
    uint32_t bad = 0u, words = 0u;
    for (uint32_t set = 0u; set < 64u; ++set) {
        uint32_t c[Q15_WORDS];
        for (uint32_t i = 0u; i < ROW_WORDS; ++i) rows[i] = pair(random_q(), random_q());
        for (uint32_t j = 0u; j < Q15_WORDS; ++j)
            c[j] = pair((int32_t)(next() % 16384u) - 8192, (int32_t)(next() % 16384u) - 8192);
        const uint32_t n = set < 2u ? set + 1u : N_OUT - (set & 1u);
        bad += compare(c, 2.9e-8f * (float)(set + 1u), n);
        words += 3u * n;
    }
    /* the extreme: q = -32767 against c = -8192 everywhere, and the mirror */
    for (uint32_t i = 0u; i < ROW_WORDS; ++i) rows[i] = pair(-32767, -32767);
    const uint32_t cmin[Q15_WORDS] = {pair(-8192, -8192), pair(-8192, -8192), pair(-8192, -8192),
                                      pair(-8192, -8192)};
    bad += compare(cmin, 1.0f, N_OUT);
    if (out_asm[0] != 2147418112.0f) {
        semihost_puts("q15_qemu: the extreme sum is not 8 * 32767 * 8192\n");
        bad++;
    }
    words += 3u * N_OUT;
    /* the amplitude conversion: C's clamp-then-trunc against VCVT + SSAT */
    static const float edge[] = {0.0f, -0.0f, 0.99f, -0.99f, 8190.99f, 8191.0f, 8191.5f, 8192.0f,
                                 -8191.9f, -8192.0f, -8192.5f, -8193.0f, 1e9f, -1e9f, 3e38f, -3e38f,
                                 1e-30f, -1e-30f};
    for (uint32_t i = 0u; i < sizeof edge / sizeof edge[0]; ++i) {
        const float one = 1.0f;
        uint32_t c[Q15_WORDS];
        float a[Q15_RANK] = {edge[i]}, v[Q15_RANK] = {one};
        q15_amplitudes(a, v, c);
        bad += (uint32_t)((int32_t)(int16_t)(uint16_t)(c[0] & 0xffffu) != q15_sat_asm(edge[i]));
        words++;
    }
    /* the amplitudes term by term against tfit_row() of the library's
     * float modal family, mode by mode (p = 4: 35 terms) */
    for (uint32_t set = 0u; set < 64u; ++set) {
        static float a_tr[TFIT_TERMS(4u) * Q15_RANK], a_rows[Q15_RANK * TFIT_TERMS(4u)];
        float phi[TFIT_TERMS(4u)], a_asm[Q15_RANK];
        const uint32_t n = TFIT_TERMS(1u + set % 4u);
        for (uint32_t t = 0u; t < n; ++t) {
            phi[t] = (float)((int32_t)(next() >> 8) - (1 << 23)) * 0x1.0p-23f;
            for (uint32_t k = 0u; k < Q15_RANK; ++k) {
                const float x = (float)((int32_t)(next() >> 8) - (1 << 23)) * 0x1.0p-20f;
                a_tr[t * Q15_RANK + k] = x;
                a_rows[k * n + t] = x;
            }
        }
        q15_amp_terms_asm(a_tr, phi, n, a_asm);
        for (uint32_t k = 0u; k < Q15_RANK; ++k) {
            union {
                float f;
                uint32_t u;
            } x = {tfit_row(a_rows + k * n, phi, n)}, y = {a_asm[k]};
            bad += (uint32_t)(x.u != y.u);
            words++;
        }
        /* the fused step: scales that make some products saturate (|a v|
         * up to 2^15) or vanish, and keep = 0 every fourth set */
        float v[Q15_RANK];
        uint32_t c_c[Q15_WORDS], c_asm[Q15_WORDS];
        for (uint32_t k = 0u; k < Q15_RANK; ++k) {
            v[k] = (float)(next() >> 20) * (set % 3u == 0u ? 8.0f : 0.25f);
        }
        const uint32_t keep = set % 4u == 3u ? 0u : 0xffffffffu;
        q15_amp_c(a_tr, phi, n, v, keep, c_c);
        q15_amp_asm(a_tr, phi, n, v, keep, c_asm);
        for (uint32_t j = 0u; j < Q15_WORDS; ++j) {
            bad += (uint32_t)(c_c[j] != c_asm[j]);
            words++;
        }
    }
    semihost_puts("q15_qemu: words compared ");
    semihost_put_u32(words);
    semihost_puts(bad == 0u ? ", all bit-identical\n" : ", MISMATCH\n");
    return bad == 0u ? 0 : 1;
}
