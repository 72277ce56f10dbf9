/*
 * pod.c — see pod.h.
 */
#include "numerics/pod.h"

#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int tf_pod_compute(tf_ctx *ctx, const double *data, int m, int n, tf_pod *pod)
{
    int k = m < n ? m : n;
    double *a = malloc((size_t)m * n * sizeof *a);
    double *vt = malloc((size_t)k * n * sizeof *vt);
    pod->m = m;
    pod->n = n;
    pod->k = k;
    pod->modes = malloc((size_t)m * k * sizeof *pod->modes);
    pod->sigma = malloc((size_t)k * sizeof *pod->sigma);
    if (a == NULL || vt == NULL || pod->modes == NULL || pod->sigma == NULL) {
        free(a);
        free(vt);
        tf_pod_free(pod);
        return tf_fail(ctx, "POD: out of memory for a %d x %d data matrix", m, n);
    }
    memcpy(a, data, (size_t)m * n * sizeof *a);
    lapack_int info = LAPACKE_dgesdd(LAPACK_COL_MAJOR, 'S', m, n, a, m, pod->sigma, pod->modes, m,
                                     vt, k);
    free(a);
    free(vt);
    if (info != 0) {
        tf_pod_free(pod);
        return tf_fail(ctx, "POD: LAPACK dgesdd failed (info %d)", (int)info);
    }
    return 0;
}

void tf_pod_free(tf_pod *pod)
{
    free(pod->modes);
    free(pod->sigma);
    pod->modes = pod->sigma = NULL;
}

int tf_pod_rank_for(const tf_pod *pod, double tol)
{
    double tail = 0;
    for (int r = pod->k; r > 0; --r) {
        tail += pod->sigma[r - 1] * pod->sigma[r - 1];
        if (sqrt(tail) > tol) {
            return r;
        }
    }
    return 0;
}
