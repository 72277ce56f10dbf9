/*
 * pod.h — proper orthogonal decomposition of training displacements: the
 * thin SVD D = U S V^T of a data matrix whose columns are load cases, through
 * LAPACK (dgesdd).  The modal family keeps the first r columns of U as its
 * spatial modes (docs/fitting.md).
 */
#ifndef TF_POD_H
#define TF_POD_H

#include <stddef.h>

#include "base/context.h"

typedef struct tf_pod {
    int m, n, k;   /* data rows, columns, k = min(m, n) */
    double *modes; /* m x k, column-major, orthonormal columns (left singular vectors) */
    double *sigma; /* k singular values, descending */
} tf_pod;

/* Decomposes data (m x n, column-major, not modified).  Returns 0, or -1
 * with a message when LAPACK fails or memory runs out. */
int tf_pod_compute(tf_ctx *ctx, const double *data, int m, int n, tf_pod *pod);

void tf_pod_free(tf_pod *pod);

/* Smallest rank r whose discarded singular values leave a Frobenius
 * residual sqrt(sum_{i>=r} sigma_i^2) <= tol (0 when the data are that small). */
int tf_pod_rank_for(const tf_pod *pod, double tol);

#endif /* TF_POD_H */
