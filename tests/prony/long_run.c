/*
 * long_run.c — 10^6 ticks of every stateful model (prony, resonant) of one
 * generated header on
 * the target library, against the host reference's hash (NAME_long.h from
 * long_ref.c): status, every state word and a rotating output point at
 * every tick, every output each 2^16 ticks (long_hash.h), from the same
 * integer force sequence (tests/support/force_sequence.h): presses, holds,
 * releases, jitter, pushes far beyond the envelope, NaN/Inf ticks.
 * Built natively (stdio) and for the QEMU boards (semihosting,
 * -DLONG_QEMU), with -DGOLDEN_H, -DGOLDEN_SETS, -DLONG_H and
 * -DTFIT_NAME_IMPLEMENTATION, -DLABEL.  Exit status 0 only when every
 * model's hash matches.
 */
#include GOLDEN_H
#include LONG_H

#include "force_sequence.h"
#include "long_hash.h"

#ifdef LONG_QEMU
#include "semihost.h"
#include "startup.h"
#define SAY(s) semihost_puts(s)
#define SAY_U32(v) semihost_put_u32(v)
#else
#include <stdio.h>
#define SAY(s) fputs(s, stdout)
#define SAY_U32(v) printf("%u", (unsigned)(v))
#endif

#define MAX_OUT 512u
static float out[3u * MAX_OUT];

static uint32_t run(const tfit_model *m, float scale)
{
    float state[TFIT_RESONANT_MAX_STATE];
    const int prony = m->family == TFIT_FAMILY_PRONY;
    const uint32_t words = prony ? TFIT_PRONY_STATE_WORDS(m->dims[2])
                                 : TFIT_RESONANT_STATE_WORDS(m->dims[2]);
    tf_force_seq q;
    uint32_t h = TF_LONG_HASH0;
    tf_seq_init(&q, TF_LONG_SEED);
    if (prony) {
        tfit_prony_reset(m, state);
    } else {
        tfit_resonant_reset(m, state);
    }
    for (uint32_t n = 0u; n < TF_LONG_TICKS; ++n) {
        float f[3];
        tf_seq_force(&q, scale, f);
        tfit_status s = prony ? tfit_prony_step(m, state, f, out)
                              : tfit_resonant_step(m, state, f, out);
        h = tf_long_tick(h, n, (int32_t)s, state, words, out, m->n_out);
    }
    return h;
}

#ifdef GOLDEN_Q31_SETS
static int32_t out_q31[3u * MAX_OUT];

static uint32_t run_q31(const tfit_model_q31 *m)
{
    int32_t state[TFIT_PRONY_Q31_STATE_WORDS(TFIT_PRONY_MAX_TERMS)];
    const uint32_t words = TFIT_PRONY_Q31_STATE_WORDS(m->q[TFIT_Q31_MAP_WORDS]);
    tf_force_seq q;
    uint32_t h = TF_LONG_HASH0;
    tf_seq_init(&q, TF_LONG_SEED);
    tfit_prony_reset_q31(m, state);
    for (uint32_t n = 0u; n < TF_LONG_TICKS; ++n) {
        int32_t v[3], x[3];
        const int bad = tf_seq_tick(&q, v);
        for (uint32_t i = 0u; i < 3u; ++i) {
            x[i] = tf_long_word_q31(v[i], bad, i);
        }
        tfit_status s = tfit_prony_step_q31(m, state, x, out_q31);
        h = tf_long_tick_q31(h, n, (int32_t)s, state, words, out_q31, m->n_out);
    }
    return h;
}

/* Every Q31 prony model of the header: 10^6 ticks against the host's
 * integer reference; returns the models run, counts failures. */
static uint32_t run_all_q31(uint32_t *failed)
{
    static const tfit_golden_q31 *const sets[] = GOLDEN_Q31_SETS; /* null-terminated */
    uint32_t models = 0u;
    for (uint32_t i = 0u; sets[i] != 0; ++i) {
        const tfit_model_q31 *m = sets[i]->model;
        if (m->family != TFIT_FAMILY_PRONY) {
            continue;
        }
        ++models;
        if (m->n_out > MAX_OUT || tfit_model_check_q31(m) != TFIT_OK ||
            run_q31(m) != long_hash_q31[i]) {
            SAY(LABEL ": q31 set ");
            SAY_U32(i);
            SAY(": model check failed, too many outputs or the hash differs\n");
            ++*failed;
        }
    }
    return models;
}
#endif

int main(void)
{
    static const tfit_golden *const sets[] = GOLDEN_SETS;
    const uint32_t n_sets = (uint32_t)(sizeof sets / sizeof sets[0]);
    uint32_t models = 0u, failed = 0u;
    for (uint32_t i = 0u; i < n_sets; ++i) {
        const tfit_model *m = sets[i]->model;
        if (m->family != TFIT_FAMILY_PRONY && m->family != TFIT_FAMILY_RESONANT) {
            continue;
        }
        ++models;
        if (m->n_out > MAX_OUT || tfit_model_check(m) != TFIT_OK) {
            SAY(LABEL ": set ");
            SAY_U32(i);
            SAY(": model check failed or too many outputs\n");
            ++failed;
            continue;
        }
        const uint32_t h = run(m, tf_long_float(long_scale[i]));
        if (h != long_hash[i]) {
            SAY(LABEL ": set ");
            SAY_U32(i);
            SAY(": hash ");
            SAY_U32(h);
            SAY(", the host's ");
            SAY_U32(long_hash[i]);
            SAY("\n");
            ++failed;
        }
    }
    SAY(LABEL ": ");
    SAY_U32(models);
    SAY(" stateful models x ");
    SAY_U32(TF_LONG_TICKS);
    SAY(" ticks: ");
    SAY_U32(models - failed);
    SAY(" bit-exact (status, state, outputs), ");
    SAY_U32(failed);
    SAY(" differ\n");
#ifdef GOLDEN_Q31_SETS
    uint32_t failed_q31 = 0u;
    const uint32_t models_q31 = run_all_q31(&failed_q31);
    SAY(LABEL ": ");
    SAY_U32(models_q31);
    SAY(" Q31 prony models x ");
    SAY_U32(TF_LONG_TICKS);
    SAY(" ticks: ");
    SAY_U32(models_q31 - failed_q31);
    SAY(" bit-exact (status, state, outputs), ");
    SAY_U32(failed_q31);
    SAY(" differ\n");
    failed += failed_q31;
    models += models_q31;
#endif
    return (failed == 0u && models > 0u) ? 0 : 1;
}
