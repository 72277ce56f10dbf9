/*
 * probe.c — evaluates every golden vector of every model of families.h once,
 * float and Q31 forms, under callgrind, dumping the instruction count of
 * each evaluation (CALLGRIND_DUMP_STATS_AT) so that run.sh can compare
 * them: the count must not depend on the input.  A prony or resonant model's golden
 * vectors are one tick sequence: each tick is one evaluation, stepped from
 * a reset state, so the count must depend on neither the input nor the
 * state.  Q31 sets are numbered from 20 and their family ids shifted by 10
 * (11 nodal, 14 contact, 15 prony).
 *
 * families.h by default; another header with -DGOLDEN_H, -DGOLDEN_SETS,
 * -DGOLDEN_Q31_SETS and its -DTFIT_NAME_IMPLEMENTATION (tests/prony.mk runs
 * creep48.h, the block48-shaped viscoelastic model, this way).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <valgrind/callgrind.h>

#ifndef GOLDEN_H
#define TFIT_FAMILIES_IMPLEMENTATION
#define GOLDEN_H "families_golden.h"
#define GOLDEN_SETS TFIT_FAMILIES_GOLDEN_SETS
#define GOLDEN_Q31_SETS TFIT_FAMILIES_GOLDEN_Q31_SETS
#endif
#include GOLDEN_H

/* Negative control: a function whose cost depends on its input, so run.sh
 * can show that the measurement tells the difference. */
static __attribute__((noinline)) float control_branchy(float x)
{
    float acc = 0.0f;
    for (int i = 0; i < 50 && acc < x; ++i) {
        acc += 1.0f;
    }
    return acc;
}

int main(void)
{
    static const tfit_golden *const sets[] = GOLDEN_SETS;
    for (size_t s = 0; s < sizeof sets / sizeof sets[0]; ++s) {
        const tfit_model *m = sets[s]->model;
        float *out = malloc(3 * m->n_out * sizeof *out);
        float state[TFIT_RESONANT_MAX_STATE];
        if (m->family == TFIT_FAMILY_PRONY) {
            tfit_prony_reset(m, state);
        } else if (m->family == TFIT_FAMILY_RESONANT) {
            tfit_resonant_reset(m, state);
        }
        for (uint32_t v = 0; v < sets[s]->n_vec; ++v) {
            float x[3];
            char label[64];
            tfit_status st;
            memcpy(x, sets[s]->in + 3 * v, sizeof x);
            CALLGRIND_ZERO_STATS;
            if (m->family == TFIT_FAMILY_PRONY) {
                st = tfit_prony_step(m, state, x, out);
            } else if (m->family == TFIT_FAMILY_RESONANT) {
                st = tfit_resonant_step(m, state, x, out);
            } else if (m->family == TFIT_FAMILY_CONTACT) {
                st = tfit_contact_force(m, x, out);
            } else {
                st = tfit_displacements(m, x, out);
            }
            snprintf(label, sizeof label, "set=%zu family=%u vec=%u status=%d", s, m->family, v,
                     (int)st);
            CALLGRIND_DUMP_STATS_AT(label);
        }
        free(out);
    }
    static const tfit_golden_q31 *const q31[] = GOLDEN_Q31_SETS;
    for (size_t s = 0; q31[s] != NULL; ++s) {
        const tfit_model_q31 *m = q31[s]->model;
        int32_t *out = malloc(3 * m->n_out * sizeof *out);
        int32_t state[TFIT_PRONY_Q31_STATE_WORDS(TFIT_PRONY_MAX_TERMS)];
        if (m->family == TFIT_FAMILY_PRONY) {
            tfit_prony_reset_q31(m, state);
        }
        for (uint32_t v = 0; v < q31[s]->n_vec; ++v) {
            char label[64];
            const int32_t *x = q31[s]->in + 3 * v;
            CALLGRIND_ZERO_STATS;
            tfit_status st = m->family == TFIT_FAMILY_PRONY     ? tfit_prony_step_q31(m, state, x, out)
                             : m->family == TFIT_FAMILY_CONTACT ? tfit_contact_force_q31(m, x, out)
                                                                : tfit_displacements_q31(m, x, out);
            snprintf(label, sizeof label, "set=%zu family=%u vec=%u status=%d", 20 + s,
                     m->family + 10, v, (int)st);
            CALLGRIND_DUMP_STATS_AT(label);
        }
        free(out);
    }
    for (int v = 0; v < 3; ++v) {
        char label[64];
        volatile float sink;
        CALLGRIND_ZERO_STATS;
        sink = control_branchy((float)(10 * v));
        (void)sink;
        snprintf(label, sizeof label, "set=99 family=0 vec=%d status=0", v);
        CALLGRIND_DUMP_STATS_AT(label);
    }
    return 0;
}
