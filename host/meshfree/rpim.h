/*
 * rpim.h — radial point interpolation shape functions and their first
 * derivatives (seed §2.2, eqs 11-17) on one support domain.
 *
 * With the multiquadric R_i(x) = (r_i^2 + (alpha_c d_c)^2)^q and, when
 * asked, the linear polynomial p = [1, x, y, z] (eq 11, with the usual
 * moment conditions P^T a = 0), the shape functions solve the symmetric
 * system
 *
 *     [ R_s  P ] [ Phi^T ]   [ R(x) ]
 *     [ P^T  0 ] [ .     ] = [ p(x) ]          (eq 17, transposed)
 *
 * and the derivatives solve it with the right-hand side differentiated.
 * Distances are made dimensionless by the support radius s (and the
 * polynomial centred on the support), which leaves Phi unchanged and keeps
 * the condition estimate meaningful.
 *
 * With the polynomial the system is solved in the null space of P^T (the
 * standard method for saddle-point systems; Benzi, Golub & Liesen, Acta
 * Numerica 2005, §6): with P = Q [R_P; 0] (Householder QR, LAPACK dgeqrf),
 * Q = [Q1 Q2], the moment conditions P^T a = p(x) fix a = Q1 w + Q2 z with
 * R_P^T w = p(x), and the first block row projected on Q2 gives
 *
 *     (Q2^T R_s Q2) z = Q2^T R(x) - (Q2^T R_s Q1) w,      Phi^T = a.
 *
 * Q2^T R_s Q2 is the multiquadric restricted to coefficient vectors that
 * annihilate linear fields; for 1 < q < 2 it is positive definite (the
 * multiquadric is conditionally positive definite of order 2).  For a flat
 * basis (alpha_c d_c many nodal spacings) the constant and linear parts of
 * R_s, which dominate it, are exactly what the projection removes, so the
 * projected system is many orders better conditioned than the saddle-point
 * matrix and the shape functions keep their digits (docs/solver.md).  It is
 * factorised by LU with partial pivoting (dgetrf; q < 1 makes it negative
 * definite), the condition estimate is that of this projected system (and
 * of R_P: coplanar nodes make P rank-deficient).  Without the polynomial
 * (the seed's eq 12) R_s itself is factorised by LU.  Either way, one
 * factorisation per support serves any number of points at once (the
 * triangular solves with many right-hand sides run as level-3 BLAS).
 */
#ifndef TF_RPIM_H
#define TF_RPIM_H

#include <stddef.h>
#include <stdint.h>

typedef struct tf_rpim {
    double shape; /* alpha_c d_c, mm */
    double q;
    int poly;     /* 0: RBF only (eq 12), 1: RBF + linear polynomial (eq 11) */
} tf_rpim;

/* Per-thread workspace for supports of up to cap nodes. */
typedef struct tf_rpim_work {
    size_t cap, n, m;  /* capacity, current support size, polynomial terms */
    double centre[3], s, c2, q, c2q; /* c2 = (alpha_c d_c / s)^2, c2q = c2^q */
    double *xs;        /* 3 cap: support nodes, scaled, relative to centre */
    double *g;         /* (cap + 4)^2: the factorised system (with the polynomial: n x n,
                          Q^T R_s Q with its lower-right n - 4 block factorised) */
    int *ipiv;
    double *qp;        /* 4 cap: the QR factorisation of P (Householder vectors, R_P) */
    double tau[4];
    double *pp;        /* 4 x rhs_cap: the polynomial rows of the right-hand sides */
    double *rhs;       /* (cap + 4) x rhs_cap, used as (n + m) x columns */
    size_t rhs_cap;    /* columns */
    double *work;      /* 4 (cap + 4) */
    int *iwork;
    double *qwork;     /* 64 (cap + 4 + rhs_cap): dormqr's work */
} tf_rpim_work;

int tf_rpim_work_init(tf_rpim_work *w, size_t cap);
void tf_rpim_work_free(tf_rpim_work *w);

/* Builds and factorises the system for the n support nodes idx[] (xyz holds
 * all nodes), centred at centre, scaled by the support radius s (mm).
 * Writes the reciprocal condition estimate (1-norm) to *rcond.  Returns 0,
 * or -1 when the system is singular (rcond at or below the machine
 * epsilon) or n exceeds the workspace. */
int tf_rpim_factor(const tf_rpim *p, tf_rpim_work *w, const double *xyz, const uint32_t *idx,
                   size_t n, const double centre[3], double s, double *rcond);

/* Shape functions at the np points x[3p ..]: phi[p n + i] for the
 * factorised support's n nodes; when dphi is not NULL,
 * dphi[(3p + a) n + i] = d phi_i / d x_a at point p (per mm).  Returns 0,
 * or -1 when out of memory. */
int tf_rpim_eval(tf_rpim_work *w, const double *x, size_t np, double *phi, double *dphi);

#endif /* TF_RPIM_H */
