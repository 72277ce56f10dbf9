/*
 * lm_fdjac.c — difference Jacobians (see lm_fdjac.h).
 *
 * Steps are relative to the parameter's size, max(|p_j|, typical_j).  A
 * forward difference has truncation error O(h) and rounding error
 * O(eps / h): h = sqrt(eps) * size balances them and leaves about half the
 * digits of double precision.  A central difference has truncation error
 * O(h^2): h = eps^(1/3) * size leaves about two thirds (Dennis & Schnabel,
 * §5.4 and §5.6), for twice the evaluations.  The typical size (lm.c passes
 * |p0_j|, or 1) keeps the step from shrinking with a parameter that heads
 * to 0: a step of 1e-300 would not move the residuals at all, and a zero
 * column reads as a zero gradient.  h is replaced by (p_j + h) - p_j, the
 * step the arithmetic actually takes.  Where the box or a non-finite
 * residual forbids a side, the difference is one-sided, backwards if need
 * be.
 */
#include "numerics/lm_fdjac.h"

#include <float.h>
#include <math.h>
#include <string.h>

static int all_finite(const double *v, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        if (!isfinite(v[i])) {
            return 0;
        }
    }
    return 1;
}

/* Distance from p to the box edge towards dir (+1 or -1). */
static double room(const tf_fdjac *fd, size_t j, double p, int dir)
{
    double lo = fd->lower != NULL ? fd->lower[j] : -INFINITY;
    double hi = fd->upper != NULL ? fd->upper[j] : INFINITY;
    return dir > 0 ? hi - p : p - lo;
}

/* The representable step from p by at most h0 towards dir without leaving
 * the box; 0 when the box allows no step that way. */
static double step_inside(const tf_fdjac *fd, size_t j, double p, double h0, int dir)
{
    double t = p + dir * fmin(h0, room(fd, j, p, dir));
    return t - p;
}

/* Residuals at p with p_j moved by h into rt: 0 finite, 1 not, -1 failed. */
static int shifted(const tf_fdjac *fd, const double *p, size_t j, double h, double *pt,
                   double *rt, size_t *evals)
{
    memcpy(pt, p, fd->n * sizeof *pt);
    pt[j] = p[j] + h;
    ++*evals;
    if (fd->residual(fd->ctx, pt, rt) != 0) {
        return -1;
    }
    return all_finite(rt, fd->m) ? 0 : 1;
}

/* Central difference of column j; 0 done, 1 not possible here, -1 failed. */
static int central(const tf_fdjac *fd, size_t j, const double *p, double *col, double *pt,
                   double *rt, double *rt2, size_t *evals)
{
    double h0 = cbrt(DBL_EPSILON) * fmax(fabs(p[j]), fd->typical[j]);
    if (room(fd, j, p[j], 1) < h0 || room(fd, j, p[j], -1) < h0) {
        return 1; /* the box cuts a side short: one-sided instead */
    }
    double hp = step_inside(fd, j, p[j], h0, 1), hm = step_inside(fd, j, p[j], h0, -1);
    int rc = shifted(fd, p, j, hp, pt, rt, evals);
    if (rc == 0) {
        rc = shifted(fd, p, j, hm, pt, rt2, evals);
    }
    if (rc != 0) {
        return rc;
    }
    for (size_t i = 0; i < fd->m; ++i) {
        col[i] = (rt[i] - rt2[i]) / (hp - hm);
    }
    return 0;
}

/* Column j into jac; 0, -1 callback failed, 1 not finite either way. */
static int column(const tf_fdjac *fd, size_t j, const double *p, const double *r, double *jac,
                  double *pt, double *rt, double *rt2, size_t *evals)
{
    double *col = jac + j * fd->m;
    if (fd->central) {
        int rc = central(fd, j, p, col, pt, rt, rt2, evals);
        if (rc <= 0) {
            return rc;
        }
    }
    double h0 = sqrt(DBL_EPSILON) * fmax(fabs(p[j]), fd->typical[j]);
    int tried = 0;
    for (int dir = 1; dir >= -1; dir -= 2) {
        double h = step_inside(fd, j, p[j], h0, dir);
        if (h == 0) {
            continue;
        }
        tried = 1;
        int rc = shifted(fd, p, j, h, pt, rt, evals);
        if (rc < 0) {
            return -1;
        }
        if (rc == 0) {
            for (size_t i = 0; i < fd->m; ++i) {
                col[i] = (rt[i] - r[i]) / h;
            }
            return 0;
        }
    }
    /* A parameter pinned by a zero-width box has no derivative to take. */
    memset(col, 0, fd->m * sizeof *col);
    return tried ? 1 : 0;
}

int tf_fdjac_eval(const tf_fdjac *fd, const double *p, const double *r, double *jac, double *pt,
                  double *rt, double *rt2, size_t *evals)
{
    for (size_t j = 0; j < fd->n; ++j) {
        int rc = column(fd, j, p, r, jac, pt, rt, rt2, evals);
        if (rc != 0) {
            return rc;
        }
    }
    return 0;
}
