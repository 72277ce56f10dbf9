/*
 * solve_every_study.c — what a solver step coarser than the tick costs
 * (fit.solve_every, fitting/histories.h; docs/fitting.md §7.6).
 *
 *   solve_every_study SCENE M1,M2,...
 *
 * The scene's held-out press-hold-release histories are solved with a
 * solver step of every M ticks (the force linear between steps, the ticks
 * between interpolated: what `tissuefit fit` does with solve_every: M) for
 * the first M of the list; then the same per-tick forces are solved again
 * with a step every M' ticks for each M' of the list (M' = 1: every tick,
 * the truth).  Printed: the largest output displacement difference over
 * every tick and output against the first M' = 1 run, absolute and over
 * the largest displacement.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/context.h"
#include "fitting/cases.h"
#include "fitting/histories.h"
#include "scene/scene.h"
#include "solvers/solver.h"

#define MAX_M 8

/* The history's outputs with a solver step every m ticks on the ticks'
 * own forces (which, for m a divisor of the fit's step, are linear between
 * the coarser steps: the same force). */
static int resolve(const tf_cases *c, const tf_history_set *s, size_t h, size_t m, double tick,
                   double *out)
{
    const size_t dofs = 3 * tf_solver_node_count(c->solver);
    const size_t steps = 1 + (s->n_ticks - 1 + m - 1) / m;
    double *full = malloc(dofs * steps * sizeof *full);
    double(*f)[3] = malloc(steps * sizeof *f);
    if (full == NULL || f == NULL) {
        free(full);
        free(f);
        return -1;
    }
    for (size_t j = 0; j < steps; ++j) {
        memcpy(f[j], tf_history_force(s, h, j * m < s->n_ticks ? j * m : s->n_ticks - 1),
               sizeof f[j]);
    }
    int rc = tf_solver_history(c->solver, c->contact, (const double(*)[3])f, steps,
                               (double)m * tick, full);
    if (rc == 0) {
        tf_histories_outputs(&c->problem->outputs, full, dofs, s->n_ticks, m, out);
    }
    free(full);
    free(f);
    return rc;
}

int main(int argc, char **argv)
{
    size_t ms[MAX_M], nm = 0;
    if (argc != 3) {
        fprintf(stderr, "usage: solve_every_study SCENE M1,M2,...\n");
        return 2;
    }
    for (char *p = argv[2]; *p && nm < MAX_M; ++nm) {
        char *end;
        ms[nm] = strtoul(p, &end, 10);
        if (end == p || ms[nm] < 1) {
            fprintf(stderr, "solve_every_study: %s: a list of ticks per solver step\n", argv[2]);
            return 2;
        }
        p = *end == ',' ? end + 1 : end;
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    tf_scene *scene = tf_scene_load(&ctx, argv[1], NULL, 0);
    if (scene == NULL) {
        fprintf(stderr, "solve_every_study: %s\n", ctx.err);
        return 2;
    }
    tf_fit_plan plan = scene->fit;
    plan.n_train = 6; /* the static cases are not studied here */
    plan.n_heldout = 1;
    tf_solver *solver = tf_solver_create(&scene->problem, NULL, &ctx);
    tf_cases cases;
    tf_histories hist;
    if (solver == NULL || tf_cases_build(&scene->problem, solver, &plan, &cases) != 0 ||
        tf_histories_solve(&cases, TF_HIST_PRESS, plan.tick_ns, ms[0], 2, plan.hist_heldout, plan.hist_ticks,
                           plan.seed, &hist) != 0) {
        fprintf(stderr, "solve_every_study: %s\n", ctx.err);
        return 1;
    }
    const tf_history_set *s = &hist.heldout;
    const size_t rows = 3 * (size_t)s->n_out, len = s->n_ticks * rows;
    double *truth = malloc(len * sizeof *truth), *u = malloc(len * sizeof *u);
    printf("%s: %zu held-out histories of %zu ticks of %u us; forces linear between every "
           "%zu ticks\n", argv[1], s->n, s->n_ticks, plan.tick_ns / 1000, ms[0]);
    printf("%-22s %-14s %-14s %s\n", "solver step (ticks)", "max diff mm", "of the peak",
           "solver steps");
    for (size_t h = 0; h < s->n; ++h) {
        if (resolve(&cases, s, h, 1, hist.tick, truth) != 0) {
            fprintf(stderr, "solve_every_study: %s\n", ctx.err);
            return 1;
        }
        double peak = 0;
        for (size_t i = 0; i < len; ++i) {
            peak = fmax(peak, fabs(truth[i]));
        }
        for (size_t q = 0; q < nm; ++q) {
            double d = 0;
            if (q == 0) {
                memcpy(u, tf_history_u(s, h, 0), len * sizeof *u);
            } else if (resolve(&cases, s, h, ms[q], hist.tick, u) != 0) {
                fprintf(stderr, "solve_every_study: %s\n", ctx.err);
                return 1;
            }
            for (size_t i = 0; i < len; ++i) {
                d = fmax(d, fabs(u[i] - truth[i]));
            }
            printf("history %zu: %3zu%s  %-14.3g %-14.3g %zu\n", h, ms[q], q == 0 ? " (fit)" : "      ",
                   d, d / peak, 1 + (s->n_ticks - 1 + ms[q] - 1) / ms[q]);
        }
        printf("history %zu: peak displacement %.4g mm\n", h, peak);
        fflush(stdout);
    }
    free(truth);
    free(u);
    tf_histories_free(&hist);
    tf_cases_free(&cases);
    tf_solver_destroy(solver);
    tf_scene_free(scene);
    return 0;
}
