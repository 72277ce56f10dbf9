/*
 * grid_spline.h — tensor-product uniform cubic B-splines over a grid of
 * sites, in double precision (the region models' blend of per-site values:
 * fitting/region_*.c fits them, model/region_model.c evaluates a model's
 * tables with them).
 *
 * nx x ny sites at the grid nodes; every per-site quantity is stored as
 * control values c[j][i], i = -1 .. nx, j = -1 .. ny ((nx + 2)(ny + 2)
 * control points, row-major, i fastest; m quantities per control point,
 * interleaved), and evaluated at grid coordinates g = (a / ha, b / hb) as
 *
 *   Q(g) = sum_{l=0..3} sum_{k=0..3} B_l(tb) B_k(ta) c[jb - 1 + l][ia - 1 + k],
 *
 * ga clamped to [0, nx - 1], ia = min(floor(ga), nx - 2), ta = ga - ia (the
 * same in b), with the uniform cubic B-spline weights B0 = (1 - t)^3 / 6,
 * B1 = (3t^3 - 6t^2 + 4) / 6, B2 = (-3t^3 + 3t^2 + 3t + 1) / 6, B3 = t^3 / 6
 * (non-negative, summing to 1).
 *
 * Interpolation: the control values that make Q equal the site values at
 * every site, with not-a-knot ends (the third derivative continuous across
 * the first and last interior knots: -c[-1] + 4c[0] - 6c[1] + 4c[2] - c[3]
 * = 0 and its mirror), which keep the interpolant's error O(h^4) up to the
 * domain's edge (natural ends would force Q'' = 0 there: O(h^2)).  Each axis
 * is one (n + 2)-square system (the interpolation rows (c[i-1] + 4c[i] +
 * c[i+1]) / 6 = y[i] are tridiagonal, the two end rows five wide), factored
 * once by LU with partial pivoting and applied to every grid line and
 * quantity: first along a for every row of sites, then along b.  Needs at
 * least 4 sites per axis (with 3 the two end conditions coincide).
 */
#ifndef TF_GRID_SPLINE_H
#define TF_GRID_SPLINE_H

#include <stddef.h>

#include "base/context.h"

#define TF_SPLINE_MIN_SITES 4

/* Weights w[k] = B_k(t) and their t-derivatives dw[k] (may be NULL). */
void tf_bspline_weights(double t, double w[4], double dw[4]);

/* The cell i in [0, n - 2] and local coordinate t in [0, 1] of grid
 * coordinate g on n sites (g clamped to [0, n - 1] first).  Returns 1 when
 * g was clamped, else 0. */
int tf_bspline_cell(double g, unsigned n, unsigned *i, double *t);

/* Control values ctrl (m per control point, (nx + 2)(ny + 2) of them) that
 * interpolate site values (m per site, nx ny sites, row-major, i fastest).
 * Returns 0, or -1 with a message (fewer than TF_SPLINE_MIN_SITES sites on
 * an axis, out of memory). */
int tf_spline_interpolate(tf_ctx *ctx, unsigned nx, unsigned ny, size_t m, const double *site,
                          double *ctrl);

/* Q(g) for the m quantities (q), and optionally dQ/dga and dQ/dgb (NULL to
 * skip): the derivatives of the cell's polynomial (where g was clamped, the
 * one-sided derivative at the domain's edge). */
void tf_spline_eval(unsigned nx, unsigned ny, size_t m, const double *ctrl, double ga, double gb,
                    double *q, double *dqa, double *dqb);
/* The same over float control values (a model's tables), m per control
 * point, summed in double. */
void tf_spline_eval_float(unsigned nx, unsigned ny, size_t m, const float *ctrl, double ga,
                          double gb, double *q, double *dqa, double *dqb);

#endif /* TF_GRID_SPLINE_H */
