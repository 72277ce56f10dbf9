/*
 * random_models.c — the invariants of items 2 and 5 (invariants.h) beyond
 * the shipped headers: random models of every family from
 * tests/support/random_model.c (sizes up to the build's capacity, offset
 * and elongated ellipsoidal envelopes, coefficients over up to 240
 * binades), each with the fixed extreme inputs and N seeded random inputs,
 * float32 and (where the model has one) its Q31 form.
 *
 *   random_models MODELS SEED N
 *
 * Prints one line per family: models, inputs, the worst clamp deviations
 * (float: ulps, and as a fraction of each input's tolerance; Q31: as a
 * fraction of each model's tolerance) and how many float clamps needed the
 * projection allowance for models steep at their boundary (invariants.h).  Exits 1 on any violated
 * invariant; the failing model is named by its index (same SEED
 * reproduces it).
 */
#include <stdio.h>
#include <stdlib.h>

#include "base/blas_pin.h"
#include "inputs.h"
#include "model/q31.h"
#include "random_model.h"
#include "model/target_view.h"

#define N_FAMILIES 4

typedef struct tally {
    unsigned models, q31_models;
    uint64_t inputs, violations;
    double float_worst;            /* ulps */
    double q31_ratio;              /* worst deviation / tolerance */
    uint64_t sensitive;            /* float clamps within the projection allowance */
    double float_ratio;            /* of those, the worst deviation / its tolerance */
} tally;

static uint64_t float_form(const tf_model *m, const char *label, uint64_t n, uint64_t seed,
                           tally *t)
{
    tfit_model view;
    stab_float c;
    tf_target_view(m, &view);
    if (tfit_model_check(&view) != TFIT_OK || stab_float_init(&c, &view, label) != 0) {
        fprintf(stderr, "%s: model check failed or out of memory\n", label);
        return 1;
    }
    uint64_t bad = stab_extremes_float(&c) + stab_random_float(&c, n, seed);
    t->inputs += c.st.n;
    t->float_worst = c.st.worst > t->float_worst ? c.st.worst : t->float_worst;
    t->sensitive += c.st.sensitive;
    t->float_ratio = c.st.worst_ratio > t->float_ratio ? c.st.worst_ratio : t->float_ratio;
    stab_float_free(&c);
    return bad;
}

static uint64_t q31_form(const tf_model *m, const char *label, uint64_t n, uint64_t seed,
                         tally *t)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_q31 *q = tf_q31_quantise(&ctx, m);
    if (q == NULL) { /* modal, zhou2017, or an envelope beyond the headroom */
        return 0;
    }
    tfit_model_q31 view;
    stab_q31 c;
    tf_target_view_q31(q, &view);
    uint64_t bad = 0;
    if (tfit_model_check_q31(&view) != TFIT_OK || stab_q31_init(&c, &view, label) != 0) {
        fprintf(stderr, "%s: Q31 model check failed or out of memory\n", label);
        bad = 1;
    } else {
        bad = stab_extremes_q31(&c) + stab_random_q31(&c, n, seed);
        t->q31_models++;
        t->inputs += c.st.n;
        t->q31_ratio = c.st.worst / c.tol > t->q31_ratio ? c.st.worst / c.tol : t->q31_ratio;
        stab_q31_free(&c);
    }
    tf_q31_free(q);
    return bad;
}

int main(int argc, char **argv)
{
    tf_blas_pin(argv); /* the Q31 quantisation calls LAPACK: same bits everywhere */
    if (argc != 4) {
        fprintf(stderr, "usage: random_models MODELS SEED N\n");
        return 2;
    }
    const unsigned models = (unsigned)strtoul(argv[1], NULL, 10);
    const uint64_t seed = strtoull(argv[2], NULL, 10), n = strtoull(argv[3], NULL, 10);
    static const char *const names[N_FAMILIES] = {"nodal", "modal", "zhou2017", "contact"};
    tally t[N_FAMILIES] = {{0}};
    tf_rng r = {seed};
    uint64_t bad = 0;
    for (unsigned i = 0; i < models; ++i) {
        const tfit_family f = (tfit_family)(1 + i % N_FAMILIES);
        tf_model *m = tf_random_model(&r, "random", f, 0);
        if (m == NULL) {
            fprintf(stderr, "random_models: out of memory\n");
            return 1;
        }
        char label[64];
        snprintf(label, sizeof label, "random model %u (%s)", i, names[f - 1]);
        tally *ft = &t[f - 1];
        ft->models++;
        uint64_t v = float_form(m, label, n, seed + i, ft) + q31_form(m, label, n, seed + i, ft);
        ft->violations += v;
        bad += v;
        tf_model_free(m);
    }
    for (int f = 0; f < N_FAMILIES; ++f) {
        printf("random %-8s %3u models (%3u with Q31) %8llu inputs: worst clamp %.3g ulps "
               "(float; %llu beyond %g, within the projection allowance, worst %.2f of it), "
               "%.2f of the tolerance (Q31); %llu violations\n",
               names[f], t[f].models, t[f].q31_models, (unsigned long long)t[f].inputs,
               t[f].float_worst, (unsigned long long)t[f].sensitive, STAB_FLOAT_TOL_ULPS,
               t[f].float_ratio, t[f].q31_ratio, (unsigned long long)t[f].violations);
    }
    return bad == 0 ? 0 : 1;
}
