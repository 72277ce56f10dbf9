/*
 * dist_internal.h — the session and the messages between rank 0 and the
 * workers (dist.h).
 *
 * Rank 0 -> worker:  JOB (contact, n_keep) + KEEP (n_keep DOF indices);
 *                    CASE (index, force, flags) [+ FIELD: the start, 3N];
 *                    JOB_END; STOP.
 * Worker -> rank 0:  DONE (index, seconds, flags) + KEPT (n_keep values)
 *                    [+ FIELD: its solution, when other cases start from it]
 *                    or DONE without OK + ERROR (the solver's message).
 * Messages between two ranks arrive in the order they were sent (MPI's
 * non-overtaking rule), so a header's data follow it.  Rank 0 hands a case
 * only to a worker whose last results it has received in full, so neither
 * side can block on the other.
 */
#ifndef TF_DIST_INTERNAL_H
#define TF_DIST_INTERNAL_H

#include <mpi.h>
#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "dist/dist.h"

enum dist_tag {
    DIST_JOB = 1,
    DIST_KEEP,
    DIST_CASE,
    DIST_FIELD,
    DIST_JOB_END,
    DIST_STOP,
    DIST_DONE,
    DIST_KEPT,
    DIST_ERROR,
};

enum dist_flag {
    DIST_HAS_START = 1,  /* CASE: a FIELD follows, the case starts from it */
    DIST_WANT_FIELD = 2, /* CASE: send the solution back (a start); DONE: it follows */
    DIST_OK = 4,         /* DONE: solved (else an ERROR follows) */
};

/* Every control message: the fields a tag does not use are zero. */
typedef struct dist_msg {
    int64_t index;   /* case in the list; JOB: n_keep */
    double force[3]; /* CASE */
    double seconds;  /* DONE: the solve's wall time ... */
    double cpu;      /* ... and its thread's CPU time */
    int32_t contact; /* JOB */
    int32_t flags;
} dist_msg;

struct tf_dist {
    int rank, size;
    char last_error[TF_CTX_ERR_MAX]; /* a worker's last error (tf_dist_sink) */
    tf_case_runner runner;
};

/* Receives like MPI_Recv, polling with sleeps that grow from 50 us to 2 ms
 * while nothing comes (a waiting rank must not take a core). */
void dist_recv(void *buf, int count, MPI_Datatype type, int source, int tag, MPI_Status *st);

/* The calling thread's CPU time, s. */
double dist_cpu_seconds(void);

/* One case list spread over the ranks (dist_runner.c). */
int dist_run(const tf_case_runner *r, tf_solver *s, const tf_case_list *l, double *kept);

#endif /* TF_DIST_INTERNAL_H */
