/*
 * cmd_fit.h — `tissuefit fit` on every rank of an MPI job (main_mpi.c,
 * dist/dist.h): each rank parses the same command line, reads the scene and
 * builds the solver; then rank 0 fits and writes exactly what the serial
 * tool writes while the others solve the cases it hands out.
 */
#ifndef TF_CMD_FIT_H
#define TF_CMD_FIT_H

#include <stdint.h>

#include "base/context.h"
#include "fitting/case_runner.h"
#include "solvers/solver.h"

typedef struct tf_fit_ranks {
    int worker;                   /* this rank solves cases; rank 0 fits */
    const tf_case_runner *runner; /* rank 0: spreads the case lists */
    /* Collective, once the solver is built (rc: this rank's exit status so
     * far, 0 when ready; fingerprint: a checksum of the scene and the
     * overrides): the run's status, the same on every rank. */
    int (*agree)(void *user, tf_ctx *ctx, int rc, uint32_t fingerprint);
    /* Workers: solve until rank 0 stops them; returns the exit status. */
    int (*serve)(void *user, tf_solver *s);
    /* Rank 0, when the fit is over: the workers leave serve. */
    void (*stop)(void *user);
    void *user;
} tf_fit_ranks;

/* `fit` (argv[0] is the command name) as rank 0 or a worker; the exit
 * status. */
int tf_cmd_fit_ranks(tf_ctx *ctx, int argc, char **argv, const tf_fit_ranks *ranks);

#endif /* TF_CMD_FIT_H */
