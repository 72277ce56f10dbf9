/*
 * common.c — see common.h.
 */
#include "fitting/families/common.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/basis.h"
#include <lapacke.h>
#include <math.h>
#include "numerics/lsq.h"

/* Relative rank tolerance on the column-scaled R diagonal: terms the data
 * cannot separate from the others get coefficient 0 (lsq.h). */
#define FIT_RANK_TOL 1e-10

void tf_family_normalise(const tf_model *m, const double x[3], double g[3])
{
    const float *x0 = m->coef, *w = m->coef + 3;
    double d[3];
    for (int i = 0; i < 3; ++i) {
        d[i] = x[i] - (double)x0[i];
    }
    for (int i = 0; i < 3; ++i) {
        g[i] = (double)w[3 * i] * d[0] + (double)w[3 * i + 1] * d[1] + (double)w[3 * i + 2] * d[2];
    }
}

double *tf_family_design(const tf_model *m, const double (*x)[3], const size_t *idx, size_t n,
                         uint32_t p)
{
    uint32_t t = tf_terms(p);
    double *a = malloc(n * t * sizeof *a);
    double *phi = malloc(t * sizeof *phi);
    if (a == NULL || phi == NULL) {
        free(a);
        free(phi);
        return NULL;
    }
    for (size_t i = 0; i < n; ++i) {
        double g[3];
        tf_family_normalise(m, x[tf_family_case(idx, i)], g);
        tf_basis(p, g, phi);
        for (uint32_t k = 0; k < t; ++k) {
            a[i + k * n] = phi[k];
        }
    }
    free(phi);
    return a;
}

double *tf_family_gather_u(const tf_fitdata *d, const size_t *idx, size_t m)
{
    size_t rows = 3 * (size_t)d->n_out;
    double *y = malloc(m * rows * sizeof *y);
    if (y == NULL) {
        return NULL;
    }
    for (size_t i = 0; i < m; ++i) {
        const double *col = d->u + rows * tf_family_case(idx, i);
        for (size_t o = 0; o < rows; ++o) {
            y[i + o * m] = col[o];
        }
    }
    return y;
}

int tf_family_lsq(tf_ctx *ctx, const double *a, size_t m, size_t n, const double *y, size_t k,
                  double *x)
{
    tf_lsq *f = tf_lsq_factor(ctx, m, n, a, m, NULL, FIT_RANK_TOL);
    if (f == NULL) {
        return -1;
    }
    if (tf_lsq_rank(f) < n) {
        tf_fail(ctx,
                TF_FAMILY_UNDETERMINED
                ": %zu cases determine only %zu of %zu coefficients "
                "(repeated or collinear load cases, or too few for this order)",
                m, tf_lsq_rank(f), n);
        tf_lsq_free(f);
        return -1;
    }
    int rc = tf_lsq_solve(ctx, f, k, y, m, x, n, NULL);
    tf_lsq_free(f);
    return rc;
}

void tf_family_forward_setup(tf_model *model, const tf_fitdata *d)
{
    memcpy(model->node_ids, d->node_ids, d->n_out * sizeof *d->node_ids);
    tf_model_set_ball(model, d->centre, d->radius);
}

tf_model *tf_family_forward_model(tf_ctx *ctx, const char *name, tfit_family family,
                                  const uint32_t *dims, uint32_t n_dims, uint32_t p,
                                  const tf_fitdata *d, const size_t *idx, size_t m)
{
    tf_model *model = tf_model_new(ctx, name, family, d->n_out, dims, n_dims);
    if (model == NULL) {
        return NULL;
    }
    tf_family_forward_setup(model, d);
    if (p > 0 && tf_family_spans(ctx, model, d->force, idx, m) != 0) {
        tf_model_free(model);
        return NULL;
    }
    return model;
}

#define SPAN_MIN 1e-3 /* RMS extent, as a fraction of the envelope radius */

int tf_family_spans(tf_ctx *ctx, const tf_model *m, const double (*x)[3], const size_t *idx,
                    size_t n)
{
    double mom[9] = {0}, eig[3];
    for (size_t i = 0; i < n; ++i) {
        double g[3];
        if (m != NULL) {
            tf_family_normalise(m, x[tf_family_case(idx, i)], g);
        } else {
            memcpy(g, x[tf_family_case(idx, i)], sizeof g);
        }
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) {
                mom[3 * a + b] += g[a] * g[b] / (double)n;
            }
        }
    }
    if (LAPACKE_dsyev(LAPACK_ROW_MAJOR, 'V', 'U', 3, mom, 3, eig) != 0) {
        return tf_fail(ctx, "the spread of the load cases could not be computed");
    }
    if (!(eig[0] >= SPAN_MIN * SPAN_MIN)) { /* ascending: eig[0] is the smallest */
        return tf_fail(ctx,
                       TF_FAMILY_UNDETERMINED
                       ": the %zu load cases barely move along (%.3f, %.3f, %.3f) "
                       "of the normalised envelope (RMS extent %.2g of its radius): the fit would "
                       "extrapolate there",
                       n, mom[0], mom[3], mom[6], sqrt(fmax(eig[0], 0)));
    }
    return 0;
}

int tf_family_history_cv(size_t n, size_t folds, int kmax, tf_family_history_fold fold, void *ctx,
                         double *cv)
{
    size_t *train = malloc(2 * n * sizeof *train), *valid = train + n;
    if (train == NULL) {
        return -1;
    }
    for (int k = 0; k <= kmax; ++k) {
        double sum2 = 0;
        size_t count = 0;
        cv[k] = INFINITY;
        for (size_t f = 0; f < folds; ++f) {
            size_t nt = 0, nv = 0;
            for (size_t i = 0; i < n; ++i) {
                if (i % folds != f) {
                    train[nt++] = i;
                } else {
                    valid[nv++] = i;
                }
            }
            double r;
            if (fold(ctx, k, train, nt, valid, nv, &r) != 0) {
                break;
            }
            sum2 += r * r * (double)nv;
            count += nv;
        }
        if (count == n) {
            cv[k] = sqrt(sum2 / (double)n);
        }
    }
    free(train);
    return 0;
}
