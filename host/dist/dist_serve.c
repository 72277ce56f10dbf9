/*
 * dist_serve.c — a worker rank: solves the cases rank 0 hands out until it
 * says stop (dist.h, the messages in dist_internal.h).
 */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dist/dist_internal.h"

typedef struct job {
    int contact;
    size_t n_keep, dofs;
    size_t *keep;
    double *start, *full, *kept;
} job;

static void job_free(job *j)
{
    free(j->keep);
    free(j->start);
    free(j->full);
    free(j->kept);
    memset(j, 0, sizeof *j);
}

static void out_of_memory(const tf_dist *d)
{
    fprintf(stderr, "tissuefit: error: rank %d: out of memory for a case list\n", d->rank);
    MPI_Abort(MPI_COMM_WORLD, 1);
}

static void job_start(const tf_dist *d, job *j, const dist_msg *m, size_t dofs)
{
    job_free(j);
    j->contact = m->contact;
    j->n_keep = (size_t)m->index;
    j->dofs = dofs;
    j->keep = malloc((j->n_keep + 1) * sizeof *j->keep);
    j->start = malloc(dofs * sizeof *j->start);
    j->full = malloc(dofs * sizeof *j->full);
    j->kept = malloc((j->n_keep + 1) * sizeof *j->kept);
    uint64_t *dof = malloc((j->n_keep + 1) * sizeof *dof);
    if (!j->keep || !j->start || !j->full || !j->kept || !dof) {
        out_of_memory(d);
    }
    MPI_Recv(dof, (int)j->n_keep, MPI_UINT64_T, 0, DIST_KEEP, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    for (size_t k = 0; k < j->n_keep; ++k) {
        j->keep[k] = (size_t)dof[k];
    }
    free(dof);
}

/* One case: the same single solve as every runner's (tf_case_solve_one). */
static void solve_case(tf_solver *s, job *j, const dist_msg *m)
{
    if (m->flags & DIST_HAS_START) {
        MPI_Recv(j->start, (int)j->dofs, MPI_DOUBLE, 0, DIST_FIELD, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
    }
    const double force[1][3] = {{m->force[0], m->force[1], m->force[2]}};
    const tf_case_list one = {.contact = j->contact, .n = 1, .force = force,
                              .n_keep = j->n_keep, .keep = j->keep};
    dist_msg done = {.index = m->index};
    double t0 = omp_get_wtime(), c0 = dist_cpu_seconds();
    s->ctx->err[0] = '\0';
    int rc = tf_case_solve_one(s, &one, 0, (m->flags & DIST_HAS_START) ? j->start : NULL, j->full);
    done.seconds = omp_get_wtime() - t0;
    done.cpu = dist_cpu_seconds() - c0;
    if (rc != 0) {
        MPI_Send(&done, sizeof done, MPI_BYTE, 0, DIST_DONE, MPI_COMM_WORLD);
        MPI_Send(s->ctx->err, TF_CTX_ERR_MAX, MPI_CHAR, 0, DIST_ERROR, MPI_COMM_WORLD);
        return;
    }
    tf_case_keep(&one, j->full, j->kept);
    done.flags = DIST_OK | (m->flags & DIST_WANT_FIELD);
    MPI_Send(&done, sizeof done, MPI_BYTE, 0, DIST_DONE, MPI_COMM_WORLD);
    MPI_Send(j->kept, (int)j->n_keep, MPI_DOUBLE, 0, DIST_KEPT, MPI_COMM_WORLD);
    if (m->flags & DIST_WANT_FIELD) {
        MPI_Send(j->full, (int)j->dofs, MPI_DOUBLE, 0, DIST_FIELD, MPI_COMM_WORLD);
    }
}

int tf_dist_serve(tf_dist *d, tf_solver *s)
{
    const size_t dofs = 3 * tf_solver_node_count(s);
    job j = {0};
    for (;;) {
        dist_msg m;
        MPI_Status st;
        dist_recv(&m, sizeof m, MPI_BYTE, 0, MPI_ANY_TAG, &st);
        switch (st.MPI_TAG) {
        case DIST_JOB:
            job_start(d, &j, &m, dofs);
            break;
        case DIST_CASE:
            solve_case(s, &j, &m);
            break;
        case DIST_JOB_END:
            job_free(&j);
            break;
        case DIST_STOP:
            job_free(&j);
            return 0;
        default:
            fprintf(stderr, "tissuefit: error: rank %d: unexpected message %d from rank 0\n",
                    d->rank, st.MPI_TAG);
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
    }
}
