/*
 * verify.c — a problem against its analytic solution (verify.h).
 */
#include "verify/verify.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>

#include "solvers/solver.h"
#include "verify/error_norm.h"

int tf_verify_problem(const tf_problem *p, unsigned level, tf_ctx *ctx, tf_verify_row *row)
{
    if (p->analytic.kind == TF_ANALYTIC_NONE) {
        tf_fail(ctx, "%s: the scene has no reference section to verify against", p->source);
        return -2;
    }
    double t0 = omp_get_wtime();
    tf_solver *sv = tf_solver_create(p, NULL, ctx);
    double *u = malloc(3 * p->cloud.n * sizeof *u);
    int rc = sv && u ? tf_solver_solve(sv, -1, NULL, 1, NULL, u) : -1;
    if (rc == 0) {
        row->seconds = omp_get_wtime() - t0;
        tf_solver_report(sv);
        rc = tf_error_norms(sv, u, TF_VERIFY_ERROR_ORDER, &row->error_l2, &row->error_energy);
    } else if (sv != NULL && u == NULL) {
        tf_fail(ctx, "out of memory");
    }
    row->level = level;
    row->nodes = p->cloud.n;
    row->dofs = 3 * p->cloud.n;
    row->h = 0;
    for (int a = 0; a < 3 && row->h == 0; ++a) {
        row->h = p->cloud.grid[a] > 2 ? p->cloud.spacing[a] : 0;
    }
    row->rate = NAN;
    free(u);
    tf_solver_destroy(sv);
    return rc;
}

void tf_verify_rates(tf_verify_row *rows, size_t n)
{
    for (size_t k = 1; k < n; ++k) {
        double dh = log(rows[k - 1].h / rows[k].h);
        rows[k].rate = dh != 0 ? log(rows[k - 1].error_l2 / rows[k].error_l2) / dh : NAN;
    }
}
