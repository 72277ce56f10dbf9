/*
 * blas_pin.c — see blas_pin.h.
 */
#include "base/blas_pin.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define PIN_MARK "TISSUEFIT_BLAS_PINNED"

const char *tf_blas_wanted_coretype(void)
{
#if defined(__x86_64__)
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
        return TF_BLAS_CORETYPE;
    }
    return TF_BLAS_CORETYPE_FALLBACK;
#else
    return NULL; /* other architectures: one kernel family per build */
#endif
}

const char *tf_blas_coretype(void)
{
    const char *c = getenv("OPENBLAS_CORETYPE");
    return c != NULL ? c : "default";
}

void tf_blas_pin(char **argv)
{
    const char *core = tf_blas_wanted_coretype();
    const char *have_core = getenv("OPENBLAS_CORETYPE");
    const char *have_threads = getenv("OPENBLAS_NUM_THREADS");
    int pinned = (core == NULL || (have_core != NULL && strcmp(have_core, core) == 0)) &&
                 have_threads != NULL && strcmp(have_threads, "1") == 0;
    if (pinned || getenv(PIN_MARK) != NULL) {
        return; /* pinned, or already re-executed once (never loop) */
    }
    if (core != NULL) {
        setenv("OPENBLAS_CORETYPE", core, 1);
    }
    setenv("OPENBLAS_NUM_THREADS", "1", 1);
    /* OpenMP workers sleep between parallel regions instead of spinning:
     * the Newton solver alternates short parallel assemblies with serial
     * factorisations, and on this shared 2-core machine the spinning took
     * 85 % of a solve's CPU time (docs/solver.md).  (Timing only: no
     * result depends on it.) */
    setenv("OMP_WAIT_POLICY", "passive", 0);
    setenv(PIN_MARK, "1", 1);
    execv("/proc/self/exe", argv);
    fprintf(stderr, "tissuefit: warning: could not re-execute to pin OpenBLAS (%s); results may "
                    "differ in the last bits from other machines\n",
            argv[0]);
}
