/*
 * case_runner.c — the case list's checks and messages, the one solve every
 * runner does, and the serial runner (case_runner.h).
 */
#include "fitting/case_runner.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/progress.h"


static long start_of(const tf_case_list *l, size_t i)
{
    return l->from != NULL ? l->from[i] : -1;
}

void tf_case_starts(const tf_case_list *l, unsigned char *is_start)
{
    memset(is_start, 0, l->n);
    for (size_t i = 0; i < l->n; ++i) {
        if (start_of(l, i) >= 0) {
            is_start[start_of(l, i)] = 1;
        }
    }
}

int tf_case_solve_one(tf_solver *s, const tf_case_list *l, size_t i, const double *u0,
                      double *full)
{
    return tf_solver_solve(s, l->contact, l->force + i, 1, u0, full);
}

void tf_case_keep(const tf_case_list *l, const double *full, double *kept)
{
    for (size_t k = 0; k < l->n_keep; ++k) {
        kept[k] = full[l->keep[k]];
    }
}

int tf_case_failed(tf_ctx *ctx, const tf_case_list *l, size_t i, int rank)
{
    char why[TF_CTX_ERR_MAX], on[32] = "";
    const tf_case_segment *seg = NULL;
    const double *f = l->force[i];
    snprintf(why, sizeof why, "%s", ctx->err);
    for (size_t g = l->n_seg; g-- > 0 && seg == NULL;) {
        seg = l->seg[g].start <= i ? &l->seg[g] : NULL;
    }
    if (rank >= 0) {
        snprintf(on, sizeof on, " on rank %d", rank);
    }
    if (seg == NULL) {
        return tf_fail(ctx, "case %zu of %zu (force (%.9g, %.9g, %.9g) N)%s: %s", i, l->n, f[0],
                       f[1], f[2], on, why);
    }
    return tf_fail(ctx, "%s case %zu (case %zu of %zu, force (%.9g, %.9g, %.9g) N)%s: %s",
                   seg->name, i - seg->start, i, l->n, f[0], f[1], f[2], on, why);
}

/* Here, in list order: each start's field is kept until the end. */
static int serial_run(const tf_case_runner *r, tf_solver *s, const tf_case_list *l,
                      double *kept)
{
    (void)r;
    const size_t dofs = 3 * tf_solver_node_count(s);
    unsigned char *is_start = malloc(l->n);
    double **field = calloc(l->n, sizeof *field);
    double *full = malloc(dofs * sizeof *full);
    int rc = 0;
    if (is_start == NULL || field == NULL || full == NULL) {
        rc = tf_fail(s->ctx, "out of memory for %zu load cases of %zu DOFs", l->n, dofs);
    } else {
        tf_case_starts(l, is_start);
    }
    tf_progress pr; /* a nonlinear law's cases take minutes: a line every 5 s */
    tf_progress_start(&pr, s->ctx, TF_CASE_PROGRESS_S);
    for (size_t i = 0; rc == 0 && i < l->n; ++i) {
        long from = start_of(l, i);
        double *out = is_start[i] ? (field[i] = malloc(dofs * sizeof *out)) : full;
        if (out == NULL) {
            rc = tf_fail(s->ctx, "out of memory for the field case %zu starts others from", i);
        } else if (tf_case_solve_one(s, l, i, from >= 0 ? field[from] : NULL, out) != 0) {
            rc = tf_case_failed(s->ctx, l, i, -1);
        } else {
            tf_case_keep(l, out, kept + i * l->n_keep);
            tf_progress_line(&pr, "cases: %zu of %zu solved", i + 1, l->n);
        }
    }
    for (size_t i = 0; field != NULL && i < l->n; ++i) {
        free(field[i]);
    }
    free(field);
    free(is_start);
    free(full);
    return rc;
}

static const tf_case_runner serial = {.name = "serial", .run = serial_run};

int tf_case_run(const tf_case_runner *r, tf_solver *s, const tf_case_list *l, double *kept)
{
    for (size_t i = 0; i < l->n; ++i) {
        long from = start_of(l, i);
        if (from < -1 || from >= (long)i) {
            return tf_fail(s->ctx, "case list: case %zu starts from case %ld, which is not an "
                           "earlier case", i, from);
        }
    }
    for (size_t k = 0; k < l->n_keep; ++k) {
        if (l->keep[k] >= 3 * tf_solver_node_count(s)) {
            return tf_fail(s->ctx, "case list: kept DOF %zu is not one of the solver's %zu",
                           l->keep[k], 3 * tf_solver_node_count(s));
        }
    }
    if (l->n == 0) {
        return 0;
    }
    return (r != NULL ? r : &serial)->run(r != NULL ? r : &serial, s, l, kept);
}
