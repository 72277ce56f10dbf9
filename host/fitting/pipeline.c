/*
 * pipeline.c — the fitting pipeline (pipeline.h).
 */
#include "fitting/pipeline.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fitting/fit_common.h"
#include "fitting/families/family.h"
#include "base/log.h"
#include "model/ref_eval.h"

/* Below this CV error a higher order buys nothing the float32 target can
 * show (mm or N). */
#define CV_FLOOR 1e-6

static double seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The smallest index whose value is within 2 % (plus the floor) of the best. */
static uint32_t cheapest_within(const double *v, uint32_t lo, uint32_t hi)
{
    double best = INFINITY;
    for (uint32_t i = lo; i <= hi; ++i) {
        best = fmin(best, v[i]);
    }
    for (uint32_t i = lo; i <= hi; ++i) {
        if (v[i] <= 1.02 * best + CV_FLOOR) {
            return i;
        }
    }
    return lo;
}

/* Degrees p in [lo, max] by CV; a degree with more terms than a training
 * fold has cases is not tried (its CV error is infinite). */
static int select_degree(const tf_fitdata *d, tf_fitter fit, const tf_fit_plan *plan, uint32_t lo,
                         uint32_t extra, double *cv, uint32_t *best, char *err, size_t errlen)
{
    size_t fold_cases = d->n_cases - (d->n_cases + plan->folds - 1) / plan->folds;
    uint32_t hi = lo;
    for (uint32_t p = 0; p <= TFIT_MAX_DEGREE; ++p) {
        cv[p] = INFINITY;
        if (p < lo || p > plan->max_degree || tf_terms(p) > fold_cases) {
            continue;
        }
        uint32_t orders[2] = {p, extra};
        if (tf_cv_error(d, fit, orders, plan->folds, plan->seed, &cv[p], NULL, err, errlen) != 0) {
            return -1;
        }
        hi = p;
    }
    *best = cheapest_within(cv, lo, hi);
    if (!isfinite(cv[*best])) {
        snprintf(err, errlen,
                 "%s: no degree is determined by the %zu training cases (repeated or collinear "
                 "load cases?)",
                 TF_FIT_UNDETERMINED, d->n_cases);
        return -1;
    }
    return 0;
}

static void heldout(tf_family_fit *f, const tf_fitdata *d)
{
    tf_model_errors(f->model, d, NULL, d->n_cases, &f->heldout_max, &f->heldout_rms,
                    &f->heldout_rel_max);
    f->model->heldout_max = f->heldout_max;
    f->model->heldout_rms = f->heldout_rms;
    f->model->heldout_rel_max = f->heldout_rel_max;
    f->model->heldout_cases = (uint32_t)d->n_cases;
}

/* Seed Table 3 and the mean deviation maps (pipeline.h).  Returns 0, or -1
 * with a message in ctx. */
static int seed_table(tf_family_fit *f, tf_cases *c, tf_ctx *ctx)
{
    const tf_fitdata *d = &c->train;
    const size_t rows = 3 * (size_t)d->n_out;
    float *out = malloc(rows * sizeof *out);
    double *truth = malloc(rows * sizeof *truth);
    f->deviation = calloc(9 * (size_t)d->n_out, sizeof *f->deviation);
    if (out == NULL || truth == NULL || f->deviation == NULL) {
        free(out);
        free(truth);
        return tf_fail(ctx, "out of memory for the error maps");
    }
    for (int a = 0; a < 3; ++a) {
        double sum2[3] = {0, 0, 0};
        for (int level = 1; level <= TF_FIT_LEVELS; ++level) {
            double s = d->radius * level / TF_FIT_LEVELS, f3[3] = {0, 0, 0};
            f3[a] = (double)(float)(d->centre[a] + s);
            const float in[3] = {(float)d->centre[0], (float)d->centre[1], (float)d->centre[2]};
            float fin[3] = {in[0], in[1], in[2]};
            fin[a] = (float)f3[a];
            for (int k = 0; k < 3; ++k) {
                f3[k] = (double)fin[k];
            }
            if (tf_cases_response(c, f3, truth, NULL) != 0) {
                free(out);
                free(truth);
                return -1;
            }
            tf_ref_eval(f->model, fin, out, NULL);
            for (size_t j = 0; j < d->n_out; ++j) {
                for (int comp = 0; comp < 3; ++comp) {
                    double e = (double)out[3 * j + (size_t)comp] - truth[3 * j + (size_t)comp];
                    sum2[comp] += (e / s) * (e / s);
                    f->deviation[((size_t)a * 3 + (size_t)comp) * d->n_out + j] +=
                        e / TF_FIT_LEVELS;
                }
            }
        }
        for (int comp = 0; comp < 3; ++comp) {
            f->table3[a][comp] = sqrt(sum2[comp] / (TF_FIT_LEVELS * (double)d->n_out));
        }
    }
    free(out);
    free(truth);
    return 0;
}

static int fit_nodal(tf_fit_outcome *o, const tf_fit_plan *plan, char *err, size_t errlen)
{
    tf_family_fit *f = &o->fam[TFIT_FAMILY_NODAL];
    uint32_t p;
    if (select_degree(&o->cases.train, tf_fit_nodal, plan, 0, 0, f->cv, &p, err, errlen) != 0) {
        return -1;
    }
    f->model = tf_fit_nodal(&o->cases.train, NULL, o->cases.train.n_cases, &p, "nodal", err,
                            errlen);
    return f->model ? 0 : -1;
}

static int fit_contact(tf_fit_outcome *o, const tf_fit_plan *plan, char *err, size_t errlen)
{
    tf_family_fit *f = &o->fam[TFIT_FAMILY_CONTACT];
    uint32_t p;
    if (select_degree(&o->cases.train, tf_fit_contact, plan, 1, 0, f->cv, &p, err, errlen) != 0) {
        return -1;
    }
    f->model = tf_fit_contact(&o->cases.train, NULL, o->cases.train.n_cases, &p, "contact", err,
                              errlen);
    return f->model ? 0 : -1;
}

/* Modal: the degree by CV at the largest rank searched, then the rank by CV
 * at that degree; the held-out error of every rank for the report. */
static int fit_modal(tf_fit_outcome *o, const tf_fit_plan *plan, char *err, size_t errlen)
{
    tf_family_fit *f = &o->fam[TFIT_FAMILY_MODAL];
    const tf_fitdata *d = &o->cases.train;
    const size_t fold_cases = d->n_cases - (d->n_cases + plan->folds - 1) / plan->folds;
    uint32_t rmax = plan->max_rank;
    if (rmax > TF_FIT_MAX_RANK) {
        rmax = TF_FIT_MAX_RANK;
    }
    if (rmax > fold_cases) {
        rmax = (uint32_t)fold_cases;
    }
    uint32_t p;
    if (select_degree(d, tf_fit_modal, plan, 0, rmax, f->cv, &p, err, errlen) != 0) {
        return -1;
    }
    f->cv_rank[0] = INFINITY;
    for (uint32_t r = 1; r <= TF_FIT_MAX_RANK; ++r) {
        const uint32_t orders[2] = {p, r};
        f->cv_rank[r] = INFINITY;
        o->rank_max[r] = INFINITY;
        if (r > rmax) {
            continue;
        }
        if (tf_cv_error(d, tf_fit_modal, orders, plan->folds, plan->seed, &f->cv_rank[r], NULL,
                        err, errlen) != 0) {
            return -1;
        }
        tf_model *m = tf_fit_modal(d, NULL, d->n_cases, orders, "modal", err, errlen);
        if (m == NULL) {
            return -1;
        }
        tf_model_errors(m, &o->cases.heldout, NULL, o->cases.heldout.n_cases, &o->rank_max[r],
                        NULL, NULL);
        if (o->rank_10um == 0 && o->rank_max[r] <= 0.010) {
            o->rank_10um = r;
        }
        tf_model_free(m);
    }
    const uint32_t orders[2] = {p, cheapest_within(f->cv_rank, 1, rmax)};
    f->model = tf_fit_modal(d, NULL, d->n_cases, orders, "modal", err, errlen);
    return f->model ? 0 : -1;
}

static int fit_zhou(tf_fit_outcome *o, const tf_fit_plan *plan, char *err, size_t errlen)
{
    tf_family_fit *f = &o->fam[TFIT_FAMILY_ZHOU2017];
    if (tf_zhou_applicable(&o->cases.train, f->why, sizeof f->why) != 0) {
        f->applicable = 0;
        return 0;
    }
    const tf_fitdata *axis[3] = {&o->cases.axis[0], &o->cases.axis[1], &o->cases.axis[2]};
    f->zhou_cv = malloc(sizeof *f->zhou_cv);
    if (f->zhou_cv == NULL ||
        tf_zhou_select(axis, plan->folds, plan->seed, &f->zhou, f->zhou_cv, err, errlen) != 0) {
        return -1;
    }
    f->model = tf_fit_zhou2017(axis, &f->zhou, "zhou2017", err, errlen);
    return f->model ? 0 : -1;
}

static int run_family(tf_ctx *ctx, tf_fit_outcome *o, const tf_fit_plan *plan, tfit_family fam)
{
    char *err = ctx->err;
    const size_t errlen = sizeof ctx->err;
    tf_family_fit *f = &o->fam[fam];
    double t0 = seconds();
    int rc;
    f->applicable = 1;
    tf_info(ctx, "fit: %s: choosing orders by %u-fold cross-validation", tf_family_name(fam),
            plan->folds);
    switch (fam) {
    case TFIT_FAMILY_NODAL:
        rc = fit_nodal(o, plan, err, errlen);
        break;
    case TFIT_FAMILY_MODAL:
        rc = fit_modal(o, plan, err, errlen);
        break;
    case TFIT_FAMILY_ZHOU2017:
        rc = fit_zhou(o, plan, err, errlen);
        break;
    default:
        rc = fit_contact(o, plan, err, errlen);
        break;
    }
    if (rc != 0 || !f->applicable) {
        return rc;
    }
    heldout(f, &o->cases.heldout);
    if (fam != TFIT_FAMILY_CONTACT && seed_table(f, &o->cases, ctx) != 0) {
        return -1;
    }
    f->seconds = seconds() - t0;
    tf_info(ctx, "fit: %s: held-out max %.3g %s, rms %.3g (%.2f s)", tf_family_name(fam),
            f->heldout_max, fam == TFIT_FAMILY_CONTACT ? "N" : "mm", f->heldout_rms, f->seconds);
    return 0;
}

/* Small-strain elasticity stops describing tissue when displacements
 * approach the body's size; the model still reproduces the solve, which is
 * what its error measures, so this is a warning, not a refusal. */
static void warn_large(const tf_ctx *ctx, const tf_problem *p, const tf_fitdata *d)
{
    double biggest = 0, body = INFINITY, lo[3], hi[3];
    for (size_t i = 0; i < 3 * (size_t)d->n_out * d->n_cases; ++i) {
        biggest = fmax(biggest, fabs(d->u[i]));
    }
    tf_problem_bounds(p, lo, hi);
    for (int a = 0; a < 3; ++a) {
        body = fmin(body, hi[a] - lo[a]);
    }
    if (biggest > 0.1 * body) {
        tf_info(ctx, "fit: warning: displacements reach %.3g mm on a body %.3g mm thick: linear "
                "(small-strain) elasticity does not describe tissue there; the models reproduce "
                "the linear solve",
                biggest, body);
    }
}

int tf_fit_run(const tf_problem *p, tf_solver *solver, const tf_fit_plan *plan,
               tf_fit_outcome *o)
{
    tf_ctx *ctx = solver->ctx;
    memset(o, 0, sizeof *o);
    double t0 = seconds();
    if (tf_cases_build(p, solver, plan->contact, plan->n_train, plan->n_heldout, plan->seed,
                       plan->direct, &o->cases) != 0) {
        return -1;
    }
    o->seconds_cases = seconds() - t0;
    warn_large(ctx, p, &o->cases.train);
    if (plan->family == TFIT_FAMILY_ZHOU2017 &&
        tf_zhou_applicable(&o->cases.train, ctx->err, sizeof ctx->err) != 0) {
        tf_fit_outcome_free(o);
        return -2; /* refuse before any fitting */
    }
    static const tfit_family order[] = {TFIT_FAMILY_NODAL, TFIT_FAMILY_MODAL,
                                        TFIT_FAMILY_ZHOU2017, TFIT_FAMILY_CONTACT};
    for (size_t i = 0; i < sizeof order / sizeof order[0]; ++i) {
        if (run_family(ctx, o, plan, order[i]) != 0) {
            tf_fit_outcome_free(o);
            return -1;
        }
    }
    if (!o->fam[plan->family].applicable) {
        tf_fail(ctx, "%s", o->fam[plan->family].why);
        tf_fit_outcome_free(o);
        return -2;
    }
    return 0;
}

void tf_fit_outcome_free(tf_fit_outcome *o)
{
    for (int f = 1; f <= 4; ++f) {
        tf_model_free(o->fam[f].model);
        free(o->fam[f].deviation);
        free(o->fam[f].zhou_cv);
        o->fam[f].model = NULL;
        o->fam[f].deviation = NULL;
        o->fam[f].zhou_cv = NULL;
    }
    tf_cases_free(&o->cases);
}
