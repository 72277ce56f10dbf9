/*
 * heldout_check.c — recomputes a fitted header's held-out errors
 * independently of the fitting pipeline: the header is compiled here with
 * the target library and evaluated by tfit_displacements() /
 * tfit_contact_force() (not the host's reference evaluator), at the
 * held-out forces redesigned from the scene's seed and solved afresh.  A
 * cut forward model (family id 6) is evaluated by tfit_displacements_cut()
 * at the held-out cut progress values, its scene solved afresh at each
 * (fitting/cut_progress.h).
 *
 *   heldout_check SCENE MAX_FORWARD_MM MAX_CONTACT_REL [FIRST]
 *
 * Compiled with -DHEADER='"NAME.h"' -DFORWARD=tfit_NAME_forward
 * -DCONTACT=tfit_NAME_contact -DPFX=TFIT_NAME (and the IMPLEMENTATION
 * macro).  Fails when the recomputed errors differ from the header's
 * metadata or exceed the bounds given.
 *
 * FIRST (a nonlinear scene's short check) recomputes only the first FIRST
 * held-out cases, at least the anchors of the fit's route (case_graph.h),
 * each solved from the case the whole route solves it from, so that the
 * same equilibria are reached: each maximum must then be at most the
 * header's and at least a tenth of it (a recomputation that lost its
 * errors fails), and the header's RMS figures are left to the full check.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fitting/case_graph.h"
#include "fitting/case_runner.h"
#include "fitting/cut_progress.h"
#include "fitting/force_samples.h"
#include "scene/scene.h"
#include "solvers/solver.h"

#include HEADER

#define CAT(a, b) a##b
#define MACRO(p, s) CAT(p, s)

/* The header's %.6g numbers, compared at that precision. */
static int same(double recomputed, double header)
{
    return fabs(recomputed - header) <= 1e-5 * fabs(header) + 1e-30;
}

/* A subset's maximum: at most the header's (to its precision), and at
 * least a tenth of it. */
static int within(double recomputed, double header)
{
    return recomputed <= header * (1 + 1e-5) + 1e-30 && recomputed >= 0.1 * header;
}

/* The solve's displacements where the header's models read them: output j
 * (3 j ...) and the contact point (3 n_out ...).  Outputs by node (node_ids
 * are node numbers) and a contact by node take the nodal values; outputs
 * given as points (node_ids 1 ... n number them) and a contact given by
 * position take the solver's field there, as the fit did. */
static int solved_at(const tf_solver *solver, const tf_problem *p, const tf_contact *ct,
                     const tfit_model *fwd, const double *ui, double *truth)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    double grad[9];
    for (uint32_t j = 0; j < fwd->n_out; ++j) {
        const size_t node = p->outputs.points ? 0 : (size_t)fwd->node_ids[j] - 1;
        const double *x = p->outputs.points ? p->outputs.points + 3 * (size_t)j : NULL;
        if (x != NULL && tf_solver_field(&ctx, solver, ui, x, 1, truth + 3 * j, grad) != 0) {
            fprintf(stderr, "heldout_check: %s\n", ctx.err);
            return -1;
        }
        for (int k = 0; x == NULL && k < 3; ++k) {
            truth[3 * j + (uint32_t)k] = ui[3 * node + (size_t)k];
        }
    }
    double *tc = truth + 3 * fwd->n_out;
    if (!ct->by_node && tf_solver_field(&ctx, solver, ui, ct->at, 1, tc, grad) != 0) {
        fprintf(stderr, "heldout_check: %s\n", ctx.err);
        return -1;
    }
    if (!ct->by_node) {
        return 0;
    }
    for (int k = 0; k < 3; ++k) {
        tc[k] = ui[3 * (size_t)ct->node + (size_t)k];
    }
    return 0;
}

/* The held-out cases into u (dofs x n): an affine solver's in one call (one
 * factorisation); any other's each from the anchor case nearest its force
 * (fitting/case_graph.h), a shorter Newton path to the same equilibrium
 * than one from rest, the fit's own route. */
static int solve_held(tf_solver *solver, int contact, const double (*held)[3], size_t n,
                      size_t first, size_t dofs, double *u)
{
    if (tf_solver_caps_of(solver) & TF_SOLVER_AFFINE) {
        return tf_solver_solve(solver, contact, held, first, NULL, u);
    }
    long *from = malloc(n * sizeof *from);
    size_t *keep = malloc(dofs * sizeof *keep);
    int rc = -1;
    if (from != NULL && keep != NULL) {
        for (size_t j = 0; j < dofs; ++j) {
            keep[j] = j;
        }
        /* the route of all n cases; the anchors come first, so the first
         * `first` cases (first >= anchors) are solved as in the whole route */
        tf_case_graph_anchored(held, n, tf_case_graph_anchors(n), from);
        const tf_case_list list = {.contact = contact, .n = first, .force = held, .from = from,
                                   .n_keep = dofs, .keep = keep};
        rc = tf_case_run(NULL, solver, &list, u);
    }
    free(from);
    free(keep);
    return rc;
}

#if MACRO(PFX, _FORWARD_FAMILY_ID) == 6 /* TFIT_FAMILY_CUT */
/* The cut model at every held-out s and force, against the scene solved
 * with its cuts truncated at that s.  Returns 0, or -1 with a message. */
static int forward_errors(const tf_scene *s, const tf_solver *solver, const double (*held)[3],
                          size_t n, const double *u, size_t dofs, double *max, double *sum2,
                          size_t *count)
{
    (void)u;
    (void)dofs;
    const tfit_model *fwd = &FORWARD;
    tf_cut_cases cc;
    if (tf_cut_cases_solve(&s->problem, solver, &s->fit, &cc) != 0) {
        fprintf(stderr, "heldout_check: %s\n", solver->ctx->err);
        return -1;
    }
    float *out = malloc(cc.rows * sizeof *out);
    double *truth = malloc(cc.rows * sizeof *truth);
    for (size_t i = 0; i < cc.n; ++i) {
        for (size_t j = 0; cc.role[i] == TF_CUT_HELDOUT && j < n; ++j) {
            const float f[3] = {(float)held[j][0], (float)held[j][1], (float)held[j][2]};
            if (tfit_displacements_cut(fwd, f, cc.s[i], out) < 0) {
                return -1;
            }
            tf_cut_cases_response(&cc, i, held[j], truth);
            for (size_t o = 0; o < cc.rows; ++o) {
                double e = (double)out[o] - truth[o];
                *max = fmax(*max, fabs(e));
                *sum2 += e * e;
            }
            ++*count;
        }
    }
    free(out);
    free(truth);
    tf_cut_cases_free(&cc);
    return 0;
}
#else
/* The forward model at every held-out force against the fresh solves u, at
 * the points its outputs name (solved_at). */
static int forward_errors(const tf_scene *s, const tf_solver *solver, const double (*held)[3],
                          size_t n, const double *u, size_t dofs, double *max, double *sum2,
                          size_t *count)
{
    const tf_problem *p = &s->problem;
    const tfit_model *fwd = &FORWARD;
    float *out = malloc(3 * fwd->n_out * sizeof *out);
    double *truth = malloc(3 * (fwd->n_out + 1) * sizeof *truth);
    int rc = out != NULL && truth != NULL ? 0 : -1;
    for (size_t i = 0; rc == 0 && i < n; ++i) {
        const float f[3] = {(float)held[i][0], (float)held[i][1], (float)held[i][2]};
        if (solved_at(solver, p, &p->contacts[s->fit.contact], fwd, u + i * dofs, truth) != 0 ||
            tfit_displacements(fwd, f, out) < 0) {
            rc = -1;
            break;
        }
        for (uint32_t j = 0; j < fwd->n_out; ++j) {
            for (int k = 0; k < 3; ++k) {
                double e = (double)out[3 * j + (uint32_t)k] - truth[3 * j + (uint32_t)k];
                *max = fmax(*max, fabs(e));
                *sum2 += e * e;
            }
        }
        ++*count;
    }
    free(out);
    free(truth);
    return rc;
}
#endif

int main(int argc, char **argv)
{
    if (argc != 4 && argc != 5) {
        fprintf(stderr, "usage: heldout_check SCENE MAX_FORWARD_MM MAX_CONTACT_REL [FIRST]\n");
        return 2;
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    tf_scene *s = tf_scene_load(&ctx, argv[1], NULL, 0);
    if (s == NULL) {
        fprintf(stderr, "heldout_check: %s\n", ctx.err);
        return 1;
    }
    const tf_problem *p = &s->problem;
    tf_solver *solver = tf_solver_create(p, NULL, &ctx);
    if (solver == NULL) {
        fprintf(stderr, "heldout_check: %s\n", ctx.err);
        return 1;
    }
    const size_t n_all = s->fit.n_heldout, n_train = s->fit.n_train;
    const size_t first = argc == 5 ? (size_t)atol(argv[4]) : n_all;
    if (first < tf_case_graph_anchors(n_all) || first > n_all) {
        fprintf(stderr, "heldout_check: FIRST must lie in [%zu, %zu] (the route's anchors, the cases)\n",
                tf_case_graph_anchors(n_all), n_all);
        return 2;
    }
    const size_t dofs = 3 * tf_solver_node_count(solver);
    double(*train)[3] = malloc(n_train * sizeof *train), (*held)[3] = malloc(n_all * sizeof *held);
    double *u = malloc(first * dofs * sizeof *u);
    tf_force_samples(p->envelope.centre, p->envelope.radius, n_train, n_all, s->fit.seed, train, held);
    for (size_t i = 0; i < n_all; ++i) { /* the firmware's input is a float */
        for (int k = 0; k < 3; ++k) {
            held[i][k] = (double)(float)held[i][k];
        }
    }
    const size_t n = first; /* the cases recomputed */
    if (solve_held(solver, s->fit.contact, (const double(*)[3])held, n_all, n, dofs, u) != 0) {
        fprintf(stderr, "heldout_check: %s\n", ctx.err);
        return 1;
    }
    const tfit_model *fwd = &FORWARD, *con = &CONTACT;
    double fwd_max = 0, fsum2 = 0, con_max = 0, csum2 = 0, crel = 0;
    size_t fwd_cases = 0;
    if (forward_errors(s, solver, (const double(*)[3])held, n, u, dofs, &fwd_max, &fsum2,
                       &fwd_cases) != 0) {
        fprintf(stderr, "heldout_check: no forward errors at the outputs\n");
        return 1;
    }
    double *truth = malloc(3 * (fwd->n_out + 1) * sizeof *truth);
    for (size_t i = 0; i < n; ++i) {
        if (truth == NULL ||
            solved_at(solver, p, &p->contacts[s->fit.contact], fwd, u + i * dofs, truth) != 0) {
            fprintf(stderr, "heldout_check: no displacement at the contact point\n");
            return 1;
        }
        const double *tc = truth + 3 * fwd->n_out;
        const float d[3] = {(float)tc[0], (float)tc[1], (float)tc[2]};
        float fc[3];
        if (tfit_contact_force(con, d, fc) < 0) {
            return 1;
        }
        double e2 = 0, t2 = 0;
        for (int k = 0; k < 3; ++k) {
            double e = (double)fc[k] - held[i][k];
            con_max = fmax(con_max, fabs(e));
            csum2 += e * e;
            e2 += e * e;
            t2 += held[i][k] * held[i][k];
        }
        crel = fmax(crel, sqrt(e2 / t2));
    }
    double frms = sqrt(fsum2 / (3.0 * fwd->n_out * (double)fwd_cases)), crms = sqrt(csum2 / (3.0 * (double)n));
    int ok;
    if (n == n_all) {
        printf("held-out, recomputed from the compiled header: forward max %.3g mm rms %.3g mm "
               "(bound %s); contact max %.3g N, rms %.3g N, relative %.3g (bound %s)\n",
               fwd_max, frms, argv[2], con_max, crms, crel, argv[3]);
        ok = same(fwd_max, MACRO(PFX, _FORWARD_HELDOUT_MAX_MM)) &&
             same(frms, MACRO(PFX, _FORWARD_HELDOUT_RMS_MM)) &&
             same(con_max, MACRO(PFX, _CONTACT_HELDOUT_MAX_N)) &&
             same(crel, MACRO(PFX, _CONTACT_HELDOUT_REL_MAX));
        if (!ok) {
            printf("the header's held-out metadata does not match the recomputation\n");
        }
    } else {
        printf("held-out, the first %zu of %zu cases recomputed from the compiled header: forward "
               "max %.3g mm of the header's %.6g (bound %s); contact max %.3g N of %.6g, relative "
               "%.3g of %.6g (bound %s)\n",
               n, n_all, fwd_max, (double)MACRO(PFX, _FORWARD_HELDOUT_MAX_MM), argv[2], con_max,
               (double)MACRO(PFX, _CONTACT_HELDOUT_MAX_N), crel,
               (double)MACRO(PFX, _CONTACT_HELDOUT_REL_MAX), argv[3]);
        ok = within(fwd_max, MACRO(PFX, _FORWARD_HELDOUT_MAX_MM)) &&
             within(con_max, MACRO(PFX, _CONTACT_HELDOUT_MAX_N)) &&
             within(crel, MACRO(PFX, _CONTACT_HELDOUT_REL_MAX));
        if (!ok) {
            printf("a recomputed error beyond the header's maximum, or under a tenth of it\n");
        }
    }
    if (fwd_max > atof(argv[2]) || crel > atof(argv[3])) {
        printf("held-out error beyond its bound\n");
        ok = 0;
    }
    free(truth);
    free(train);
    free(held);
    free(u);
    tf_solver_destroy(solver);
    tf_scene_free(s);
    return ok ? 0 : 1;
}
