/*
 * dist_session.c — the MPI session: start and end, the agreement before
 * any case is solved, the workers' quiet log, polling receives (dist.h).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "base/blas_pin.h"
#include "base/log.h"
#include "dist/dist_internal.h"

tf_dist *tf_dist_init(tf_ctx *ctx, int *argc, char ***argv)
{
    int provided = 0;
    if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        tf_fail(ctx, "MPI_Init_thread failed");
        return NULL;
    }
    tf_dist *d = calloc(1, sizeof *d);
    if (d == NULL || provided < MPI_THREAD_FUNNELED) {
        tf_fail(ctx, "%s",
                d ? "this MPI library gives no MPI_THREAD_FUNNELED support (rank 0 solves cases "
                    "in a thread of its own)"
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

double dist_cpu_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

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

#define CORE_MAX 32 /* an OpenBLAS kernel family's name */

/* What every rank said before any case: its status, the checksum of what
 * it read, its OpenBLAS kernels, its last error (rank 0 only). */
typedef struct ranks_said {
    int *rc;
    uint32_t *print;
    char *core, *msgs;
} ranks_said;

/* 0, or 2 when a rank read another scene or runs other BLAS kernels than
 * rank 0: its cases would give other bits. */
static int same_inputs(const ranks_said *a, int size)
{
    for (int r = 1; r < size; ++r) {
        if (a->print[r] != a->print[0] ||
            strcmp(a->core + (size_t)r * CORE_MAX, a->core) != 0) {
            return 2;
        }
    }
    return 0;
}

/* Rank 0's report of what went wrong elsewhere. */
static void report(tf_ctx *ctx, const ranks_said *a, int size)
{
    for (int r = 1; r < size; ++r) {
        const char *core = a->core + (size_t)r * CORE_MAX;
        if (a->rc[r] != 0) {
            tf_error(ctx, "rank %d: %s", r, a->msgs + (size_t)r * TF_CTX_ERR_MAX);
        } else if (a->print[r] != a->print[0]) {
            tf_error(ctx, "rank %d read another scene or other overrides than rank 0 (checksum "
                     "%08x, rank 0: %08x): every rank must read the same files",
                     r, (unsigned)a->print[r], (unsigned)a->print[0]);
        } else if (strcmp(core, a->core) != 0) {
            tf_error(ctx, "rank %d uses OpenBLAS's %s kernels, rank 0 %s: its cases would differ "
                     "in the last bits (run every rank on CPUs with the same kernel family, "
                     "blas_pin.h)",
                     r, core, a->core);
        }
    }
}

int tf_dist_agree(tf_dist *d, tf_ctx *ctx, int rc, uint32_t fingerprint)
{
    const size_t n = (size_t)d->size;
    char core[CORE_MAX] = "";
    ranks_said a = {calloc(n, sizeof *a.rc), calloc(n, sizeof *a.print), calloc(n, CORE_MAX),
                    d->rank == 0 ? calloc(n, TF_CTX_ERR_MAX) : NULL};
    if (!a.rc || !a.print || !a.core || (d->rank == 0 && !a.msgs)) {
        fprintf(stderr, "tissuefit: error: rank %d: out of memory\n", d->rank);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    snprintf(core, sizeof core, "%s", tf_blas_coretype());
    MPI_Allgather(&rc, 1, MPI_INT, a.rc, 1, MPI_INT, MPI_COMM_WORLD);
    MPI_Allgather(&fingerprint, 1, MPI_UINT32_T, a.print, 1, MPI_UINT32_T, MPI_COMM_WORLD);
    MPI_Allgather(core, CORE_MAX, MPI_CHAR, a.core, CORE_MAX, MPI_CHAR, MPI_COMM_WORLD);
    MPI_Gather(d->last_error, TF_CTX_ERR_MAX, MPI_CHAR, a.msgs, TF_CTX_ERR_MAX, MPI_CHAR, 0,
               MPI_COMM_WORLD);
    int worst = 0;
    for (size_t r = 0; r < n; ++r) {
        worst = a.rc[r] > worst ? a.rc[r] : worst;
    }
    worst = worst != 0 ? worst : same_inputs(&a, d->size);
    if (d->rank == 0 && a.rc[0] == 0) {
        report(ctx, &a, d->size);
    }
    free(a.rc);
    free(a.print);
    free(a.core);
    free(a.msgs);
    return worst;
}

void tf_dist_stop(tf_dist *d)
{
    const dist_msg stop = {0};
    for (int r = 1; r < d->size; ++r) {
        MPI_Send(&stop, sizeof stop, MPI_BYTE, r, DIST_STOP, MPI_COMM_WORLD);
    }
}
