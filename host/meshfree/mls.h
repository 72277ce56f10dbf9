/*
 * mls.h — moving-least-squares shape functions and their first derivatives
 * (seed 001 §2, eqs 1-8; the element-free Galerkin method of Belytschko,
 * Lu & Gu 1994), the alternative to rpim.h with the same per-point output.
 *
 * Linear basis p = [1, x, y, z] (eq 1), weights w_i(x) = w(r_i) with the
 * cubic spline of eq 8,
 *
 *   w(r) = 2/3 - 4 r^2 + 4 r^3              r <= 1/2
 *          4/3 - 4 r + 4 r^2 - 4/3 r^3      1/2 < r <= 1
 *          0                                r > 1,
 *
 * r_i = |x - x_i| scaled per axis by node i's radius of influence
 * (an ellipsoid with semi-axes radius[3 i + a]; a sphere, as in the seed,
 * when they are equal), moment matrix A(x) = sum_i w_i p(x_i) p(x_i)^T
 * (eq 3) and phi_i(x) = p(x)^T A(x)^-1 p(x_i) w_i(x) (eq 6).
 *
 * Numerically: the basis is shifted to the evaluation point and divided by
 * a length s (the support radius), p_i = [1, (x_i - x)/s], which leaves phi
 * unchanged and A of order one; A (4 x 4, symmetric positive definite when
 * the weighted nodes are not coplanar) is factorised by LAPACK's Cholesky
 * dpotrf with a condition estimate (dpocon), and with gamma = A^-1 p(x)
 * (Belytschko's form)
 *
 *   phi_i = w_i gamma . p_i,
 *   d_a phi_i = w_i d_a gamma . p_i + d_a w_i gamma . p_i,
 *   A d_a gamma = d_a p(x) - (d_a A) gamma,   d_a p(x) = e_(a+1)/s.
 *
 * MLS shape functions do not interpolate (phi_i(x_j) != delta_ij): nodal
 * values are parameters, not displacements, and essential conditions need
 * a weak form (seed eq 19: penalty) — the solver's business.
 */
#ifndef TF_MLS_H
#define TF_MLS_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"

/* Cubic spline weight at the scaled distance r >= 0 (eq 8); *dw_r receives
 * (dw/dr)/r, which stays finite at r = 0. */
double tf_mls_weight(double r, double *dw_r);

/* An optional factor on node weights (cut.h's enrichment): returns 0 when
 * node's weight is left alone at x, else 1 with the factor in *e and its
 * gradient (per mm) in de. */
typedef int (*tf_mls_enrich_fn)(const void *ctx, uint32_t node, const double x[3], double *e,
                                double de[3]);

/* Per-thread workspace for supports of up to cap nodes. */
typedef struct tf_mls_work {
    tf_mls_enrich_fn enrich; /* NULL: plain weights (tf_mls_work_init) */
    const void *enrich_ctx;
    size_t cap;
    double *w;  /* cap weights at the current point */
    double *dw; /* 3 cap weight gradients, per mm */
    double *p;  /* 4 cap shifted, scaled basis at the nodes */
} tf_mls_work;

int tf_mls_work_init(tf_mls_work *w, size_t cap);
void tf_mls_work_free(tf_mls_work *w);

/* Shape functions at the np points x[3p ..] of the n nodes idx[] (xyz
 * holds all nodes; node j has the radii radius[3j .. 3j+2], mm):
 * phi[p n + i] and, when dphi is not NULL, dphi[(3p + a) n + i] =
 * d phi_i / d x_a (per mm), the layout of tf_rpim_eval.  Nodes whose
 * domain does not reach a point get 0 there.  s (mm) scales the basis.
 * *rcond receives the smallest reciprocal condition estimate (1-norm) of
 * the points' moment matrices and *at the index of that point.  Returns 0,
 * or -1 when n > cap or a moment matrix is singular (rcond <= machine
 * epsilon: fewer than four weighted nodes, or all of them in one plane),
 * with that point's index in *at. */
int tf_mls_eval(tf_mls_work *w, const double *xyz, const double *radius, const uint32_t *idx,
                size_t n, double s, const double *x, size_t np, double *phi, double *dphi,
                double *rcond, size_t *at);

/* Radii of influence of the n nodes: radius[3i + a] = scale x the local
 * nodal spacing of node i along axis a, which is the largest |x_j,a - x_i,a|
 * over its six nearest neighbours j, "nearest" with each axis measured in
 * the nominal spacing spacing[a] (on a regular grid, however anisotropic:
 * the grid spacing of each axis, at faces, edges and corners too).
 * Returns 0, or -1 with a message (fewer than seven nodes, a node whose
 * neighbours all lie in one plane through it, out of memory). */
int tf_mls_radii(tf_ctx *ctx, const double *xyz, size_t n, const double spacing[3], double scale,
                 double *radius);

/* Keeps, in order, those of the n nodes idx[] whose domain of influence
 * reaches into the box [lo, hi] (a point when lo == hi), i.e. that have a
 * non-zero weight somewhere in it; returns how many. */
size_t tf_mls_reach(const double *xyz, const double *radius, uint32_t *idx, size_t n,
                    const double lo[3], const double hi[3]);

#endif /* TF_MLS_H */
