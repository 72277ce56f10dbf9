/*
 * run_invariants.c — issue 7 items 2 and 5 on every model of one generated
 * header, float32 and Q31 forms:
 *
 *   run_invariants extremes          the fixed extreme inputs (inputs.h)
 *   run_invariants random N SEED     N seeded random inputs per model and form
 *
 * One line per model and form: statuses seen, clamped results compared with
 * the boundary, the worst deviation against its tolerance, and the input
 * that gave it.  Exits 1 on any violated invariant or failed model check.
 *
 * Compiled per header with -DGOLDEN_H='"NAME_golden.h"',
 * -DGOLDEN_SETS=TFIT_NAME_GOLDEN_SETS, -DGOLDEN_Q31_SETS=..._GOLDEN_Q31_SETS
 * and -DTFIT_NAME_IMPLEMENTATION (like tests/header/run_golden.c): the
 * golden sets list every model of the header.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include GOLDEN_H
#include "inputs.h"

static const char *family_name(uint32_t f)
{
    static const char *const names[] = {"?",     "nodal", "modal",    "zhou2017", "contact",
                                        "prony", "cut",   "resonant", "modal_q15"};
    return f < sizeof names / sizeof names[0] ? names[f] : "?";
}

static double seconds(clock_t t0)
{
    return (double)(clock() - t0) / CLOCKS_PER_SEC;
}

typedef struct run {
    int random;
    uint64_t n, seed;
    const char *header;
} run;

static uint64_t float_model(const run *rn, size_t i, const tfit_model *m)
{
    char label[96];
    snprintf(label, sizeof label, "%s float %zu %s n_out=%u", rn->header, i, family_name(m->family),
             m->n_out);
    stab_float c;
    if (tfit_model_check(m) != TFIT_OK || stab_float_init(&c, m, label) != 0) {
        fprintf(stderr, "%s: model check failed or out of memory\n", label);
        return 1;
    }
    const clock_t t0 = clock();
    uint64_t bad = rn->random ? stab_random_float(&c, rn->n, rn->seed + i) : stab_extremes_float(&c);
    stab_print(0, label, &c.st, STAB_FLOAT_TOL_ULPS, seconds(t0));
    stab_float_free(&c);
    return bad;
}

static uint64_t q31_model(const run *rn, size_t i, const tfit_model_q31 *m)
{
    char label[96];
    snprintf(label, sizeof label, "%s q31 %zu %s n_out=%u", rn->header, i, family_name(m->family),
             m->n_out);
    stab_q31 c;
    if (tfit_model_check_q31(m) != TFIT_OK || stab_q31_init(&c, m, label) != 0) {
        fprintf(stderr, "%s: model check failed or out of memory\n", label);
        return 1;
    }
    const clock_t t0 = clock();
    uint64_t bad = rn->random ? stab_random_q31(&c, rn->n, rn->seed + 1000 + i) : stab_extremes_q31(&c);
    stab_print(1, label, &c.st, c.tol, seconds(t0));
    stab_q31_free(&c);
    return bad;
}

static int usage(void)
{
    fprintf(stderr, "usage: run_invariants [-l LABEL] extremes | random N SEED\n");
    return 2;
}

int main(int argc, char **argv)
{
    static const tfit_golden *const sets[] = GOLDEN_SETS;
    static const tfit_golden_q31 *const q31_sets[] = GOLDEN_Q31_SETS;
    run rn = {0, 0, 0, "header"};
    int a = 1;
    if (argc > 2 && strcmp(argv[1], "-l") == 0) {
        rn.header = argv[2];
        a = 3;
    }
    if (argc == a + 1 && strcmp(argv[a], "extremes") == 0) {
        rn.random = 0;
    } else if (argc == a + 3 && strcmp(argv[a], "random") == 0) {
        rn.random = 1;
        rn.n = strtoull(argv[a + 1], NULL, 10);
        rn.seed = strtoull(argv[a + 2], NULL, 10);
    } else {
        return usage();
    }
    uint64_t bad = 0;
    for (size_t i = 0; i < sizeof sets / sizeof sets[0]; ++i) {
        bad += float_model(&rn, i, sets[i]->model);
    }
    for (size_t i = 0; q31_sets[i] != NULL; ++i) {
        bad += q31_model(&rn, i, q31_sets[i]->model);
    }
    if (bad != 0) {
        fprintf(stderr, "%s: %llu invariant violations\n", rn.header, (unsigned long long)bad);
        return 1;
    }
    return 0;
}
