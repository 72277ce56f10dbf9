/*
 * rpim.c — RPIM shape functions (rpim.h; seed eqs 11-17).
 */
#include "meshfree/rpim.h"

#include <float.h>
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>

_Static_assert(sizeof(lapack_int) == sizeof(int), "LAPACKE with 32-bit integers");

int tf_rpim_work_init(tf_rpim_work *w, size_t cap)
{
    size_t k = cap + 4;
    w->cap = cap;
    w->n = w->m = 0;
    w->rhs_cap = 4;
    w->xs = malloc(3 * cap * sizeof *w->xs);
    w->g = malloc(k * k * sizeof *w->g);
    w->ipiv = malloc(k * sizeof *w->ipiv);
    w->rhs = malloc(w->rhs_cap * k * sizeof *w->rhs);
    w->work = malloc(4 * k * sizeof *w->work);
    w->iwork = malloc(k * sizeof *w->iwork);
    if (!w->xs || !w->g || !w->ipiv || !w->rhs || !w->work || !w->iwork) {
        tf_rpim_work_free(w);
        return -1;
    }
    return 0;
}

void tf_rpim_work_free(tf_rpim_work *w)
{
    free(w->xs);
    free(w->g);
    free(w->ipiv);
    free(w->rhs);
    free(w->work);
    free(w->iwork);
    w->xs = w->g = w->rhs = w->work = NULL;
    w->ipiv = w->iwork = NULL;
    w->cap = w->rhs_cap = 0;
}

/* Multiquadric of a squared scaled distance (seed §2.2). */
static inline double mq(double r2, double c2, double q)
{
    return pow(r2 + c2, q);
}

int tf_rpim_factor(const tf_rpim *p, tf_rpim_work *w, const double *xyz, const uint32_t *idx,
                   size_t n, const double centre[3], double s, double *rcond)
{
    *rcond = 0;
    if (n > w->cap || n == 0) {
        return -1;
    }
    size_t m = p->poly ? 4 : 0, k = n + m;
    w->n = n;
    w->m = m;
    w->s = s;
    w->c2 = (p->shape / s) * (p->shape / s);
    w->q = p->q;
    for (int a = 0; a < 3; ++a) {
        w->centre[a] = centre[a];
    }
    for (size_t i = 0; i < n; ++i) {
        for (int a = 0; a < 3; ++a) {
            w->xs[3 * i + a] = (xyz[3 * (size_t)idx[i] + a] - centre[a]) / s;
        }
    }
    /* Column major, both triangles: [R_s P; P^T 0]. */
    double *g = w->g;
    for (size_t j = 0; j < n; ++j) {
        const double *xj = w->xs + 3 * j;
        for (size_t i = j; i < n; ++i) {
            const double *xi = w->xs + 3 * i;
            double d0 = xi[0] - xj[0], d1 = xi[1] - xj[1], d2 = xi[2] - xj[2];
            g[i + k * j] = g[j + k * i] = mq(d0 * d0 + d1 * d1 + d2 * d2, w->c2, w->q);
        }
        if (m) {
            const double pj[4] = {1, xj[0], xj[1], xj[2]};
            for (size_t r = 0; r < 4; ++r) {
                g[n + r + k * j] = g[j + k * (n + r)] = pj[r];
            }
        }
    }
    for (size_t j = n; j < k; ++j) {
        for (size_t i = n; i < k; ++i) {
            g[i + k * j] = 0;
        }
    }
    double anorm = LAPACKE_dlange_work(LAPACK_COL_MAJOR, '1', (lapack_int)k, (lapack_int)k, g,
                                       (lapack_int)k, w->work);
    if (LAPACKE_dgetrf_work(LAPACK_COL_MAJOR, (lapack_int)k, (lapack_int)k, g, (lapack_int)k,
                            w->ipiv) != 0) {
        return -1;
    }
    if (LAPACKE_dgecon_work(LAPACK_COL_MAJOR, '1', (lapack_int)k, g, (lapack_int)k, anorm, rcond,
                            w->work, w->iwork) != 0) {
        return -1;
    }
    /* A pivot that is zero only through rounding leaves nothing to trust. */
    return *rcond > DBL_EPSILON ? 0 : -1;
}

/* Right-hand sides of one point: R(x), p(x), and when deriv their x, y, z
 * derivatives, in four columns of length k = n + m. */
static void point_rhs(const tf_rpim_work *w, const double x[3], int deriv, double *b)
{
    size_t n = w->n, m = w->m, k = n + m;
    double xs[3];
    for (int a = 0; a < 3; ++a) {
        xs[a] = (x[a] - w->centre[a]) / w->s;
    }
    for (size_t i = 0; i < n; ++i) {
        const double *xi = w->xs + 3 * i;
        double d0 = xs[0] - xi[0], d1 = xs[1] - xi[1], d2 = xs[2] - xi[2];
        double t = d0 * d0 + d1 * d1 + d2 * d2;
        double r = mq(t, w->c2, w->q);
        b[i] = r;
        if (deriv) {
            /* dR/dx_a = 2 q (r^2 + c^2)^(q-1) (x_a - x_ia), in scaled units */
            double f = 2 * w->q * r / (t + w->c2);
            b[i + k] = f * d0;
            b[i + 2 * k] = f * d1;
            b[i + 3 * k] = f * d2;
        }
    }
    if (m) {
        const double pv[4] = {1, xs[0], xs[1], xs[2]};
        for (size_t j = 0; j < 4; ++j) {
            b[n + j] = pv[j];
            if (deriv) {
                b[n + j + k] = j == 1;
                b[n + j + 2 * k] = j == 2;
                b[n + j + 3 * k] = j == 3;
            }
        }
    }
}

int tf_rpim_eval(tf_rpim_work *w, const double *x, size_t np, double *phi, double *dphi)
{
    size_t n = w->n, k = n + w->m, per = dphi ? 4 : 1, cols = per * np;
    if (cols > w->rhs_cap) {
        double *grown = realloc(w->rhs, cols * (w->cap + 4) * sizeof *grown);
        if (grown == NULL) {
            return -1;
        }
        w->rhs = grown;
        w->rhs_cap = cols;
    }
    for (size_t p = 0; p < np; ++p) {
        point_rhs(w, x + 3 * p, dphi != NULL, w->rhs + p * per * k);
    }
    LAPACKE_dgetrs_work(LAPACK_COL_MAJOR, 'N', (lapack_int)k, (lapack_int)cols, w->g,
                        (lapack_int)k, w->ipiv, w->rhs, (lapack_int)k);
    for (size_t p = 0; p < np; ++p) {
        const double *b = w->rhs + p * per * k;
        for (size_t i = 0; i < n; ++i) {
            phi[p * n + i] = b[i];
        }
        for (size_t a = 0; dphi && a < 3; ++a) {
            for (size_t i = 0; i < n; ++i) {
                dphi[(3 * p + a) * n + i] = b[i + (a + 1) * k] / w->s;
            }
        }
    }
    return 0;
}
