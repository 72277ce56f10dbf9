/*
 * shared_ops.c — tf_family operations that several families share
 * (common.h): applicability of the general ones, the degree as text, the
 * float64 form of the polynomial families, and the cost of a model from
 * its layout.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fitting/families/common.h"
#include "model/basis.h"

int tf_family_always(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan)
{
    (void)ctx;
    (void)c;
    (void)plan;
    return 0;
}

void tf_family_degree_text(const tf_model *m, int style, char *buf, size_t n)
{
    (void)style;
    snprintf(buf, n, "p=%u", m->dims[0]);
}

void tf_family_rank_text(const tf_model *m, int style, char *buf, size_t n)
{
    (void)style;
    snprintf(buf, n, "p=%u r=%u", m->dims[0], m->dims[1]);
}

/* The model's inputs and its truth at case i of d, by the family's kind. */
static const double *input_of(int inverse, const tf_fitdata *d, size_t i)
{
    return inverse ? d->contact[i] : d->force[i];
}

static const double *truth_of(int inverse, const tf_fitdata *d, size_t i, size_t rows)
{
    return inverse ? d->force[i] : d->u + rows * i;
}

int tf_family_poly_f64_errors(tf_ctx *ctx, const tf_model *m, const tf_cases *c, double *max,
                              double *rms)
{
    const tf_family *f = tf_family_of(m->family);
    const int inverse = f != NULL && f->kind == TF_FAMILY_INVERSE;
    const tf_fitdata *train = &c->train, *held = &c->heldout;
    const uint32_t p = m->dims[0], t = tf_terms(p);
    const size_t rows = 3 * (size_t)m->n_out, n = train->n_cases;
    double *a = tf_family_design(m, inverse ? train->contact : train->force, NULL, n, p);
    double *y = malloc(n * rows * sizeof *y);
    double *x = malloc(t * rows * sizeof *x), *phi = malloc(t * sizeof *phi);
    int rc = (a && y && x && phi) ? 0 : -1;
    if (rc != 0) {
        tf_fail(ctx, "%s float64 form: out of memory", m->name);
    }
    for (size_t i = 0; rc == 0 && i < n; ++i) {
        for (size_t o = 0; o < rows; ++o) {
            y[i + o * n] = truth_of(inverse, train, i, rows)[o];
        }
    }
    if (rc == 0) {
        rc = tf_family_lsq(ctx, a, n, t, y, rows, x);
    }
    double emax = 0, sum2 = 0;
    for (size_t i = 0; rc == 0 && i < held->n_cases; ++i) {
        double g[3];
        tf_family_normalise(m, input_of(inverse, held, i), g);
        tf_basis(p, g, phi);
        const double *truth = truth_of(inverse, held, i, rows);
        for (size_t o = 0; o < rows; ++o) {
            double v = 0;
            for (uint32_t k = 0; k < t; ++k) {
                v += x[k + o * t] * phi[k];
            }
            emax = fmax(emax, fabs(v - truth[o]));
            sum2 += (v - truth[o]) * (v - truth[o]);
        }
    }
    if (rc == 0) {
        *max = emax;
        *rms = sqrt(sum2 / ((double)held->n_cases * (double)rows));
    }
    free(a);
    free(y);
    free(x);
    free(phi);
    return rc;
}

void tf_family_layout_cost(const tf_model *m, tf_family_cost *out)
{
    out->ops = tf_model_ops(m);
    out->table_bytes = tf_model_table_bytes(m);
    out->m4f = tf_model_cycles(m, TF_CORE_M4F);
    out->m7 = tf_model_cycles(m, TF_CORE_M7);
}
