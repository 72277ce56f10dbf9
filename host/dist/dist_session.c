/*
 * dist_session.c — the MPI session: start and end, the agreement before
 * any case is solved, the workers' quiet log, polling receives (dist.h).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "base/log.h"
#include "dist/dist_internal.h"

tf_dist *tf_dist_init(int *argc, char ***argv, char *err, size_t errlen)
{
    int provided = 0;
    if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        snprintf(err, errlen, "MPI_Init_thread failed");
        return NULL;
    }
    tf_dist *d = calloc(1, sizeof *d);
    if (d == NULL || provided < MPI_THREAD_FUNNELED) {
        snprintf(err, errlen, d ? "this MPI library gives no MPI_THREAD_FUNNELED support (rank 0 "
                                  "solves cases in a thread of its own)"
                                : "out of memory");
        free(d);
        MPI_Finalize();
        return NULL;
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &d->rank);
    MPI_Comm_size(MPI_COMM_WORLD, &d->size);
    d->runner = (tf_case_runner){.name = "spread over MPI ranks", .run = dist_run, .state = d};
    return d;
}

void tf_dist_finalize(tf_dist *d)
{
    MPI_Finalize();
    free(d);
}

int tf_dist_rank(const tf_dist *d) { return d->rank; }
int tf_dist_size(const tf_dist *d) { return d->size; }

void tf_dist_sink(void *user, tf_log_level level, const char *msg)
{
    tf_dist *d = user;
    if (level == TF_LOG_ERROR) {
        snprintf(d->last_error, sizeof d->last_error, "%s", msg);
    }
}

const tf_case_runner *tf_dist_runner(tf_dist *d) { return &d->runner; }

void dist_recv(void *buf, int count, MPI_Datatype type, int source, int tag, MPI_Status *st)
{
    MPI_Request req;
    int done = 0;
    long nap = 50000; /* ns */
    MPI_Irecv(buf, count, type, source, tag, MPI_COMM_WORLD, &req);
    for (;;) {
        MPI_Test(&req, &done, st);
        if (done) {
            return;
        }
        nanosleep(&(struct timespec){0, nap}, NULL);
        nap = nap < 2000000 ? 2 * nap : nap;
    }
}

/* Rank 0's report of the ranks that failed where it did not, or read
 * another scene. */
static void report(tf_ctx *ctx, const int *rc, const uint32_t *print, const char *msgs, int size)
{
    for (int r = 1; r < size; ++r) {
        if (print[r] != print[0] && rc[r] == 0) {
            tf_error(ctx, "rank %d read another scene or other overrides than rank 0 (checksum "
                     "%08x, rank 0: %08x): every rank must read the same files",
                     r, (unsigned)print[r], (unsigned)print[0]);
        } else if (rc[r] != 0) {
            tf_error(ctx, "rank %d: %s", r, msgs + (size_t)r * TF_CTX_ERR_MAX);
        }
    }
}

int tf_dist_agree(tf_dist *d, tf_ctx *ctx, int rc, uint32_t fingerprint)
{
    int *all_rc = calloc((size_t)d->size, sizeof *all_rc);
    uint32_t *print = calloc((size_t)d->size, sizeof *print);
    char *msgs = d->rank == 0 ? calloc((size_t)d->size, TF_CTX_ERR_MAX) : NULL;
    if (all_rc == NULL || print == NULL || (d->rank == 0 && msgs == NULL)) {
        fprintf(stderr, "tissuefit: error: rank %d: out of memory\n", d->rank);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    MPI_Allgather(&rc, 1, MPI_INT, all_rc, 1, MPI_INT, MPI_COMM_WORLD);
    MPI_Allgather(&fingerprint, 1, MPI_UINT32_T, print, 1, MPI_UINT32_T, MPI_COMM_WORLD);
    MPI_Gather(d->last_error, TF_CTX_ERR_MAX, MPI_CHAR, msgs, TF_CTX_ERR_MAX, MPI_CHAR, 0,
               MPI_COMM_WORLD);
    int worst = 0;
    for (int r = 0; r < d->size; ++r) {
        worst = all_rc[r] > worst ? all_rc[r] : worst;
    }
    for (int r = 1; worst == 0 && r < d->size; ++r) {
        worst = print[r] != print[0] ? 2 : 0;
    }
    if (d->rank == 0 && all_rc[0] == 0) {
        report(ctx, all_rc, print, msgs, d->size);
    }
    free(all_rc);
    free(print);
    free(msgs);
    return worst;
}

void tf_dist_stop(tf_dist *d)
{
    const dist_msg stop = {0};
    for (int r = 1; r < d->size; ++r) {
        MPI_Send(&stop, sizeof stop, MPI_BYTE, r, DIST_STOP, MPI_COMM_WORLD);
    }
}
