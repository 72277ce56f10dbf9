/*
 * dist_runner.c — rank 0's runner: hands the cases of a list out to the
 * worker ranks and to a thread of its own, whichever is free, and stores
 * what comes back in case order (dist.h; the messages in dist_internal.h).
 */
#include <omp.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "base/log.h"
#include "base/progress.h"
#include "dist/dist_internal.h"

enum { WAITING, HANDED, SOLVED };
enum { L_IDLE, L_WORK, L_DONE, L_QUIT };

/* Rank 0's own solver thread; only the main thread calls MPI. */
typedef struct local {
    pthread_mutex_t mu;
    pthread_cond_t cv;
    int state;
    tf_solver *s;
    const tf_case_list *l;
    size_t index;
    const double *start;
    double *out;
    int rc;
    double seconds, cpu;
} local;

typedef struct sched {
    tf_dist *d;
    tf_solver *s;
    const tf_case_list *l;
    double *kept;
    size_t dofs, next, solved, in_flight;
    unsigned char *is_start, *state;
    double **field;   /* the solutions cases start from */
    double *full;     /* rank 0's solution of a case no other starts from */
    long *busy;       /* per rank: the case it solves, or -1 */
    size_t *cases;    /* per rank: cases solved */
    double *seconds;  /* per rank: wall time solving them ... */
    double *cpu;      /* ... and CPU time of the solving thread */
    int failed, failed_rank;
    size_t failed_case;
    char why[TF_CTX_ERR_MAX];
    local me;
    tf_progress pr; /* a line every few seconds as cases come back */
} sched;

static void *local_main(void *arg)
{
    local *w = arg;
    pthread_mutex_lock(&w->mu);
    for (;;) {
        while (w->state == L_IDLE || w->state == L_DONE) {
            pthread_cond_wait(&w->cv, &w->mu);
        }
        if (w->state == L_QUIT) {
            break;
        }
        pthread_mutex_unlock(&w->mu);
        double t0 = omp_get_wtime(), c0 = dist_cpu_seconds();
        int rc = tf_case_solve_one(w->s, w->l, w->index, w->start, w->out);
        double dt = omp_get_wtime() - t0, dc = dist_cpu_seconds() - c0;
        pthread_mutex_lock(&w->mu);
        w->rc = rc;
        w->seconds = dt;
        w->cpu = dc;
        w->state = L_DONE;
    }
    pthread_mutex_unlock(&w->mu);
    return NULL;
}

static long start_of(const tf_case_list *l, size_t i)
{
    return l->from != NULL ? l->from[i] : -1;
}

/* The lowest case not handed out whose start is solved (l->n: none). */
static size_t next_ready(sched *sc)
{
    while (sc->next < sc->l->n && sc->state[sc->next] != WAITING) {
        ++sc->next;
    }
    for (size_t i = sc->next; i < sc->l->n; ++i) {
        long from = start_of(sc->l, i);
        if (sc->state[i] == WAITING && (from < 0 || sc->state[from] == SOLVED)) {
            return i;
        }
    }
    return sc->l->n;
}

/* Marks case i handed to rank r; room for its field when others start from it. */
static double *hand(sched *sc, size_t i, int r)
{
    sc->state[i] = HANDED;
    sc->busy[r] = (long)i;
    ++sc->in_flight;
    if (sc->is_start[i] && (sc->field[i] = malloc(sc->dofs * sizeof(double))) == NULL) {
        fprintf(stderr, "tissuefit: error: rank 0: out of memory for case %zu's solution\n", i);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    return sc->field[i];
}

static void hand_to_worker(sched *sc, int r, size_t i)
{
    long from = start_of(sc->l, i);
    hand(sc, i, r);
    dist_msg m = {.index = (int64_t)i,
                  .flags = (from >= 0 ? DIST_HAS_START : 0) |
                           (sc->is_start[i] ? DIST_WANT_FIELD : 0)};
    memcpy(m.force, sc->l->force[i], sizeof m.force);
    MPI_Send(&m, sizeof m, MPI_BYTE, r, DIST_CASE, MPI_COMM_WORLD);
    if (from >= 0) {
        MPI_Send(sc->field[from], (int)sc->dofs, MPI_DOUBLE, r, DIST_FIELD, MPI_COMM_WORLD);
    }
}

static void hand_to_local(sched *sc, size_t i)
{
    long from = start_of(sc->l, i);
    double *field = hand(sc, i, 0);
    pthread_mutex_lock(&sc->me.mu);
    sc->me.index = i;
    sc->me.start = from >= 0 ? sc->field[from] : NULL;
    sc->me.out = field != NULL ? field : sc->full;
    sc->me.state = L_WORK;
    pthread_cond_signal(&sc->me.cv);
    pthread_mutex_unlock(&sc->me.mu);
}

static void finished(sched *sc, int r, size_t i, const double time[2], int ok)
{
    sc->busy[r] = -1;
    --sc->in_flight;
    sc->seconds[r] += time[0];
    sc->cpu[r] += time[1];
    if (ok) {
        sc->state[i] = SOLVED;
        ++sc->solved;
        ++sc->cases[r];
        tf_progress_line(&sc->pr, "cases: %zu of %zu solved on %d ranks", sc->solved, sc->l->n,
                         sc->d->size);
    } else if (!sc->failed) {
        sc->failed = 1;
        sc->failed_rank = r;
        sc->failed_case = i;
    }
}

/* Results that have come from the workers; returns how many. */
static int poll_workers(sched *sc)
{
    int got = 0, flag = 1;
    while (flag) {
        MPI_Status st;
        MPI_Iprobe(MPI_ANY_SOURCE, DIST_DONE, MPI_COMM_WORLD, &flag, &st);
        if (!flag) {
            break;
        }
        const int r = st.MPI_SOURCE;
        dist_msg m;
        MPI_Recv(&m, sizeof m, MPI_BYTE, r, DIST_DONE, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        const size_t i = (size_t)m.index;
        if (m.flags & DIST_OK) {
            MPI_Recv(sc->kept + i * sc->l->n_keep, (int)sc->l->n_keep, MPI_DOUBLE, r, DIST_KEPT,
                     MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (m.flags & DIST_WANT_FIELD) {
                MPI_Recv(sc->field[i], (int)sc->dofs, MPI_DOUBLE, r, DIST_FIELD, MPI_COMM_WORLD,
                         MPI_STATUS_IGNORE);
            }
        } else {
            char why[TF_CTX_ERR_MAX];
            MPI_Recv(why, TF_CTX_ERR_MAX, MPI_CHAR, r, DIST_ERROR, MPI_COMM_WORLD,
                     MPI_STATUS_IGNORE);
            why[TF_CTX_ERR_MAX - 1] = '\0';
            if (!sc->failed) {
                memcpy(sc->why, why, sizeof why);
            }
        }
        finished(sc, r, i, (const double[2]){m.seconds, m.cpu}, (m.flags & DIST_OK) != 0);
        ++got;
    }
    return got;
}

/* The result of rank 0's own thread, if it has one; returns 1 then. */
static int poll_local(sched *sc)
{
    pthread_mutex_lock(&sc->me.mu);
    int done = sc->me.state == L_DONE;
    if (done) {
        sc->me.state = L_IDLE;
    }
    pthread_mutex_unlock(&sc->me.mu);
    if (!done) {
        return 0;
    }
    const size_t i = sc->me.index;
    if (sc->me.rc == 0) {
        tf_case_keep(sc->l, sc->me.out, sc->kept + i * sc->l->n_keep);
    } else if (!sc->failed) {
        snprintf(sc->why, sizeof sc->why, "%s", sc->s->ctx->err);
    }
    finished(sc, 0, i, (const double[2]){sc->me.seconds, sc->me.cpu}, sc->me.rc == 0);
    return 1;
}

/* Hands out what is ready, collects what is done, until every case is
 * solved, or one failed and the others in flight have come back. */
static void schedule(sched *sc)
{
    const int size = sc->d->size;
    long nap = 20000; /* ns */
    for (;;) {
        for (int r = 0; !sc->failed && r < size; ++r) {
            size_t i = sc->busy[r] < 0 ? next_ready(sc) : sc->l->n;
            if (i < sc->l->n) {
                if (r == 0) {
                    hand_to_local(sc, i);
                } else {
                    hand_to_worker(sc, r, i);
                }
            }
        }
        if (sc->in_flight == 0) {
            return; /* all solved, or failed (from[i] < i: a case is always ready) */
        }
        if (poll_workers(sc) + poll_local(sc) > 0) {
            nap = 20000;
        } else {
            nanosleep(&(struct timespec){0, nap}, NULL);
            nap = nap < 1000000 ? 2 * nap : nap;
        }
    }
}

/* The job's DOFs to every worker: they keep those of each case. */
static void announce(const sched *sc)
{
    const tf_case_list *l = sc->l;
    uint64_t *dof = malloc((l->n_keep + 1) * sizeof *dof);
    if (dof == NULL) {
        fprintf(stderr, "tissuefit: error: rank 0: out of memory\n");
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    for (size_t k = 0; k < l->n_keep; ++k) {
        dof[k] = l->keep[k];
    }
    const dist_msg job = {.index = (int64_t)l->n_keep, .contact = l->contact};
    for (int r = 1; r < sc->d->size; ++r) {
        MPI_Send(&job, sizeof job, MPI_BYTE, r, DIST_JOB, MPI_COMM_WORLD);
        MPI_Send(dof, (int)l->n_keep, MPI_UINT64_T, r, DIST_KEEP, MPI_COMM_WORLD);
    }
    free(dof);
}

static void summary(const sched *sc, double wall)
{
    char line[2048];
    int k = snprintf(line, sizeof line, "dist: %zu cases on %d ranks in %.2f s (", sc->solved,
                     sc->d->size, wall);
    for (int r = 0; r < sc->d->size && k > 0 && (size_t)k < sizeof line; ++r) {
        k += snprintf(line + k, sizeof line - (size_t)k, "%srank %d: %zu in %.2f s (%.2f s CPU)",
                      r ? ", " : "", r, sc->cases[r], sc->seconds[r], sc->cpu[r]);
    }
    tf_info(sc->s->ctx, "%s)", line);
}

static void sched_free(sched *sc)
{
    for (size_t i = 0; sc->field != NULL && i < sc->l->n; ++i) {
        free(sc->field[i]);
    }
    free(sc->field);
    free(sc->is_start);
    free(sc->state);
    free(sc->full);
    free(sc->busy);
    free(sc->cases);
    free(sc->seconds);
    free(sc->cpu);
}

int dist_run(const tf_case_runner *r, tf_solver *s, const tf_case_list *l, double *kept)
{
    tf_dist *d = r->state;
    if (d->size == 1) {
        return tf_case_run(NULL, s, l, kept);
    }
    const size_t size = (size_t)d->size;
    sched sc = {.d = d, .s = s, .l = l, .kept = kept, .dofs = 3 * tf_solver_node_count(s)};
    sc.is_start = malloc(l->n);
    sc.state = calloc(l->n, 1);
    sc.field = calloc(l->n, sizeof *sc.field);
    sc.full = malloc(sc.dofs * sizeof *sc.full);
    sc.busy = malloc(size * sizeof *sc.busy);
    sc.cases = calloc(size, sizeof *sc.cases);
    sc.seconds = calloc(size, sizeof *sc.seconds);
    sc.cpu = calloc(size, sizeof *sc.cpu);
    sc.me = (local){.state = L_IDLE, .s = s, .l = l};
    if (!sc.is_start || !sc.state || !sc.field || !sc.full || !sc.busy || !sc.cases ||
        !sc.seconds || !sc.cpu || pthread_mutex_init(&sc.me.mu, NULL) != 0 ||
        pthread_cond_init(&sc.me.cv, NULL) != 0) {
        sched_free(&sc);
        return tf_fail(s->ctx, "out of memory to spread %zu load cases", l->n);
    }
    tf_case_starts(l, sc.is_start);
    for (size_t k = 0; k < size; ++k) {
        sc.busy[k] = -1;
    }
    pthread_t thread;
    double t0 = omp_get_wtime();
    tf_progress_start(&sc.pr, s->ctx, TF_CASE_PROGRESS_S);
    if (pthread_create(&thread, NULL, local_main, &sc.me) != 0) {
        sched_free(&sc);
        return tf_fail(s->ctx, "cannot start rank 0's solver thread");
    }
    announce(&sc);
    schedule(&sc);
    const dist_msg end = {0};
    for (int k = 1; k < d->size; ++k) {
        MPI_Send(&end, sizeof end, MPI_BYTE, k, DIST_JOB_END, MPI_COMM_WORLD);
    }
    pthread_mutex_lock(&sc.me.mu);
    sc.me.state = L_QUIT;
    pthread_cond_signal(&sc.me.cv);
    pthread_mutex_unlock(&sc.me.mu);
    pthread_join(thread, NULL);
    pthread_mutex_destroy(&sc.me.mu);
    pthread_cond_destroy(&sc.me.cv);
    int rc = 0;
    if (sc.failed) {
        tf_fail(s->ctx, "%s", sc.why);
        rc = tf_case_failed(s->ctx, l, sc.failed_case, sc.failed_rank);
    } else {
        summary(&sc, omp_get_wtime() - t0);
    }
    sched_free(&sc);
    return rc;
}
