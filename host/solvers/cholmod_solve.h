/*
 * cholmod_solve.h — sparse Cholesky of the stiffness matrix with CHOLMOD:
 * one analysis and factorisation, then any number of solves with many
 * right-hand sides at once.
 */
#ifndef TF_CHOLMOD_SOLVE_H
#define TF_CHOLMOD_SOLVE_H

#include <stddef.h>

#include "solvers/assemble.h"

typedef struct tf_chol tf_chol;

typedef struct tf_chol_info {
    double t_analyse, t_factor; /* s, wall */
    double nnz_l;               /* entries in the factor */
    double flops;               /* of the factorisation */
    const char *ordering;       /* fill-reducing ordering CHOLMOD chose */
} tf_chol_info;

/* Factorises the symmetric positive definite A (lower triangle; A is not
 * kept).  Returns NULL with a message in err when A is not positive
 * definite or memory runs out. */
tf_chol *tf_chol_factor(const tf_csc *a, tf_chol_info *info, char *err, size_t errlen);

/* Solves A X = B for ncol columns (column major, length n each).
 * Returns 0, or -1 with a message. */
int tf_chol_solve(tf_chol *c, const double *b, double *x, size_t ncol, char *err, size_t errlen);

void tf_chol_free(tf_chol *c);

#endif /* TF_CHOLMOD_SOLVE_H */
