/*
 * pipeline.c — the fitting pipeline (pipeline.h).
 */
#include "fitting/pipeline.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fitting/families/common.h"
#include "fitting/families/family.h"
#include "fitting/families/prony_family.h"
#include "base/clock.h"
#include "base/log.h"
#include "model/passivity.h"
#include "model/ref_eval.h"

/* The held-out errors: the static held-out cases, or the family's own
 * (a time-dependent family's held-out histories). */
static int heldout(tf_family_result *f, const tf_cases *c, tf_ctx *ctx)
{
    uint32_t n = (uint32_t)c->heldout.n_cases;
    if (f->family->heldout != NULL) {
        if (f->family->heldout(ctx, f->model, c, &f->heldout_max, &f->heldout_rms,
                               &f->heldout_rel_max, &n) != 0) {
            return -1;
        }
    } else {
        tf_family_errors(f->model, &c->heldout, NULL, c->heldout.n_cases, &f->heldout_max,
                         &f->heldout_rms, &f->heldout_rel_max);
    }
    f->model->heldout_max = f->heldout_max;
    f->model->heldout_rms = f->heldout_rms;
    f->model->heldout_rel_max = f->heldout_rel_max;
    f->model->heldout_cases = n;
    f->model->heldout_q31_max = tf_prony_q31_heldout(f->model, c); /* NAN but for prony */
    return 0;
}

/* Seed Table 3 and the mean deviation maps (pipeline.h).  Returns 0, or -1
 * with a message in ctx. */
static int seed_table(tf_family_result *f, tf_cases *c, tf_ctx *ctx)
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
        for (int level = 1; level <= TF_FAMILY_LEVELS; ++level) {
            double s = d->radius * level / TF_FAMILY_LEVELS, f3[3];
            tf_cases_level_force(d, a, level, f3);
            const float fin[3] = {(float)f3[0], (float)f3[1], (float)f3[2]};
            tf_cases_level_response(c, a, level, truth);
            tf_ref_eval(f->model, fin, out, NULL);
            for (size_t j = 0; j < d->n_out; ++j) {
                for (int comp = 0; comp < 3; ++comp) {
                    double e = (double)out[3 * j + (size_t)comp] - truth[3 * j + (size_t)comp];
                    sum2[comp] += (e / s) * (e / s);
                    f->deviation[((size_t)a * 3 + (size_t)comp) * d->n_out + j] +=
                        e / TF_FAMILY_LEVELS;
                }
            }
        }
        for (int comp = 0; comp < 3; ++comp) {
            f->table3[a][comp] = sqrt(sum2[comp] / (TF_FAMILY_LEVELS * (double)d->n_out));
        }
    }
    free(out);
    free(truth);
    return 0;
}

/* Marks every curve "not tried" before a family's order search. */
static void untried(tf_family_result *r)
{
    for (size_t i = 0; i <= TFIT_MAX_DEGREE; ++i) {
        r->cv[i] = INFINITY;
    }
    for (size_t i = 0; i <= TF_FAMILY_MAX_RANK; ++i) {
        r->cv_rank[i] = r->heldout_rank[i] = INFINITY;
    }
}

static int run_family(tf_ctx *ctx, tf_fit_outcome *o, const tf_fit_plan *plan,
                      tf_family_result *r)
{
    const tf_family *f = r->family;
    const int inverse = f->kind == TF_FAMILY_INVERSE;
    double t0 = tf_seconds();
    untried(r);
    r->applicable = f->applicable(ctx, &o->cases, plan) == 0;
    if (!r->applicable) {
        /* skipped, not failed: the reason, cut to fit */
        snprintf(r->why, sizeof r->why, "%.*s", (int)sizeof r->why - 1, ctx->err);
        return 0;
    }
    tf_info(ctx, "fit: %s: choosing orders by %u-fold cross-validation", f->name, plan->folds);
    if (f->select(ctx, &o->cases, plan, r) != 0) {
        return -1;
    }
    if (heldout(r, &o->cases, ctx) != 0) {
        return -1;
    }
    /* a contact law that creates energy somewhere in its envelope would make
     * the haptic loop unstable: refused, never emitted (passivity.h) */
    if (inverse && tf_passivity_require(ctx, r->model) != 0) {
        return -1;
    }
    if (!inverse && seed_table(r, &o->cases, ctx) != 0) {
        return -1;
    }
    r->seconds = tf_seconds() - t0;
    tf_info(ctx, "fit: %s: held-out max %.3g %s, rms %.3g (%.2f s)", f->name, r->heldout_max,
            inverse ? "N" : "mm", r->heldout_rms, r->seconds);
    return 0;
}

/* A small-strain law (linear elasticity, the Kelvin solid) stops
 * describing tissue when displacements approach the body's thickness (a
 * plate deflecting a tenth of it already stiffens as a membrane); the model
 * still reproduces the solve, which is what its error measures, so this is
 * a warning, not a refusal.  A finite-strain law describes that regime, but
 * no law a displacement larger than the whole body. */
#define SMALL_STRAIN_SHARE 0.1
size_t tf_fit_law_range(const tf_problem *p, const tf_fitdata *d, double *peak, char *buf,
                        size_t n)
{
    double biggest = 0, thick = INFINITY, size = 0, lo[3], hi[3];
    for (size_t i = 0; i < 3 * (size_t)d->n_out * d->n_cases; ++i) {
        biggest = fmax(biggest, fabs(d->u[i]));
    }
    tf_problem_bounds(p, lo, hi);
    for (int a = 0; a < 3; ++a) {
        thick = fmin(thick, hi[a] - lo[a]);
        size = fmax(size, hi[a] - lo[a]);
    }
    *peak = biggest;
    int k = 0;
    if (biggest > size) {
        k = snprintf(buf, n, "displacements reach %.3g mm, more than the body's size %.3g mm: no "
                             "law of this scene describes that",
                     biggest, size);
    } else if (!(tf_material_caps(&p->material) & TF_MATERIAL_FINITE) &&
               biggest > SMALL_STRAIN_SHARE * thick) {
        k = snprintf(buf, n, "displacements reach %.3g mm on a body %.3g mm thick (%.3g %%, more "
                             "than %g %%): the %s law is small-strain and does not describe "
                             "tissue there; the models reproduce its solve",
                     biggest, thick, 100 * biggest / thick, 100 * SMALL_STRAIN_SHARE,
                     tf_material_name(&p->material));
    } else if (n > 0) {
        buf[0] = '\0';
    }
    return k > 0 ? ((size_t)k < n ? (size_t)k : n - 1) : 0;
}

static void warn_large(const tf_ctx *ctx, const tf_problem *p, const tf_fitdata *d)
{
    char why[320];
    double peak;
    if (tf_fit_law_range(p, d, &peak, why, sizeof why) > 0) {
        tf_info(ctx, "fit: warning: %s", why);
    }
}

/* The steps that solve (cases, histories, cut progress) report in the
 * solver's context, the one it was created with; when the caller's is
 * another, it gets their message too. */
static int relayed(tf_ctx *ctx, const tf_solver *solver, int rc)
{
    if (rc != 0 && ctx != solver->ctx) {
        tf_fail(ctx, "%s", solver->ctx->err);
    }
    return rc;
}

/* A contact region: the plan's family fits the region's models (families
 * with a `region` operation, family.h); every other family is marked not
 * applicable, and each model goes to its family's result. */
static int region_run(tf_ctx *ctx, const tf_problem *p, tf_solver *solver,
                      const tf_fit_plan *plan, tf_fit_outcome *o)
{
    const tf_contact *c = &p->contacts[plan->contact];
    if (plan->family->region == NULL) { /* never a point model of a region */
        tf_fail(ctx, "contact '%s' is a contact region: the %s family fits one contact site's "
                     "load cases, not a region", c->name, plan->family->name);
        return -2;
    }
    o->n_families = tf_family_count();
    o->fam = calloc(o->n_families, sizeof *o->fam);
    if (o->fam == NULL) {
        return tf_fail(ctx, "out of memory for the families' results");
    }
    for (size_t i = 0; i < o->n_families; ++i) {
        o->fam[i].family = tf_family_at(i);
        untried(&o->fam[i]);
        snprintf(o->fam[i].why, sizeof o->fam[i].why, "contact '%s' is a contact region",
                 c->name);
    }
    tf_model *m[TF_FAMILY_REGION_MODELS];
    size_t n = 0;
    const double t0 = tf_seconds();
    tf_info(ctx, "fit: contact '%s' is a region: its law and surface (%s)", c->name,
            plan->family->name);
    const int rc = plan->family->region(ctx, solver, p, plan, m, &n);
    if (rc != 0) {
        tf_fit_outcome_free(o);
        return rc; /* -2: a region it cannot fit */
    }
    for (size_t k = 0; k < n; ++k) {
        tf_family_result *r = NULL;
        for (size_t i = 0; i < o->n_families; ++i) {
            r = o->fam[i].family->id == m[k]->family ? &o->fam[i] : r;
        }
        if (r == NULL || r->model != NULL) { /* a family's models, one each: family.h */
            for (size_t j = k; j < n; ++j) {
                tf_model_free(m[j]);
            }
            tf_fit_outcome_free(o);
            return tf_fail(ctx, "%s: model '%s' has no family of its own", plan->family->name,
                           m[k]->name);
        }
        r->applicable = 1;
        r->why[0] = '\0';
        r->model = m[k];
        r->heldout_max = m[k]->heldout_max;
        r->heldout_rms = m[k]->heldout_rms;
        r->heldout_rel_max = m[k]->heldout_rel_max;
        r->seconds = k == 0 ? tf_seconds() - t0 : 0; /* fitted together: the time once */
    }
    return 0;
}

int tf_fit_run(tf_ctx *ctx, const tf_problem *p, tf_solver *solver, const tf_fit_plan *plan,
               tf_fit_outcome *o)
{
    memset(o, 0, sizeof *o);
    if (plan->contact >= 0 && p->contacts[plan->contact].region.kind != TF_CONTACT_REGION_NONE) {
        return region_run(ctx, p, solver, plan, o);
    }
    double t0 = tf_seconds();
    if (tf_cases_build(p, solver, plan, &o->cases) != 0) {
        return relayed(ctx, solver, -1);
    }
    if (tf_solver_caps_of(solver) & TF_SOLVER_TIME_DEPENDENT) {
        tf_info(ctx, "fit: the solver is time-dependent: %zu + %zu force histories of %zu ticks "
                "of %u us, a solver step every %zu ticks", plan->hist_train, plan->hist_heldout,
                plan->hist_ticks, plan->tick_ns / 1000, plan->hist_solve_every);
        const tf_history_kind kind =
            plan->family == tf_family_find("resonant") ? TF_HIST_DYNAMIC : TF_HIST_PRESS;
        if (tf_histories_solve(&o->cases, kind, plan->tick_ns, plan->hist_solve_every,
                               plan->hist_train, plan->hist_heldout, plan->hist_ticks,
                               plan->seed, &o->hist) != 0) {
            tf_cases_free(&o->cases);
            return relayed(ctx, solver, -1);
        }
        o->has_hist = 1;
        o->cases.hist = &o->hist;
    }
    if (plan->cut_intervals > 0) {
        if (tf_cut_cases_solve(p, solver, plan, &o->cut) != 0) {
            tf_fit_outcome_free(o);
            return relayed(ctx, solver, -1);
        }
        o->has_cut = 1;
        o->cases.cut = &o->cut;
    }
    o->seconds_cases = tf_seconds() - t0;
    warn_large(ctx, p, &o->cases.train);
    /* refuse a forward family that does not apply before any fitting */
    if (plan->family->applicable(ctx, &o->cases, plan) != 0) {
        tf_fit_outcome_free(o);
        return -2;
    }
    o->n_families = tf_family_count();
    o->fam = calloc(o->n_families, sizeof *o->fam);
    if (o->fam == NULL) {
        tf_fit_outcome_free(o);
        return tf_fail(ctx, "out of memory for the families' results");
    }
    for (size_t i = 0; i < o->n_families; ++i) {
        o->fam[i].family = tf_family_at(i);
        if (run_family(ctx, o, plan, &o->fam[i]) != 0) {
            tf_fit_outcome_free(o);
            return -1;
        }
    }
    return 0;
}

void tf_fit_outcome_free(tf_fit_outcome *o)
{
    for (size_t i = 0; o->fam != NULL && i < o->n_families; ++i) {
        tf_model_free(o->fam[i].model);
        free(o->fam[i].deviation);
    }
    free(o->fam);
    o->fam = NULL;
    o->n_families = 0;
    tf_cases_free(&o->cases);
    if (o->has_hist) {
        tf_histories_free(&o->hist);
        o->has_hist = 0;
    }
    if (o->has_cut) {
        tf_cut_cases_free(&o->cut);
        o->has_cut = 0;
    }
}

const tf_family_result *tf_fit_result_of(const tf_fit_outcome *o, const tf_family *f)
{
    for (size_t i = 0; i < o->n_families; ++i) {
        if (o->fam[i].family == f) {
            return &o->fam[i];
        }
    }
    return NULL;
}

tf_model *tf_fit_emitted(const tf_fit_outcome *o, const tf_fit_plan *plan, tf_family_kind kind)
{
    for (size_t i = 0; i < o->n_families; ++i) {
        const tf_family_result *r = &o->fam[i];
        if (r->applicable && r->family->kind == kind &&
            (kind != TF_FAMILY_FORWARD || r->family == plan->family)) {
            return r->model;
        }
    }
    return NULL;
}
