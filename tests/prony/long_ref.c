/*
 * long_ref.c — the expected result of a 10^6-tick run of every stateful
 * (prony, resonant) model
 * of one generated header, from the host's reference evaluator
 * (host/model/forms/stateful.c: float arithmetic emulated in double).  Compiled
 * per header with -DGOLDEN_H='"NAME_golden.h"' -DGOLDEN_SETS=...
 * -DTFIT_NAME_IMPLEMENTATION (it reads the models from the header itself),
 * writes NAME_long.h for long_run.c: per golden set, the force scale and
 * the hash (long_hash.h) of the run.
 *
 *   long_ref OUT.h
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include GOLDEN_H

#include "force_sequence.h"
#include "long_hash.h"
#include "model/forms/stateful.h"
#include "model/model.h"
#include "model/q31.h"

/* The header's model as a host model (tables copied). */
static tf_model *host_copy(const tfit_model *t)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = tf_model_new(&ctx, "m", (tfit_family)t->family, t->n_out, t->dims, t->n_dims);
    if (m == NULL) {
        fprintf(stderr, "long_ref: %s\n", ctx.err);
        exit(1);
    }
    memcpy(m->coef, t->coef, t->n_coef * sizeof *m->coef);
    memcpy(m->node_ids, t->node_ids, t->n_out * sizeof *m->node_ids);
    return m;
}

/* A power of two at or above the envelope's extent along each axis, over
 * 2^23: the sequence's integer forces then span the envelope (and beyond,
 * on its pushes). */
static float scale_of(const tf_model *m)
{
    double w = 0;
    for (int i = 0; i < 3; ++i) {
        w = fmax(w, fabs((double)m->coef[3 + 4 * i]));
    }
    return ldexpf(1.0f, (int)ceil(log2(1.0 / w)) - 23);
}

static uint32_t run(const tf_model *m, float scale)
{
    float state[TFIT_RESONANT_MAX_STATE];
    float *out = malloc(3 * m->n_out * sizeof *out);
    const uint32_t words = m->family == TFIT_FAMILY_PRONY ? TFIT_PRONY_STATE_WORDS(m->dims[2])
                                                          : TFIT_RESONANT_STATE_WORDS(m->dims[2]);
    tf_force_seq q;
    uint32_t h = TF_LONG_HASH0;
    tf_seq_init(&q, TF_LONG_SEED);
    tf_stateful_reset(m, state);
    for (uint32_t n = 0; n < TF_LONG_TICKS; ++n) {
        float f[3];
        tf_seq_force(&q, scale, f);
        tfit_status s = tf_stateful_step(m, state, f, out, NULL);
        h = tf_long_tick(h, n, (int32_t)s, state, words, out, m->n_out);
    }
    free(out);
    return h;
}

#ifdef GOLDEN_Q31_SETS
/* The header's Q31 prony model through the host's integer reference. */
static uint32_t run_q31(const tfit_model_q31 *t)
{
    tf_q31 q = {.family = (tfit_family)t->family, .n_out = t->n_out, .degree = t->degree,
                .n_words = t->n_words, .terms = (uint32_t)t->q[TFIT_Q31_MAP_WORDS],
                .q = (int32_t *)(uintptr_t)t->q, .node_ids = t->node_ids};
    int32_t state[TFIT_PRONY_Q31_STATE_WORDS(TFIT_PRONY_MAX_TERMS)];
    int32_t *out = malloc(3 * t->n_out * sizeof *out);
    tf_force_seq s;
    uint32_t h = TF_LONG_HASH0;
    tf_seq_init(&s, TF_LONG_SEED);
    tf_q31_ref_prony_reset(&q, state);
    for (uint32_t n = 0; n < TF_LONG_TICKS; ++n) {
        int32_t v[3], x[3];
        const int bad = tf_seq_tick(&s, v);
        for (uint32_t i = 0; i < 3; ++i) {
            x[i] = tf_long_word_q31(v[i], bad, i);
        }
        tfit_status st = tf_q31_ref_prony_step(&q, state, x, out);
        h = tf_long_tick_q31(h, n, (int32_t)st, state, TFIT_PRONY_Q31_STATE_WORDS(q.terms), out,
                             t->n_out);
    }
    free(out);
    return h;
}
#endif

int main(int argc, char **argv)
{
    static const tfit_golden *const sets[] = GOLDEN_SETS;
    const size_t n = sizeof sets / sizeof sets[0];
    if (argc != 2) {
        fprintf(stderr, "usage: long_ref OUT.h\n");
        return 2;
    }
    uint32_t scale[sizeof sets / sizeof sets[0]], hash[sizeof sets / sizeof sets[0]];
    for (size_t i = 0; i < n; ++i) {
        scale[i] = hash[i] = 0;
        if (sets[i]->model->family == TFIT_FAMILY_PRONY ||
            sets[i]->model->family == TFIT_FAMILY_RESONANT) {
            tf_model *m = host_copy(sets[i]->model);
            float s = scale_of(m);
            memcpy(&scale[i], &s, sizeof s);
            hash[i] = run(m, s);
            tf_model_free(m);
        }
    }
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s.tmp", argv[1]);
    FILE *f = fopen(tmp, "w");
    if (f == NULL) {
        perror(tmp);
        return 1;
    }
    fprintf(f, "/* %s - written by tests/prony/long_ref.c: per golden set, the force scale\n"
               " * (float bits) and the hash of %u ticks (0, 0: not a stateful model). */\n",
            argv[1], TF_LONG_TICKS);
    fprintf(f, "static const uint32_t long_scale[%zu] = {", n);
    for (size_t i = 0; i < n; ++i) {
        fprintf(f, "%s0x%08xu", i ? ", " : "", scale[i]);
    }
    fprintf(f, "};\nstatic const uint32_t long_hash[%zu] = {", n);
    for (size_t i = 0; i < n; ++i) {
        fprintf(f, "%s0x%08xu", i ? ", " : "", hash[i]);
    }
    fprintf(f, "};\n");
#ifdef GOLDEN_Q31_SETS
    static const tfit_golden_q31 *const q31[] = GOLDEN_Q31_SETS; /* null-terminated */
    const size_t nq = sizeof q31 / sizeof q31[0];
    fprintf(f, "static const uint32_t long_hash_q31[%zu] = {", nq);
    for (size_t i = 0; i < nq; ++i) {
        const int prony = q31[i] != NULL && q31[i]->model->family == TFIT_FAMILY_PRONY;
        fprintf(f, "%s0x%08xu", i ? ", " : "", prony ? run_q31(q31[i]->model) : 0u);
    }
    fprintf(f, "};\n");
#endif
    if (fclose(f) != 0 || rename(tmp, argv[1]) != 0) {
        perror(argv[1]);
        return 1;
    }
    return 0;
}
