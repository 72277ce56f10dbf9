/*
 * error_norm.c — relative L2 and energy errors against an analytic solution
 * (error_norm.h).
 */
#include "verify/error_norm.h"

#include <cblas.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#include "materials/elasticity.h"
#include "meshfree/quadrature.h"
#include "problem/analytic.h"

/* Four sums per cell: error and reference, L2 and energy. */
typedef struct sums {
    double e2, u2, ee, ue;
} sums;

/* A thread's buffers for the points of one cell, and its own context: the
 * threads must not write the caller's (context.h). */
typedef struct cell_buf {
    double *x, *w, *uh, *gh;
    tf_ctx ctx;
} cell_buf;

static double energy_density(const double d[36], const double g[9])
{
    double eps[6], e = 0;
    tf_strain(g, eps);
    for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) {
            e += eps[i] * d[6 * i + j] * eps[j];
        }
    }
    return e;
}

static int cell_sums(const tf_solver *s, const double *u, const tf_cells *q, const double d[36],
                     cell_buf *b, size_t cell, sums *out)
{
    const size_t np = tf_cells_points(q);
    for (size_t p = 0; p < np; ++p) {
        tf_cells_point(q, cell, p, b->x + 3 * p, &b->w[p]);
    }
    if (tf_solver_field(&b->ctx, s, u, b->x, np, b->uh, b->gh) != 0) {
        return -1;
    }
    for (size_t p = 0; p < np; ++p) {
        const double *uh = b->uh + 3 * p, *gh = b->gh + 9 * p;
        double wt = b->w[p], ue[3], ge[9], diff[9];
        tf_analytic_eval(s->problem, b->x + 3 * p, ue, ge);
        for (int k = 0; k < 9; ++k) {
            diff[k] = gh[k] - ge[k];
        }
        for (int i = 0; i < 3; ++i) {
            out->e2 += wt * (uh[i] - ue[i]) * (uh[i] - ue[i]);
            out->u2 += wt * ue[i] * ue[i];
        }
        out->ee += wt * energy_density(d, diff);
        out->ue += wt * energy_density(d, ge);
    }
    return 0;
}

/* Every cell's sums, in parallel; the lowest failing cell's message in ctx->err. */
static int all_cells(tf_ctx *ctx, const tf_solver *s, const double *u, const tf_cells *q,
                     const double d[36], sums *per)
{
    const size_t nc = tf_cells_count(q), np = tf_cells_points(q);
    size_t failed = nc;
    openblas_set_num_threads(1); /* LAPACK inside OpenMP threads: one thread each */
#pragma omp parallel num_threads(tf_ctx_threads(s->ctx))
    {
        cell_buf b = {.x = malloc(3 * np * sizeof(double)),
                      .w = malloc(np * sizeof(double)),
                      .uh = malloc(3 * np * sizeof(double)),
                      .gh = malloc(9 * np * sizeof(double))};
        tf_ctx_init(&b.ctx);
        tf_fail(&b.ctx, "out of memory"); /* the message when an allocation failed */
        b.ctx.threads = 1;                /* loops below this one run on its thread alone */
        int ok = b.x && b.w && b.uh && b.gh;
#pragma omp for schedule(dynamic, 8)
        for (size_t c = 0; c < nc; ++c) {
            if (!ok || cell_sums(s, u, q, d, &b, c, &per[c]) != 0) {
#pragma omp critical(tf_error_norm_fail)
                if (c < failed) {
                    failed = c;
                    tf_fail(ctx, "%s", b.ctx.err); /* the lowest failing cell's */
                }
            }
        }
        free(b.x);
        free(b.w);
        free(b.uh);
        free(b.gh);
    }
    return failed < nc ? -1 : 0;
}

int tf_error_norms(const tf_solver *s, const double *u, unsigned order, double *l2,
                   double *energy)
{
    const tf_problem *p = s->problem;
    if (p->analytic.kind == TF_ANALYTIC_NONE) {
        return tf_fail(s->ctx, "%s has no analytic solution", p->source);
    }
    double lo[3], hi[3];
    tf_problem_bounds(p, lo, hi);
    tf_cells q;
    if (tf_cells_init(&q, lo, hi, s->opts.cells, order) != 0) {
        return tf_fail(s->ctx, "bad quadrature order %u", order);
    }
    double d[36], young, poisson;
    tf_material_moduli(&p->material, &young, &poisson);
    tf_dmatrix(young, poisson, d);
    size_t nc = tf_cells_count(&q);
    sums *per = calloc(nc, sizeof *per);
    if (per == NULL) {
        return tf_fail(s->ctx, "out of memory");
    }
    if (all_cells(s->ctx, s, u, &q, d, per) != 0) {
        free(per);
        return tf_fail(s->ctx, "the error integral: %s", s->ctx->err);
    }
    /* Summed in cell order: the same bits whatever the thread count. */
    sums t = {0, 0, 0, 0};
    for (size_t c = 0; c < nc; ++c) {
        t.e2 += per[c].e2;
        t.u2 += per[c].u2;
        t.ee += per[c].ee;
        t.ue += per[c].ue;
    }
    free(per);
    *l2 = t.u2 > 0 ? sqrt(t.e2 / t.u2) : sqrt(t.e2);
    *energy = t.ue > 0 ? sqrt(t.ee / t.ue) : sqrt(t.ee);
    return 0;
}
