/*
 * mgh_problems.h — the Moré–Garbow–Hillstrom unconstrained least-squares
 * test set: the 18 problems of Moré, Garbow & Hillstrom, "Testing
 * unconstrained optimization software", ACM TOMS 7(1), 1981, §3 (their
 * problems 32, 33, 34, 1, 7, 13, 2, 8, 15, 10, 20, 12, 6, 16, 35, 27, 17,
 * 19), numbered 1..18 in the order MINPACK's lmder test driver uses, run
 * from the same 53 (problem, n, m, start) combinations as that driver.
 *
 * Each problem is a residual vector f(x) in R^m; the sum of squares
 * sum_i f_i(x)^2 is minimised.  Functions and Jacobians are written from
 * the paper's definitions (host/numerics/mgh_problems.c).
 */
#ifndef TF_MGH_PROBLEMS_H
#define TF_MGH_PROBLEMS_H

#include <stddef.h>

#define TF_MGH_PROBLEMS 18
#define TF_MGH_MAX_N 40
#define TF_MGH_MAX_M 65
#define TF_MGH_MAX_MINIMA 3

/* One run: problem 1..18 with n parameters and m residuals, from
 * factor x the paper's standard start x0 (for Watson, whose x0 is 0, the
 * point with every component equal to factor, as MINPACK does). */
typedef struct tf_mgh_run {
    int problem;
    size_t n, m;
    double factor;
} tf_mgh_run;

/* The 53 runs of MINPACK's lmder driver, in its order. */
const tf_mgh_run *tf_mgh_runs(size_t *count);

/* The problem's name, e.g. "Powell singular". */
const char *tf_mgh_name(int problem);

/* The starting point of the run (n values). */
void tf_mgh_start(const tf_mgh_run *r, double *x);

/* f[0..m-1] = the residuals at x. */
void tf_mgh_residual(const tf_mgh_run *r, const double *x, double *f);

/* jac[i + j*m] = d f_i / d x_j at x. */
void tf_mgh_jacobian(const tf_mgh_run *r, const double *x, double *jac);

/* The values of sum f_i^2 at the known minima for this (n, m) in
 * f[0..count-1]; returns count (1 to TF_MGH_MAX_MINIMA).  f[0] is the
 * smallest known (the global minimum as far as known), f[1] the other
 * minimum the paper lists where it lists one (a local minimum, or one at
 * infinity: parameters going to +-infinity).  Not from the paper, found by
 * this study and checked by tests/unit/numerics/test_lm_mgh.c: f[2] for Kowalik–
 * Osborne (a local minimum: zero gradient, positive definite Hessian), and
 * both values for Chebyquad with n = 1, m = 8, which the paper does not
 * list. */
size_t tf_mgh_minima(const tf_mgh_run *r, double *f);

#endif /* TF_MGH_PROBLEMS_H */
