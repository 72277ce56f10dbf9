/*
 * long_hash.h — what the 10^6-tick runs of a prony model compare
 * (long_ref.c on the host's reference evaluator, long_run.c on the target
 * library, natively and under QEMU): an FNV-1a hash of 32-bit words, fed at
 * every tick with the status, every state word and the three outputs of
 * one output point (point n mod n_out), and every 2^16 ticks with every
 * output.  Integer arithmetic only, freestanding.
 */
#ifndef TF_LONG_HASH_H
#define TF_LONG_HASH_H

#include <stdint.h>

#define TF_LONG_TICKS 1000000u
#define TF_LONG_SEED 0x14u
#define TF_LONG_FULL_EVERY 65536u

static inline uint32_t tf_long_word(uint32_t h, uint32_t w)
{
    return (h ^ w) * 16777619u;
}

typedef union tf_long_fu {
    float f;
    uint32_t u;
} tf_long_fu;

static inline uint32_t tf_long_bits(float f)
{
    tf_long_fu v = {.f = f};
    return v.u;
}

static inline float tf_long_float(uint32_t u)
{
    tf_long_fu v = {.u = u};
    return v.f;
}

/* The hash after tick n (status, state[words], out[3 n_out]). */
static inline uint32_t tf_long_tick(uint32_t h, uint32_t n, int32_t status, const float *state,
                                    uint32_t words, const float *out, uint32_t n_out)
{
    h = tf_long_word(h, (uint32_t)status);
    for (uint32_t w = 0u; w < words; ++w) {
        h = tf_long_word(h, tf_long_bits(state[w]));
    }
    const uint32_t j = n % n_out;
    for (uint32_t i = 0u; i < 3u; ++i) {
        h = tf_long_word(h, tf_long_bits(out[3u * j + i]));
    }
    if (n % TF_LONG_FULL_EVERY == 0u) {
        for (uint32_t o = 0u; o < 3u * n_out; ++o) {
            h = tf_long_word(h, tf_long_bits(out[o]));
        }
    }
    return h;
}

/* The same for a Q31 prony model: int32 state and output words. */
static inline uint32_t tf_long_tick_q31(uint32_t h, uint32_t n, int32_t status,
                                        const int32_t *state, uint32_t words, const int32_t *out,
                                        uint32_t n_out)
{
    h = tf_long_word(h, (uint32_t)status);
    for (uint32_t w = 0u; w < words; ++w) {
        h = tf_long_word(h, (uint32_t)state[w]);
    }
    const uint32_t j = n % n_out;
    for (uint32_t i = 0u; i < 3u; ++i) {
        h = tf_long_word(h, (uint32_t)out[3u * j + i]);
    }
    if (n % TF_LONG_FULL_EVERY == 0u) {
        for (uint32_t o = 0u; o < 3u * n_out; ++o) {
            h = tf_long_word(h, (uint32_t)out[o]);
        }
    }
    return h;
}

/* A Q31 force word from the sequence's integer force v (tf_seq_tick):
 * 2^23 units, the float runs' envelope extent, are 2^30, half the word's
 * range, as the Q31 input format's envelope (q31-format.md §2); larger
 * forces saturate.  A bad tick (NaN in the float runs) is an extreme word. */
static inline int32_t tf_long_word_q31(int32_t v, int bad, uint32_t i)
{
    const int32_t lim = 1 << 24;
    const int32_t c = v > lim - 1 ? lim - 1 : (v < -lim ? -lim : v);
    const int32_t extreme = (i & 1u) ? INT32_MIN : INT32_MAX;
    return bad ? extreme : (int32_t)((uint32_t)c << 7);
}

#define TF_LONG_HASH0 2166136261u

#endif /* TF_LONG_HASH_H */
