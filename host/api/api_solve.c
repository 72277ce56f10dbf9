/*
 * api_solve.c — one load case of a scene through the API (api.h), by the
 * calls `tissuefit solve` makes (cli/cmd_solve.c): the solver the scene
 * names, one tf_solver_solve of the force at the contact site, the outputs
 * probed from the nodal values (solvers/probe.h).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api/api_internal.h"
#include "cli/cmd_args.h"
#include "solvers/history_run.h"
#include "solvers/probe.h"

/* The contact site as `tissuefit solve` picks it (cmd_solve.c,
 * pick_contact, for a scene without a history): -1 without a force, else
 * the named site or the first.  -2 after a message (its text is the tool's). */
static int pick_contact(tf_ctx *ctx, const tf_api_scene *s, const char *contact, int has_force)
{
    const tf_problem *p = &s->scene->problem;
    if (!has_force) {
        if (contact != NULL) {
            tf_fail(ctx, "solve: --contact without --force");
            return -2;
        }
        if (tf_problem_unloaded(p)) {
            tf_fail(ctx, "solve: %s: nothing loads the body (no --force, no loads and no "
                         "prescribed displacement in the scene): give --force FX,FY,FZ",
                    s->path);
            return -2;
        }
        return -1;
    }
    if (p->n_contacts == 0) {
        tf_fail(ctx, "solve: %s has no contact site for --force", s->path);
        return -2;
    }
    int k = contact ? tf_problem_contact(p, contact) : 0;
    if (k < 0) {
        tf_fail(ctx, "solve: %s has no contact site '%s'", s->path, contact);
        return -2;
    }
    return k;
}

/* The solver, built once per scene handle and cut progress (the tool
 * builds one per run); the problem's cuts truncated to the progress as
 * the tool's --cut-progress does. */
static int ensure_solver(tf_ctx *ctx, tf_api_scene *s, double progress)
{
    tf_problem *p = &s->scene->problem;
    if (!(isnan(progress) || (progress >= 0 && progress <= 1))) {
        return tf_fail(ctx, "solve: --cut-progress '%g' is not a number in [0, 1]", progress);
    }
    if (s->solver != NULL && !(isnan(progress) && isnan(s->progress)) && progress != s->progress) {
        tf_solver_destroy(s->solver);
        s->solver = NULL;
    }
    if (s->solver == NULL) {
        if (s->n_cuts > 0) {
            memcpy(p->cuts, s->cuts, s->n_cuts * sizeof *s->cuts);
        }
        p->n_cuts = s->n_cuts;
        s->progress = NAN;
        if (!isnan(progress)) {
            ctx->err[0] = '\0';
            if (tf_cmd_cut_progress(ctx, s->path, p, progress) != 0) {
                return -1;
            }
            s->progress = progress;
        }
        s->solver = tf_solver_create(&s->scene->problem, NULL, ctx);
        if (s->solver == NULL) {
            return tf_api_fail_on(ctx, "solve: %s", s->path);
        }
    }
    return 0;
}

int tf_api_solve(tf_ctx *ctx, tf_api_scene *s, const char *contact, const double *force,
                 double cut_progress, double *u, double *at_outputs)
{
    const tf_problem *p = &s->scene->problem;
    if (p->history.present) {
        return tf_fail(ctx, "solve: %s has a history: section: solve it as a time series "
                            "(tf_api_solve_history; Python: Scene.solve_history)",
                       s->path);
    }
    const double none[3] = {0, 0, 0};
    int k = pick_contact(ctx, s, contact, force != NULL);
    if (k < -1 || ensure_solver(ctx, s, cut_progress) != 0) {
        return -1;
    }
    if (tf_solver_solve(s->solver, k, (const double(*)[3])(force ? force : none), 1, NULL, u) !=
        0) {
        return tf_api_fail_on(ctx, "solve: %s", s->path);
    }
    if (at_outputs != NULL &&
        tf_solver_probe_outputs(ctx, s->solver, p, u, at_outputs) != 0) {
        return tf_api_fail_on(ctx, "solve: %s: outputs", s->path);
    }
    tf_solver_report(s->solver);
    return 0;
}

int tf_api_field(tf_ctx *ctx, tf_api_scene *s, const double *u, const double *xyz, size_t np,
                 double *out)
{
    if (s->solver == NULL) {
        return tf_fail(ctx, "field: %s: solve the scene first", s->path);
    }
    /* the scene's problem with these points as its outputs (probe.h) */
    tf_problem at = s->scene->problem;
    at.outputs.kind = TF_OUT_POINTS;
    at.outputs.points = (double *)xyz;
    at.outputs.n_nodes = np;
    at.outputs.nodes = NULL;
    if (tf_solver_probe_outputs(ctx, s->solver, &at, u, out) != 0) {
        return tf_api_fail_on(ctx, "field: %s", s->path);
    }
    return 0;
}

/* The history's samples, force replacing history.force when given. */
static int history_samples(tf_ctx *ctx, const tf_api_scene *s, const double *force,
                           tf_samples *smp)
{
    const tf_problem *p = &s->scene->problem;
    if (!p->history.present) {
        return tf_fail(ctx, "solve: %s has no history: section (solve it one load case at a "
                            "time: tf_api_solve)",
                       s->path);
    }
    tf_history h = p->history;
    if (force != NULL) {
        if (h.table) {
            return tf_fail(ctx, "solve: %s: its history has a table of forces: no --force",
                           s->path);
        }
        memcpy(h.force, force, sizeof h.force);
    }
    return tf_history_sample(&h, smp) == 0 ? 0 : tf_fail(ctx, "solve: out of memory");
}

int tf_api_history_steps(tf_ctx *ctx, tf_api_scene *s, const double *force, size_t *n)
{
    tf_samples smp;
    if (history_samples(ctx, s, force, &smp) != 0) {
        return -1;
    }
    *n = smp.n;
    tf_samples_free(&smp);
    return 0;
}

/* Each step's outputs, probed from its nodal values. */
static int history_outputs(tf_ctx *ctx, tf_api_scene *s, size_t steps, const double *u,
                           double *at_outputs)
{
    const tf_problem *p = &s->scene->problem;
    const size_t n3 = 3 * p->cloud.n, m3 = 3 * p->outputs.n_nodes;
    for (size_t k = 0; k < steps; ++k) {
        if (tf_solver_probe_outputs(ctx, s->solver, p, u + n3 * k, at_outputs + m3 * k) != 0) {
            return tf_api_fail_on(ctx, "solve: %s: outputs", s->path);
        }
    }
    return 0;
}

int tf_api_solve_history(tf_ctx *ctx, tf_api_scene *s, const char *contact, const double *force,
                         double *t, double *u, double *at_outputs)
{
    const tf_problem *p = &s->scene->problem;
    int k = contact ? tf_problem_contact(p, contact) : p->history.contact;
    if (contact != NULL && k < 0) {
        return tf_fail(ctx, "solve: %s has no contact site '%s'", s->path, contact);
    }
    tf_samples smp;
    if (history_samples(ctx, s, force, &smp) != 0) {
        return -1;
    }
    /* A fresh solver, as the tool's one run has (api.h: a second run after
     * tf_nonlinear_reset differs in the last bits). */
    tf_solver_destroy(s->solver);
    s->solver = NULL;
    int rc = ensure_solver(ctx, s, NAN);
    if (rc == 0 && tf_history_run(ctx, s->solver, k, &smp, u) != 0) {
        rc = tf_api_fail_on(ctx, "solve: %s", s->path);
    }
    if (rc == 0) {
        memcpy(t, smp.t, smp.n * sizeof *t);
        tf_solver_report(s->solver);
    }
    if (rc == 0 && at_outputs != NULL) {
        rc = history_outputs(ctx, s, smp.n, u, at_outputs);
    }
    tf_samples_free(&smp);
    return rc;
}
