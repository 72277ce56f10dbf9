/*
 * variant_solver.c — linked into test builds of tissuefit and tissuefit-mpi
 * with -Wl,--wrap=tf_solver_create: every solver the tool makes becomes a
 * variant of the scene's own that behaves as a nonlinear one does where the
 * distribution is concerned (tests/mpi/mpi.mk):
 *
 *   - it declares no capability, so the fit solves every case, one by one,
 *     through the case runner (fitting/case_runner.h);
 *   - its answer depends on where a case starts, as an iterative solver's
 *     does: u = x + (u0 - x) / 1024 for the scene solver's x, so a case
 *     started from another field than the graph names gives other bits;
 *   - it fails on request, naming the step as the nonlinear solver does:
 *     TF_TEST_FAIL_FZ=v  fails every case whose force has f_z < v;
 *     TF_TEST_FAIL_RANK=r  fails the third case solved on MPI rank r
 *     (OMPI_COMM_WORLD_RANK), a rank that breaks whatever it is handed;
 *   - TF_TEST_FAIL_CREATE_RANK=r: the solver cannot be built on rank r (as
 *     when a node lacks the memory), before any case is handed out;
 *   - TF_TEST_NUDGE_RANK=r moves every value solved on rank r by one ulp:
 *     the check's counter-test, which the header comparison must notice.
 *
 * Test code: the counter of solved cases is a static.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "solvers/solver.h"

tf_solver *__wrap_tf_solver_create(const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx);

static tf_solver_ops variant;
static const tf_solver_ops *real;
static int solved;

static unsigned no_caps(const tf_solver *s)
{
    (void)s;
    return 0;
}

static int env_int(const char *name, int fallback)
{
    const char *v = getenv(name);
    return v != NULL ? atoi(v) : fallback;
}

static int solve(tf_solver *s, int contact, const double (*forces)[3], size_t n, const double *u0,
                 double *u)
{
    const size_t n3 = 3 * s->ops->node_count(s);
    const char *fz = getenv("TF_TEST_FAIL_FZ");
    const int rank = env_int("OMPI_COMM_WORLD_RANK", 0), hold_ms = env_int("TF_TEST_HOLD_RANK0_MS", 0);
    for (size_t k = 0; k < n; ++k) {
        ++solved;
        if (rank == 0 && hold_ms > 0) {
            /* rank 0's own thread slowed, so that the workers get cases even
             * when the machine starts them late (the counter-tests below
             * need a worker's cases; a busy machine made them flaky) */
            const struct timespec ts = {hold_ms / 1000, (long)(hold_ms % 1000) * 1000000L};
            nanosleep(&ts, NULL);
        }
        if ((fz != NULL && contact >= 0 && forces[k][2] < atof(fz)) ||
            (env_int("TF_TEST_FAIL_RANK", -1) == rank && solved == 1)) {
            return tf_fail(s->ctx, "Newton did not converge in load step 4 of 8 (injected by "
                           "the test at force %g, %g, %g N)",
                           forces[k][0], forces[k][1], forces[k][2]);
        }
        double *x = u + k * n3;
        if (real->solve(s, contact, forces + k, 1, NULL, x) != 0) {
            return -1;
        }
        for (size_t d = 0; u0 != NULL && d < n3; ++d) {
            x[d] += (u0[k * n3 + d] - x[d]) / 1024;
        }
        for (size_t d = 0; env_int("TF_TEST_NUDGE_RANK", -1) == rank &&
                           d < n3; ++d) {
            x[d] = nextafter(x[d], INFINITY);
        }
    }
    return 0;
}

tf_solver *__wrap_tf_solver_create(const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx)
{
    real = tf_solver_type_find((o != NULL ? o : &p->solver)->method);
    if (real == NULL) {
        tf_fail(ctx, "no solver '%s'", (o != NULL ? o : &p->solver)->method);
        return NULL;
    }
    if (env_int("TF_TEST_FAIL_CREATE_RANK", -1) == env_int("OMPI_COMM_WORLD_RANK", 0)) {
        tf_fail(ctx, "out of memory for the stiffness matrix (injected by the test)");
        return NULL;
    }
    variant = *real;
    variant.caps = no_caps;
    variant.solve = solve;
    return tf_solver_create_as(&variant, p, o, ctx);
}
