/*
 * dist.h — load cases spread over MPI ranks (`tissuefit-mpi`, docs/scaling.md).
 *
 * Every rank reads the same scene and builds the same solver; rank 0 runs
 * the fit exactly as the serial tool does, and whenever it needs a case
 * list solved (fitting/case_runner.h) its runner hands the cases out one at
 * a time: to each worker rank, and to a thread of rank 0 itself, whichever
 * is free (self-scheduling, so the balance follows the measured solve
 * times), in list order among the cases whose start is solved.  A case that
 * starts from another's solution receives that field with it; results come
 * back to rank 0 and are stored in case order.  Each case is the same single
 * tf_solver_solve call as in the serial tool, from the same start (the
 * continuation graph is the list's), so the header is the same bytes for
 * any number of ranks and any schedule.
 *
 * Only rank 0's main thread calls MPI (MPI_THREAD_FUNNELED).  Waiting ranks
 * poll with short sleeps rather than spin, so a rank that waits while rank
 * 0 fits does not take a core from it.
 *
 * A case that fails stops the hand-out; the cases in flight finish and are
 * dropped, and the runner returns the failure naming the case and the rank.
 * Nothing here writes a file.
 */
#ifndef TF_DIST_H
#define TF_DIST_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "fitting/case_runner.h"
#include "solvers/solver.h"

typedef struct tf_dist tf_dist;

/* MPI_Init_thread (FUNNELED) and the session; NULL with a message in ctx->err
 * (MPI_Finalize already called then). */
tf_dist *tf_dist_init(tf_ctx *ctx, int *argc, char ***argv);

/* MPI_Finalize and the session's memory. */
void tf_dist_finalize(tf_dist *d);

int tf_dist_rank(const tf_dist *d);
int tf_dist_size(const tf_dist *d);

/* A log sink for the worker ranks' contexts: drops every message and keeps
 * the last error's text for tf_dist_agree (sink_user: the session). */
void tf_dist_sink(void *user, tf_log_level level, const char *msg);

/* Collective, once every rank has its scene and solver (or failed to):
 * rc is this rank's exit status so far (0: ready), fingerprint a checksum of
 * what it read (scene bytes and overrides).  Returns the run's status, the
 * same on every rank: the worst rc, or 2 when a rank read something else
 * than rank 0 or runs other OpenBLAS kernels (base/blas_pin.h), either of
 * which would change its cases' bits.  Rank 0 reports what went wrong on
 * the others (a failure it did not share, a different scene or kernel). */
int tf_dist_agree(tf_dist *d, tf_ctx *ctx, int rc, uint32_t fingerprint);

/* Rank 0: the runner that spreads case lists over the ranks (with one rank:
 * the serial runner's work, here). */
const tf_case_runner *tf_dist_runner(tf_dist *d);

/* Worker ranks: solves what rank 0 hands out with s until tf_dist_stop.
 * Returns 0 (an MPI error aborts the job). */
int tf_dist_serve(tf_dist *d, tf_solver *s);

/* Rank 0, after the fit: the workers leave tf_dist_serve. */
void tf_dist_stop(tf_dist *d);

#endif /* TF_DIST_H */
