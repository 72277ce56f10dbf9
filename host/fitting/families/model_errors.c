/*
 * model_errors.c — errors of a fitted model on solved cases, and k-fold
 * cross-validation.  Errors are those of the float32 target (the reference
 * evaluator reproduces its bits) fed with the float32-rounded input.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fitting/cv_folds.h"
#include "fitting/families/common.h"
#include "fitting/families/family.h"
#include "model/ref_eval.h"

void tf_family_errors(const tf_model *model, const tf_fitdata *d, const size_t *idx, size_t m,
                      double *max, double *rms, double *rel_max)
{
    const tf_family *f = tf_family_of(model->family);
    const int contact = f != NULL && f->kind == TF_FAMILY_INVERSE;
    const size_t rows = 3 * (size_t)model->n_out;
    float *out = malloc(rows * sizeof *out);
    double emax = 0, sum2 = 0, rmax = 0;
    for (size_t i = 0; i < m; ++i) {
        size_t n = tf_family_case(idx, i);
        const double *x = contact ? d->contact[n] : d->force[n];
        const float in[3] = {(float)x[0], (float)x[1], (float)x[2]};
        tf_ref_eval(model, in, out, NULL);
        const double *truth = contact ? d->force[n] : d->u + 3 * (size_t)d->n_out * n;
        double e2 = 0, t2 = 0;
        for (size_t o = 0; o < rows; ++o) {
            double e = (double)out[o] - truth[o];
            emax = fmax(emax, fabs(e));
            sum2 += e * e;
            e2 += e * e;
            t2 += truth[o] * truth[o];
        }
        if (contact && t2 > 0) {
            rmax = fmax(rmax, sqrt(e2 / t2));
        }
    }
    free(out);
    if (max) {
        *max = emax;
    }
    if (rms) {
        *rms = m > 0 ? sqrt(sum2 / ((double)m * rows)) : 0;
    }
    if (rel_max) {
        *rel_max = contact ? rmax : NAN;
    }
}

int tf_family_cv_error(tf_ctx *ctx, const tf_family *family, const tf_cases *c,
                       const uint32_t *orders, unsigned folds, uint64_t seed, double *rms,
                       double *max)
{
    const tf_fitdata *d = &c->train;
    const size_t n = d->n_cases;
    unsigned *fold = malloc(n * sizeof *fold);
    size_t *train = malloc(n * sizeof *train), *test = malloc(n * sizeof *test);
    double sum2 = 0, emax = 0;
    size_t count = 0;
    int rc = 0;
    if (fold == NULL || train == NULL || test == NULL) {
        tf_fail(ctx, "cross-validation: out of memory");
        rc = -1;
    }
    if (rc == 0) {
        tf_cv_folds(n, folds, seed, fold);
    }
    for (unsigned f = 0; rc == 0 && f < folds; ++f) {
        size_t n_train = tf_cv_select(fold, n, f, 0, train);
        size_t n_test = tf_cv_select(fold, n, f, 1, test);
        tf_model *m = family->fit(ctx, c, train, n_train, orders);
        if (m == NULL &&
            strncmp(ctx->err, TF_FAMILY_UNDETERMINED, strlen(TF_FAMILY_UNDETERMINED)) == 0) {
            sum2 = emax = INFINITY; /* the folds cannot determine this order */
            count = 1;
            break;
        }
        if (m == NULL) {
            rc = -1;
            break;
        }
        double fmax_err, frms;
        tf_family_errors(m, d, test, n_test, &fmax_err, &frms, NULL);
        size_t rows = 3 * (size_t)m->n_out;
        sum2 += frms * frms * (double)(n_test * rows);
        count += n_test * rows;
        emax = fmax(emax, fmax_err);
        tf_model_free(m);
    }
    free(fold);
    free(train);
    free(test);
    if (rc == 0) {
        *rms = sqrt(sum2 / (double)count);
        if (max) {
            *max = emax;
        }
    }
    return rc;
}
