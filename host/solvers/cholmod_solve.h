/*
 * cholmod_solve.h — sparse Cholesky of the stiffness matrix with CHOLMOD:
 * one analysis and factorisation, then any number of solves with many
 * right-hand sides at once.
 */
#ifndef TF_CHOLMOD_SOLVE_H
#define TF_CHOLMOD_SOLVE_H

#include <stddef.h>

#include "base/context.h"
#include "solvers/assemble.h"

typedef struct tf_chol tf_chol;

typedef struct tf_chol_info {
    double t_analyse, t_factor; /* s, wall */
    double nnz_l;               /* entries in the factor */
    double flops;               /* of the factorisation */
    const char *ordering;       /* fill-reducing ordering CHOLMOD chose */
    double rcond;               /* CHOLMOD's rough reciprocal condition: (min/max diag L)^2 */
    double peak_bytes;          /* CHOLMOD's peak memory so far (analysis, factorisation) */
} tf_chol_info;

/* Fill-reducing orderings.  The default is METIS (through CHOLMOD's
 * partition module): on block48 at 41 x 41 x 9 it gives 9.99e7 factor
 * entries and 3.0e11 flops against AMD's 1.30e8 and 5.6e11, NESDIS 9.85e7
 * and 2.9e11 for twice METIS's analysis time, the solutions equal to 4e-13
 * (docs/validation.md §6, `make bench-ordering`).  METIS seeds its random
 * choices with a constant: the same ordering (and bits) on every run and
 * for any thread count. */
typedef enum tf_ordering {
    TF_ORDER_DEFAULT,
    TF_ORDER_AMD,
    TF_ORDER_METIS,
    TF_ORDER_NESDIS,
} tf_ordering;

/* The symbolic analysis of A's pattern only, with the given ordering
 * (a Newton solver analyses once and refactorises many times); ldl: a
 * simplicial LDL^T factorisation, which (without pivoting) also takes an
 * indefinite A as long as no pivot vanishes.  Returns NULL with a
 * message. */
tf_chol *tf_chol_analyse(tf_ctx *ctx, const tf_csc *a, tf_ordering ord, int ldl,
                         tf_chol_info *info);

/* As tf_chol_analyse (LL^T), with the DOFs i where last[i] != 0 moved to
 * the end of the fill-reducing ordering (the others in the ordering's
 * order), given to CHOLMOD as its ordering (CHOLMOD_GIVEN; CHOLMOD may
 * still postorder it).  With those m DOFs last, the factor's trailing
 * m x m block L_AA satisfies L_AA L_AA^T = the Schur complement of the
 * rest onto them: a matrix that differs only in that block has the
 * factor with L_AA replaced (tf_chol_trailing).  NULL with a message. */
tf_chol *tf_chol_analyse_last(tf_ctx *ctx, const tf_csc *a, tf_ordering ord,
                              const unsigned char *last, tf_chol_info *info);

/* The trailing m x m block of c's last factorisation (supernodal LL^T),
 * column major with leading dimension *ld, its lower triangle L's entries
 * in place (writable: a caller may replace the block by the factor of
 * another trailing Schur complement); *perm gets the factor's ordering
 * (factor position -> row of A).  NULL when the factor is not supernodal
 * LL^T or the last supernode does not hold the last m columns. */
double *tf_chol_trailing(tf_chol *c, size_t m, size_t *ld, const int **perm);

/* Numeric factorisation of A (the pattern analysed) into c, replacing the
 * last one.  Returns 0; 1 when A is not positive definite (LL^T) or has a
 * zero pivot (LDL^T): c then holds no usable factor; -1 with a message on
 * other failures.  *t gets the seconds it took. */
int tf_chol_refactor(tf_ctx *ctx, tf_chol *c, const tf_csc *a, double *t);

/* A second handle with c's analysis (a, of c's pattern, analysed under
 * c's permutation; no values yet) to refactorise into while c's factor
 * stays usable, so that a matrix that turns out not positive definite
 * costs no factor (a Newton solver keeps its last positive definite one).
 * Not a copy of c: cholmod_copy_factor took 2.4 s for the 1.01e8 entries
 * of block48 at 41 x 41 x 9, this analysis 0.15 s.  Returns NULL with a
 * message. */
tf_chol *tf_chol_twin(tf_ctx *ctx, const tf_chol *c, const tf_csc *a);

/* CHOLMOD's rough reciprocal condition of the last factorisation. */
double tf_chol_rcond(tf_chol *c);

/* CHOLMOD's peak memory (bytes) in c so far: the analysis and the
 * factorisations, the factor included. */
double tf_chol_peak_bytes(const tf_chol *c);

/* The ordering's name ("AMD", ...) of an analysed c. */
const char *tf_chol_ordering(const tf_chol *c);

/* Solves A X = B for ncol columns (column major, length n each).
 * Returns 0, or -1 with a message. */
int tf_chol_solve(tf_ctx *ctx, tf_chol *c, const double *b, double *x, size_t ncol);

void tf_chol_free(tf_chol *c);

#endif /* TF_CHOLMOD_SOLVE_H */
