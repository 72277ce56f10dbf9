/*
 * nist_fit.c — one NIST StRD run through tf_lsfit, scored in correct digits
 * (see nist_fit.h).
 */
#include "numerics/nist_fit.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

double tf_lre(double estimate, double certified)
{
    if (!isfinite(estimate)) {
        return 0;
    }
    double rel = certified != 0 ? fabs(estimate - certified) / fabs(certified)
                                : fabs(estimate);
    if (rel == 0) {
        return TF_LRE_CAP;
    }
    return fmin(TF_LRE_CAP, fmax(0, -log10(rel)));
}

/* The response as fitted: log y for the models of log y (Nelson). */
static double response(const tf_nist_model *model, double y)
{
    return model->log_response ? log(y) : y;
}

double tf_nist_rss_resolution(const tf_nist *d, const tf_nist_model *model)
{
    double ymax = 0;
    for (size_t i = 0; i < d->n_obs; ++i) {
        ymax = fmax(ymax, fabs(response(model, d->y[i])));
    }
    double delta = sqrt((double)d->n_obs) * DBL_EPSILON * ymax;
    return 2 * sqrt(d->certified_rss) * delta + delta * delta;
}

const tf_nist_model *tf_nist_match(tf_ctx *ctx, const tf_nist *d, const char *path)
{
    const tf_nist_model *m = tf_nist_model_find(d->model);
    if (m == NULL) {
        tf_fail(ctx, "%s:%zu: unknown model '%s' (not one of the NIST StRD models)", path,
                d->model_line, d->model);
    } else if (m->n_par != d->n_par || m->n_x != d->n_x) {
        tf_fail(ctx,
                "%s:%zu: the model '%s' has %zu parameters and %zu predictors, the file %zu "
                "and %zu",
                path, d->model_line, d->model, m->n_par, m->n_x, d->n_par, d->n_x);
        m = NULL;
    }
    return m;
}

int tf_nist_load(tf_ctx *ctx, const char *dir, const char *name, tf_nist *d,
                 const tf_nist_model **model)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s.dat", dir, name);
    if (tf_nist_read(ctx, path, d) != 0) {
        return -1;
    }
    *model = tf_nist_match(ctx, d, path);
    if (*model == NULL) {
        tf_nist_free(d);
        return -1;
    }
    return 0;
}

void tf_nist_options(tf_lsfit_options *o, size_t n_par)
{
    tf_lsfit_default_options(o, n_par);
    o->lm.ftol = 1e-15;
    o->lm.xtol = 1e-15;
    o->lm.gtol = 0;
    o->lm.max_evals = 10000;
}

typedef struct run_ctx {
    const tf_nist *d;
    const tf_nist_model *model;
} run_ctx;

static int values(void *ctx, const double *b, double *f)
{
    const run_ctx *c = ctx;
    for (size_t i = 0; i < c->d->n_obs; ++i) {
        f[i] = c->model->f(b, c->d->x + i * c->d->n_x, NULL);
    }
    return 0;
}

static int jacobian(void *ctx, const double *b, double *jac)
{
    const run_ctx *c = ctx;
    const size_t m = c->d->n_obs;
    double g[TF_NIST_MAX_PAR];
    for (size_t i = 0; i < m; ++i) {
        c->model->f(b, c->d->x + i * c->d->n_x, g);
        for (size_t j = 0; j < c->d->n_par; ++j) {
            jac[i + j * m] = g[j];
        }
    }
    return 0;
}

static void score(const tf_nist *d, const tf_lsfit_result *r, tf_nist_score *s)
{
    s->min_lre = TF_LRE_CAP;
    for (size_t j = 0; j < d->n_par; ++j) {
        s->estimate[j] = r->par[j];
        s->lre[j] = tf_lre(r->par[j], d->certified[j]);
        s->se[j] = r->se[j];
        s->se_lre[j] = tf_lre(r->se[j], d->certified_sd[j]);
        s->min_lre = fmin(s->min_lre, s->lre[j]);
    }
    s->rss = r->rss[0];
    s->rss_lre = tf_lre(r->rss[0], d->certified_rss);
    s->min_lre = fmin(s->min_lre, s->rss_lre);
    s->stop = r->stop;
    s->iterations = r->iterations;
    s->evals = r->evals;
    s->jac_evals = r->jac_evals;
}

int tf_nist_fit(tf_ctx *ctx, const tf_nist *d, const tf_nist_model *model, int start,
                const tf_lsfit_options *o, int finite_diff, tf_nist_score *s)
{
    if (start != 1 && start != 2) {
        return tf_fail(ctx, "start must be 1 or 2, not %d", start);
    }
    double *y = malloc(d->n_obs * sizeof *y);
    if (y == NULL) {
        return tf_fail(ctx, "out of memory");
    }
    for (size_t i = 0; i < d->n_obs; ++i) {
        y[i] = response(model, d->y[i]);
    }
    run_ctx c = {d, model};
    tf_lsfit_model fm = {.n_par = d->n_par, .value = values,
                       .jacobian = finite_diff ? NULL : jacobian, .ctx = &c};
    tf_lsfit_data data = {.n_obs = d->n_obs, .n_rhs = 1, .y = y};
    tf_lsfit_options opt = *o;
    opt.start = d->start[start - 1];
    tf_lsfit_result r;
    int rc = tf_lsfit(ctx, &fm, &data, &opt, &r);
    free(y);
    if (rc != 0) {
        return -1;
    }
    score(d, &r, s);
    tf_lsfit_result_free(&r);
    return 0;
}
