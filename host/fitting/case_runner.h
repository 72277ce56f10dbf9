/*
 * case_runner.h — solving a list of load cases, here or elsewhere.
 *
 * A case list holds forces at one contact site and a continuation graph:
 * case i starts from the solution of an earlier case from[i] (from[i] < i)
 * or from rest (-1).  The graph is a function of the list alone
 * (case_graph.h), never of who solves what, so each case is solved from the
 * same start whatever the schedule.  Each case is one call of
 * tf_solver_solve with one force (tf_case_solve_one): its bits depend on its
 * force and its start only, so a runner may solve the cases in any order, in
 * any process, and the results are the same bytes.
 *
 * A runner returns, for every case in list order, the values at the list's
 * kept DOFs (the fit needs the output points and the contact site, not the
 * whole field).  The serial runner (runner NULL) solves the cases here in
 * list order; dist/ has one that spreads them over MPI ranks.
 */
#ifndef TF_FIT_CASE_RUNNER_H
#define TF_FIT_CASE_RUNNER_H

#include <stddef.h>

/* Seconds between the progress lines of a runner (serial or distributed). */
#define TF_CASE_PROGRESS_S 5.0

#include "base/context.h"
#include "solvers/solver.h"

/* A named run of consecutive cases ("training", "held-out"), for messages. */
typedef struct tf_case_segment {
    const char *name;
    size_t start; /* its first case; it runs to the next segment's start */
} tf_case_segment;

typedef struct tf_case_list {
    int contact;              /* contact site of every force */
    size_t n;                 /* cases */
    const double (*force)[3]; /* n forces [N] */
    const long *from;         /* n starts: an earlier case, or -1 (rest); NULL: all from rest */
    size_t n_keep;            /* values kept per case ... */
    const size_t *keep;       /* ... at these DOFs of the 3N solution */
    size_t n_seg;             /* named segments in order (0: none) */
    const tf_case_segment *seg;
} tf_case_list;

typedef struct tf_case_runner tf_case_runner;
struct tf_case_runner {
    const char *name;
    /* Solves every case of l with solver s (built from the same problem in
     * every process that takes part) into kept (n_keep x n, case after
     * case).  Returns 0, or -1 with a message in s's context that names the
     * case (tf_case_failed). */
    int (*run)(const tf_case_runner *r, tf_solver *s, const tf_case_list *l, double *kept);
    void *state;
};

/* Solves l with r (NULL: here, in list order).  Checks the list first
 * (every start an earlier case).  Returns 0, or -1 with the message. */
int tf_case_run(const tf_case_runner *r, tf_solver *s, const tf_case_list *l, double *kept);

/* is_start[i] = 1 when some case starts from case i (its field must be
 * kept), else 0 (n entries). */
void tf_case_starts(const tf_case_list *l, unsigned char *is_start);

/* Case i alone: its force, from u0 (NULL: from rest), into full (3N).
 * Every runner solves each case through this one call. */
int tf_case_solve_one(tf_solver *s, const tf_case_list *l, size_t i, const double *u0,
                      double *full);

/* The kept values of a full solution (n_keep). */
void tf_case_keep(const tf_case_list *l, const double *full, double *kept);

/* Rewrites ctx->err, holding the solver's message, as the failure of case
 * i of the list on a rank (-1: not said): "held-out case 3 (case 453 of
 * 465, force (fx, fy, fz) N) on rank 2: MESSAGE".  Returns -1. */
int tf_case_failed(tf_ctx *ctx, const tf_case_list *l, size_t i, int rank);

#endif /* TF_FIT_CASE_RUNNER_H */
