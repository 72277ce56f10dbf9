/*
 * force_sequence.h — a long, deterministic haptic force history for the
 * prony family's tests: presses (ramps to a random force), holds, releases,
 * rests, jitter, pushes far beyond the envelope and single NaN/Inf ticks,
 * in segments of random length.  Integer arithmetic only (a linear
 * congruential generator, 32-bit adds), then one exact conversion to float
 * times a power of two, so that the host tests and the firmware under QEMU
 * produce the same bits without sharing code or libm.  Header-only and
 * freestanding (stdint.h), for tests/prony/long_run.c on the device.
 *
 * Forces are v * scale with |v| <= 2^23 (the envelope's extent when scale
 * is its radius / 2^23) and up to 2^26 for pushes beyond it.
 */
#ifndef TF_FORCE_SEQUENCE_H
#define TF_FORCE_SEQUENCE_H

#include <stdint.h>

typedef struct tf_force_seq {
    uint32_t lcg;
    int32_t v[3];    /* the current force, integer units */
    int32_t step[3]; /* per tick during a ramp */
    uint32_t left;   /* ticks left in the segment */
    uint32_t kind;
} tf_force_seq;

enum { TF_SEQ_RAMP, TF_SEQ_HOLD, TF_SEQ_JITTER, TF_SEQ_GLITCH, TF_SEQ_KINDS };

static inline uint32_t tf_seq_next(tf_force_seq *q)
{
    q->lcg = q->lcg * 1664525u + 1013904223u;
    return q->lcg;
}

/* A signed integer in [-2^bits, 2^bits), bits <= 30. */
static inline int32_t tf_seq_int(tf_force_seq *q, uint32_t bits)
{
    return (int32_t)(tf_seq_next(q) >> (31u - bits)) - (int32_t)(1u << bits);
}

static inline void tf_seq_init(tf_force_seq *q, uint32_t seed)
{
    q->lcg = seed;
    for (int i = 0; i < 3; ++i) {
        q->v[i] = 0;
        q->step[i] = 0;
    }
    q->left = 0u;
    q->kind = TF_SEQ_HOLD;
}

/* A new segment: a ramp (press to a random force inside, or beyond the
 * envelope one time in eight, or release to zero one time in four) over
 * 2^k ticks, k = 0..12; a hold of up to 2^14 ticks; jitter around the
 * current force; or one bad tick. */
static inline void tf_seq_segment(tf_force_seq *q)
{
    const uint32_t r = tf_seq_next(q) >> 24;
    if (r < 120u) {
        const uint32_t k = (tf_seq_next(q) >> 16) % 13u, n = 1u << k;
        const uint32_t where = (tf_seq_next(q) >> 29);
        for (int i = 0; i < 3; ++i) {
            int32_t to = where < 2u ? 0 : tf_seq_int(q, where == 7u ? 25u : 22u);
            q->step[i] = (to - q->v[i]) / (int32_t)n;
        }
        q->kind = TF_SEQ_RAMP;
        q->left = n;
    } else if (r < 200u) {
        q->kind = TF_SEQ_HOLD;
        q->left = 1u + ((tf_seq_next(q) >> 8) & 0x3fffu);
    } else if (r < 250u) {
        q->kind = TF_SEQ_JITTER;
        q->left = 1u + ((tf_seq_next(q) >> 8) & 0x3ffu);
    } else {
        q->kind = TF_SEQ_GLITCH;
        q->left = 1u;
    }
}

/* The next tick's force, in integer units; returns 1 for a bad tick (the
 * caller makes one component NaN or Inf, the force itself unchanged). */
static inline int tf_seq_tick(tf_force_seq *q, int32_t v[3])
{
    if (q->left == 0u) {
        tf_seq_segment(q);
    }
    q->left--;
    int bad = 0;
    for (int i = 0; i < 3; ++i) {
        if (q->kind == TF_SEQ_RAMP) {
            q->v[i] += q->step[i];
        }
        v[i] = q->v[i];
        if (q->kind == TF_SEQ_JITTER) {
            v[i] += tf_seq_int(q, 16u);
        }
    }
    if (q->kind == TF_SEQ_GLITCH) {
        bad = 1;
    }
    return bad;
}

/* The force of this tick as floats: v * scale (scale a power of two, so
 * the product is exact whenever (float)v is), one component replaced by a
 * NaN or an Inf on a bad tick. */
static inline void tf_seq_force(tf_force_seq *q, float scale, float f[3])
{
    int32_t v[3];
    const int bad = tf_seq_tick(q, v);
    for (int i = 0; i < 3; ++i) {
        f[i] = (float)v[i] * scale;
    }
    if (bad) {
        union {
            uint32_t u;
            float f;
        } nan;
        const uint32_t which = tf_seq_next(q) >> 30;
        nan.u = which == 0u ? 0x7f800000u : (which == 1u ? 0xff800000u : 0x7fc00001u);
        f[which == 3u ? 2 : (int)which % 3] = nan.f;
    }
}

#endif /* TF_FORCE_SEQUENCE_H */
