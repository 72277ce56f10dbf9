/*
 * cut_progress.c — see cut_progress.h.
 */
#include "fitting/cut_progress.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/clock.h"
#include "base/context.h"
#include "base/log.h"
#include "base/rng.h"
#include "meshfree/cut.h"
#include "model/forms/cut.h"
#include "solvers/probe.h"

/* One s: the problem with every cut truncated at s, a solver of it, the
 * four unit responses at the outputs into resp (4 x rows). */
static int solve_at(const tf_problem *p, const tf_solver *like, int contact, double s,
                    double *resp, size_t rows)
{
    tf_ctx *ctx = like->ctx;
    tf_cut cuts[8];
    if (p->n_cuts > sizeof cuts / sizeof cuts[0]) {
        return tf_fail(ctx, "cut progress: %zu cuts, at most 8", p->n_cuts);
    }
    tf_problem q = *p;
    q.n_cuts = 0;
    q.cuts = cuts;
    for (size_t i = 0; i < p->n_cuts; ++i) {
        tf_cut_truncate(&p->cuts[i], s, &cuts[q.n_cuts]);
        q.n_cuts += cuts[q.n_cuts].n >= 2;
    }
    if (q.n_cuts == 0) {
        q.cuts = NULL;
    }
    tf_solver *sv = tf_solver_create(&q, &like->opts, ctx);
    if (sv == NULL) {
        return -1;
    }
    const double f[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const size_t dofs = 3 * tf_solver_node_count(sv);
    double *full = malloc(4 * dofs * sizeof *full);
    int rc = full == NULL ? tf_fail(ctx, "out of memory for the cut progress solves")
                          : tf_solver_solve(sv, contact, f, 4, NULL, full);
    for (int k = 0; rc == 0 && k < 4; ++k) {
        rc = tf_solver_probe_outputs(ctx, sv, &q, full + k * dofs, resp + k * rows);
    }
    for (int k = 1; rc == 0 && k < 4; ++k) {
        for (size_t o = 0; o < rows; ++o) {
            resp[k * rows + o] -= resp[o];
        }
    }
    free(full);
    tf_solver_destroy(sv);
    return rc;
}

int tf_cut_cases_solve(const tf_problem *p, const tf_solver *like, const tf_fit_plan *plan,
                       tf_cut_cases *out)
{
    tf_ctx *ctx = like->ctx;
    memset(out, 0, sizeof *out);
    if (!(tf_solver_caps_of(like) & TF_SOLVER_AFFINE)) {
        return tf_fail(ctx, "cut progress: solver %s is not affine in the force (the cut family "
                            "superposes unit responses at each s)", tf_solver_name(like));
    }
    const uint32_t k = plan->cut_intervals;
    out->knots = k;
    out->n = 2 * (size_t)k + 1 + plan->cut_heldout;
    out->rows = 3 * p->outputs.n_nodes;
    out->s = malloc(out->n * sizeof *out->s);
    out->role = malloc(out->n * sizeof *out->role);
    out->resp = malloc(out->n * 4 * out->rows * sizeof *out->resp);
    if (out->s == NULL || out->role == NULL || out->resp == NULL) {
        tf_cut_cases_free(out);
        return tf_fail(ctx, "out of memory for %zu cut progress values", out->n);
    }
    tf_rng r = {plan->seed ^ 0x637574u};
    for (size_t i = 0; i < out->n; ++i) {
        if (i <= k) {
            out->s[i] = (float)((double)i / k);
            out->role[i] = TF_CUT_TRAIN;
        } else if (i <= 2 * (size_t)k) {
            out->s[i] = (float)((i - k - 0.5) / k);
            out->role[i] = TF_CUT_VALIDATE;
        } else { /* uniform in (0, 1), never on a knot or a midpoint */
            double s;
            do {
                s = tf_rng_uniform(&r);
            } while (fmod(s * 2 * k, 1.0) < 0.05 || fmod(s * 2 * k, 1.0) > 0.95);
            out->s[i] = (float)s;
            out->role[i] = TF_CUT_HELDOUT;
        }
    }
    double t0 = tf_seconds();
    tf_info(ctx, "fit: cut progress: solving at %zu values of s (%u + 1 knots, %u between, %zu "
            "held out)", out->n, k, k, plan->cut_heldout);
    for (size_t i = 0; i < out->n; ++i) {
        if (solve_at(p, like, plan->contact, out->s[i], out->resp + i * 4 * out->rows,
                     out->rows) != 0) {
            tf_cut_cases_free(out);
            return -1;
        }
    }
    out->seconds = tf_seconds() - t0;
    return 0;
}

void tf_cut_cases_free(tf_cut_cases *c)
{
    free(c->s);
    free(c->role);
    free(c->resp);
    memset(c, 0, sizeof *c);
}

void tf_cut_cases_response(const tf_cut_cases *c, size_t i, const double f[3], double *u)
{
    const double *b = c->resp + i * 4 * c->rows;
    for (size_t o = 0; o < c->rows; ++o) {
        u[o] = b[o] + f[0] * b[c->rows + o] + f[1] * b[2 * c->rows + o] +
               f[2] * b[3 * c->rows + o];
    }
}

int tf_cut_cases_errors(const tf_model *m, const tf_cut_cases *c, size_t i, const tf_fitdata *d,
                        double *max, double *sum2)
{
    float *out = malloc(c->rows * sizeof *out);
    double *truth = malloc(c->rows * sizeof *truth);
    *max = 0;
    *sum2 = 0;
    if (out == NULL || truth == NULL) {
        free(out);
        free(truth);
        return -1;
    }
    for (size_t j = 0; j < d->n_cases; ++j) {
        const float in[3] = {(float)d->force[j][0], (float)d->force[j][1], (float)d->force[j][2]};
        const double f[3] = {in[0], in[1], in[2]};
        tf_cut_ref_eval(m, in, c->s[i], out, NULL);
        tf_cut_cases_response(c, i, f, truth);
        for (size_t o = 0; o < c->rows; ++o) {
            double e = (double)out[o] - truth[o];
            *max = fmax(*max, fabs(e));
            *sum2 += e * e;
        }
    }
    free(out);
    free(truth);
    return 0;
}
