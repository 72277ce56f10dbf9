/*
 * main_mpi.c — `tissuefit-mpi`: `tissuefit fit` with the load cases spread
 * over the ranks of an MPI job (dist/dist.h, docs/scaling.md):
 *
 *   mpirun -n N tissuefit-mpi [-q] fit SCENE -o NAME.h [fit options]
 *
 * Every rank reads the scene and builds the solver; rank 0 fits and writes
 * the header (the same bytes as `tissuefit fit`), the others solve the
 * cases it hands out and stay silent.
 */
#include <stdio.h>
#include <string.h>

#include "base/blas_pin.h"
#include "base/interrupts.h"
#include "base/log.h"
#include "cli/cli.h"
#include "cli/cmd_fit.h"
#include "dist/dist.h"
#include "tfit.h"

static void usage(FILE *out)
{
    fprintf(out,
            "usage: mpirun -n N tissuefit-mpi [-q] fit SCENE -o FILE.h [OPTIONS]\n"
            "       tissuefit-mpi fit --help\n"
            "       tissuefit-mpi --version\n\n"
            "`tissuefit fit` with the load cases of a scene whose solver is not affine\n"
            "(nonlinear laws) solved on every rank: rank 0 fits and writes exactly the\n"
            "bytes `tissuefit fit` writes, whatever the number of ranks.  A case that\n"
            "fails stops the run with the case and the rank named (exit 1, nothing\n"
            "written).  Each rank uses OMP_NUM_THREADS threads.  docs/scaling.md.\n\n"
            "Exit status: 0 success, 1 failure while running, 2 bad usage or input.\n");
}

static int agree(void *user, tf_ctx *ctx, int rc, uint32_t fingerprint)
{
    return tf_dist_agree(user, ctx, rc, fingerprint);
}

static int serve(void *user, tf_solver *s) { return tf_dist_serve(user, s); }
static void stop(void *user) { tf_dist_stop(user); }

static int dispatch(tf_ctx *ctx, tf_dist *d, int argc, char **argv)
{
    const int root = tf_dist_rank(d) == 0;
    int i = 1;
    for (; i < argc && argv[i][0] == '-'; ++i) {
        if (strcmp(argv[i], "-q") == 0 || strcmp(argv[i], "--quiet") == 0) {
            ctx->level = root ? TF_LOG_WARN : ctx->level;
        } else if (strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "--help") == 0) {
            if (root) {
                usage(stdout);
            }
            return TF_EXIT_OK;
        } else if (strcmp(argv[i], "--version") == 0) {
            if (root) {
                printf("tissuefit-mpi %s (tfit API %d, OpenBLAS kernels %s, %d ranks)\n",
                       TFIT_TOOL_VERSION, TFIT_API_VERSION, tf_blas_coretype(), tf_dist_size(d));
            }
            return TF_EXIT_OK;
        } else {
            tf_error(ctx, "unknown option '%s' (try 'tissuefit-mpi --help')", argv[i]);
            return TF_EXIT_USAGE;
        }
    }
    if (i == argc || strcmp(argv[i], "fit") != 0) {
        tf_error(ctx, "%s%s%s: tissuefit-mpi runs `fit` only (the other commands: tissuefit)",
                 i == argc ? "no command" : "'", i == argc ? "" : argv[i], i == argc ? "" : "'");
        if (root) {
            usage(stderr);
        }
        return TF_EXIT_USAGE;
    }
    if (tf_wants_help(argc - i, argv + i)) {
        if (root) {
            tf_cmd_fit.help(stdout);
        }
        return TF_EXIT_OK;
    }
    const tf_fit_ranks ranks = {.worker = !root, .runner = tf_dist_runner(d), .agree = agree,
                                .serve = serve, .stop = stop, .user = d};
    return tf_cmd_fit_ranks(ctx, argc - i, argv + i, &ranks);
}

int main(int argc, char **argv)
{
    tf_blas_pin(argv);
    tf_ctx run;
    tf_ctx_init(&run);
    /* before MPI's and OpenMP's threads: interrupts wait while outputs are
     * written (base/interrupts.h) */
    tf_interrupts watch;
    run.interrupts = tf_interrupts_start(&watch) == 0 ? &watch : NULL;
    tf_dist *d = tf_dist_init(&run, &argc, &argv);
    if (d == NULL) {
        fprintf(stderr, "tissuefit-mpi: error: %s\n", run.err);
        return TF_EXIT_FAIL;
    }
    if (tf_dist_rank(d) > 0) { /* silent; the last error goes to rank 0 */
        run.level = TF_LOG_ERROR;
        run.sink = tf_dist_sink;
        run.sink_user = d;
    }
    int rc = tf_finish_stdout(&run, dispatch(&run, d, argc, argv));
    tf_dist_finalize(d);
    return rc;
}
