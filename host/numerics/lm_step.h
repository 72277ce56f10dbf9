/*
 * lm_step.h — the damped step of one Levenberg–Marquardt iteration, for
 * lm.c only: given the pivoted QR factor of J, find lambda >= 0 and
 *     p = -(J^T J + lambda D^2)^-1 J^T r
 * with ||D p|| close to the trust radius delta (Moré 1978, §5–7).
 */
#ifndef TF_LM_STEP_H
#define TF_LM_STEP_H

#include <lapacke.h>
#include <stddef.h>

typedef struct tf_lmstep {
    size_t n;               /* columns of J (the free parameters) */
    size_t k;               /* rows of the factor R: min(m, n) */
    const double *r;        /* R in the upper triangle of r[i + j*ldr] (dgeqp3) */
    size_t ldr;
    const lapack_int *piv;  /* column j of R is parameter piv[j] - 1 */
    size_t rank;            /* leading columns of R taken as independent */
    const double *qtf;      /* the first k entries of Q^T r */
    const double *diag;     /* D, positive, parameter order */
    double *work;           /* tf_lmstep_work_size(n) doubles */
} tf_lmstep;

size_t tf_lmstep_work_size(size_t n);

#define TF_LMSTEP_FAILED (-1.0)    /* LAPACK failed (cannot happen for finite input) */
#define TF_LMSTEP_UNDERFLOW (-2.0) /* the damped step underflowed to zero */

/* Returns lambda (par is the previous one, a starting guess) and the step
 * in step[] (parameter order); ||D step|| <= 1.1 delta, and lambda = 0
 * when the Gauss–Newton step is already that short.  Returns
 * TF_LMSTEP_UNDERFLOW when the damped step for a delta this small is zero
 * in double precision (its scaled norm, the Newton iteration's divisor,
 * would be 0), TF_LMSTEP_FAILED if LAPACK fails. */
double tf_lmstep_solve(const tf_lmstep *s, double delta, double par, double *step);

#endif /* TF_LM_STEP_H */
