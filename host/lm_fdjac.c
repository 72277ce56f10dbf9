/*
 * lm_fdjac.c — forward differences (see lm_fdjac.h).
 *
 * Step h_j = sqrt(eps) max(|p_j|, typical_j): the truncation error of a
 * forward difference is O(h) and the rounding error O(eps / h), so h ~
 * sqrt(eps) relative to the parameter's size balances them and gives about
 * half the digits of double precision (Dennis & Schnabel, §5.4).  The
 * typical size (lm.c passes |p0_j|, or 1) keeps the step from shrinking
 * with a parameter that heads to 0: a step of 1e-300 would not move the
 * residuals at all, and a zero column reads as a zero gradient.  h is then
 * replaced by (p_j + h) - p_j, the step the arithmetic actually takes.  The step goes backwards when forwards
 * would leave the box or lands on a non-finite residual.
 */
#include "lm_fdjac.h"

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

/* The representable step from p by at most h0 towards dir (+1 or -1)
 * without leaving the box; 0 when the box allows no step that way. */
static double step_inside(const tf_fdjac *fd, size_t j, double p, double h0, int dir)
{
    double lo = fd->lower != NULL ? fd->lower[j] : -INFINITY;
    double hi = fd->upper != NULL ? fd->upper[j] : INFINITY;
    double room = dir > 0 ? hi - p : p - lo;
    double t = p + dir * fmin(h0, room);
    return t - p;
}

/* Column j into jac; 0, -1 callback failed, 1 not finite either way. */
static int column(const tf_fdjac *fd, size_t j, const double *p, const double *r, double *jac,
                  double *pt, double *rt, size_t *evals)
{
    double h0 = sqrt(DBL_EPSILON) * fmax(fabs(p[j]), fd->typical[j]);
    double *col = jac + j * fd->m;
    int tried = 0;
    for (int dir = 1; dir >= -1; dir -= 2) {
        double h = step_inside(fd, j, p[j], h0, dir);
        if (h == 0) {
            continue;
        }
        tried = 1;
        memcpy(pt, p, fd->n * sizeof *pt);
        pt[j] = p[j] + h;
        ++*evals;
        if (fd->residual(fd->ctx, pt, rt) != 0) {
            return -1;
        }
        if (all_finite(rt, fd->m)) {
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

int tf_fdjac_forward(const tf_fdjac *fd, const double *p, const double *r, double *jac,
                     double *pt, double *rt, size_t *evals)
{
    for (size_t j = 0; j < fd->n; ++j) {
        int rc = column(fd, j, p, r, jac, pt, rt, evals);
        if (rc != 0) {
            return rc;
        }
    }
    return 0;
}
