/*
 * mls.c — MLS shape functions of the element-free Galerkin method (mls.h;
 * seed 001 eqs 1-8).
 */
#include "meshfree/mls.h"

#include <float.h>
#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "meshfree/neighbours.h"

double tf_mls_weight(double r, double *dw_r)
{
    if (r <= 0.5) {
        *dw_r = -8 + 12 * r;
        return 2.0 / 3 - 4 * r * r + 4 * r * r * r;
    }
    if (r <= 1) {
        double q = 1 - r;
        *dw_r = -4 * q * q / r; /* dw/dr = -4 + 8r - 4r^2 */
        return 4.0 / 3 * q * q * q; /* = 4/3 - 4r + 4r^2 - 4/3 r^3 */
    }
    *dw_r = 0;
    return 0;
}

int tf_mls_work_init(tf_mls_work *w, size_t cap)
{
    w->enrich = NULL;
    w->enrich_ctx = NULL;
    w->cap = cap;
    w->w = malloc(cap * sizeof *w->w);
    w->dw = malloc(3 * cap * sizeof *w->dw);
    w->p = malloc(4 * cap * sizeof *w->p);
    if (!w->w || !w->dw || !w->p) {
        tf_mls_work_free(w);
        return -1;
    }
    return 0;
}

void tf_mls_work_free(tf_mls_work *w)
{
    free(w->w);
    free(w->dw);
    free(w->p);
    w->w = w->dw = w->p = NULL;
    w->cap = 0;
}

/* Weights, their gradients and the shifted basis at the nodes; the moment
 * matrix A (eq 3) and, when deriv, its derivatives dA[a] (4 x 4, full). */
static void moments(tf_mls_work *w, const double *xyz, const double *radius,
                    const uint32_t *idx, size_t n, double s, const double x[3], int deriv,
                    double A[16], double dA[3][16])
{
    for (int k = 0; k < 16; ++k) {
        A[k] = dA[0][k] = dA[1][k] = dA[2][k] = 0;
    }
    for (size_t i = 0; i < n; ++i) {
        const double *xi = xyz + 3 * (size_t)idx[i], *d = radius + 3 * (size_t)idx[i];
        double t[3], r2 = 0, dwr, *p = w->p + 4 * i;
        for (int a = 0; a < 3; ++a) {
            t[a] = x[a] - xi[a];
            r2 += (t[a] / d[a]) * (t[a] / d[a]);
        }
        double wi = tf_mls_weight(sqrt(r2), &dwr), e, de[3];
        p[0] = 1;
        for (int a = 0; a < 3; ++a) {
            w->dw[3 * i + a] = dwr * t[a] / (d[a] * d[a]);
            p[a + 1] = -t[a] / s;
        }
        if (wi != 0 && w->enrich && w->enrich(w->enrich_ctx, idx[i], x, &e, de)) {
            for (int a = 0; a < 3; ++a) { /* (w e)' = w' e + w e' */
                w->dw[3 * i + a] = w->dw[3 * i + a] * e + wi * de[a];
            }
            wi *= e;
        }
        w->w[i] = wi;
        if (wi == 0) {
            continue; /* w and dw vanish together outside the domain (C2 spline) */
        }
        for (int r = 0; r < 4; ++r) {
            for (int c = 0; c < 4; ++c) {
                A[4 * c + r] += wi * p[r] * p[c];
                for (int a = 0; deriv && a < 3; ++a) {
                    dA[a][4 * c + r] += w->dw[3 * i + a] * p[r] * p[c];
                }
            }
        }
    }
}

/* Cholesky factor of A in place and its reciprocal condition; 0 or -1. */
static int factor(double A[16], double *rcond)
{
    double anorm = 0, work[12];
    lapack_int iwork[4];
    for (int c = 0; c < 4; ++c) {
        double sum = 0;
        for (int r = 0; r < 4; ++r) {
            sum += fabs(A[4 * c + r]);
        }
        anorm = fmax(anorm, sum);
    }
    *rcond = 0;
    if (LAPACKE_dpotrf_work(LAPACK_COL_MAJOR, 'L', 4, A, 4) != 0 ||
        LAPACKE_dpocon_work(LAPACK_COL_MAJOR, 'L', 4, A, 4, anorm, rcond, work, iwork) != 0) {
        *rcond = 0;
        return -1;
    }
    return *rcond > DBL_EPSILON ? 0 : -1;
}

static double dot4(const double a[4], const double b[4])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

/* One point: phi[i], and dphi[a n + i] when dphi is not NULL. */
static int point(tf_mls_work *w, const double *xyz, const double *radius, const uint32_t *idx,
                 size_t n, double s, const double x[3], double *phi, double *dphi, double *rcond)
{
    double A[16], dA[3][16], g[4] = {1, 0, 0, 0}, dg[12];
    moments(w, xyz, radius, idx, n, s, x, dphi != NULL, A, dA);
    if (factor(A, rcond) != 0) {
        return -1;
    }
    LAPACKE_dpotrs_work(LAPACK_COL_MAJOR, 'L', 4, 1, A, 4, g, 4); /* gamma = A^-1 p(x) */
    for (size_t i = 0; i < n; ++i) {
        phi[i] = w->w[i] * dot4(g, w->p + 4 * i);
    }
    if (dphi == NULL) {
        return 0;
    }
    for (int a = 0; a < 3; ++a) { /* d_a p(x) - (d_a A) gamma */
        for (int r = 0; r < 4; ++r) {
            dg[4 * a + r] = (r == a + 1 ? 1 / s : 0) -
                            (dA[a][r] * g[0] + dA[a][4 + r] * g[1] + dA[a][8 + r] * g[2] +
                             dA[a][12 + r] * g[3]);
        }
    }
    LAPACKE_dpotrs_work(LAPACK_COL_MAJOR, 'L', 4, 3, A, 4, dg, 4);
    for (int a = 0; a < 3; ++a) {
        for (size_t i = 0; i < n; ++i) {
            const double *p = w->p + 4 * i;
            dphi[a * n + i] = w->w[i] * dot4(dg + 4 * a, p) + w->dw[3 * i + a] * dot4(g, p);
        }
    }
    return 0;
}

int tf_mls_eval(tf_mls_work *w, const double *xyz, const double *radius, const uint32_t *idx,
                size_t n, double s, const double *x, size_t np, double *phi, double *dphi,
                double *rcond, size_t *at)
{
    *rcond = INFINITY;
    *at = 0;
    if (n > w->cap) {
        return -1;
    }
    for (size_t p = 0; p < np; ++p) {
        double rc;
        int rc_point = point(w, xyz, radius, idx, n, s, x + 3 * p, phi + p * n,
                             dphi ? dphi + 3 * p * n : NULL, &rc);
        if (rc < *rcond) {
            *rcond = rc;
            *at = p;
        }
        if (rc_point != 0) {
            *at = p;
            return -1;
        }
    }
    return 0;
}

/* --- radii of influence -------------------------------------------------- */

#define NEAREST 6

/* Keeps the NEAREST smallest (d2, j) pairs, ascending (ties by index). */
static void keep_nearest(double d2, uint32_t j, double *bd, uint32_t *bj, size_t *nb)
{
    size_t k = *nb < NEAREST ? (*nb)++ : NEAREST;
    if (k == NEAREST && (d2 > bd[k - 1] || (d2 == bd[k - 1] && j > bj[k - 1]))) {
        return;
    }
    if (k == NEAREST) {
        k--;
    }
    while (k > 0 && (bd[k - 1] > d2 || (bd[k - 1] == d2 && bj[k - 1] > j))) {
        bd[k] = bd[k - 1];
        bj[k] = bj[k - 1];
        --k;
    }
    bd[k] = d2;
    bj[k] = j;
}

/* Squared distance with each axis divided by the nominal spacing h[a]. */
static double dist2(const double *a, const double *b, const double h[3])
{
    double d0 = (a[0] - b[0]) / h[0], d1 = (a[1] - b[1]) / h[1], d2 = (a[2] - b[2]) / h[2];
    return d0 * d0 + d1 * d1 + d2 * d2;
}

/* The NEAREST nearest neighbours of node i in the metric of dist2: from
 * the grid query (an ellipsoid of 2 spacings, i.e. the ball of radius 2 in
 * that metric) when the farthest of them lies inside it, else by looking
 * at all nodes. */
static void nearest(const double *xyz, size_t n, size_t i, const double h[3],
                    const uint32_t *cand, size_t nc, uint32_t *bj)
{
    double bd[NEAREST];
    size_t nb = 0;
    for (size_t c = 0; c < nc; ++c) {
        if (cand[c] != i) {
            keep_nearest(dist2(xyz + 3 * i, xyz + 3 * (size_t)cand[c], h), cand[c], bd, bj, &nb);
        }
    }
    if (nb == NEAREST && bd[NEAREST - 1] < 4) {
        return;
    }
    nb = 0;
    for (size_t j = 0; j < n; ++j) {
        if (j != i) {
            keep_nearest(dist2(xyz + 3 * i, xyz + 3 * j, h), (uint32_t)j, bd, bj, &nb);
        }
    }
}

int tf_mls_radii(tf_ctx *ctx, const double *xyz, size_t n, const double spacing[3], double scale,
                 double *radius)
{
    if (n <= NEAREST) {
        return tf_fail(ctx, "EFG needs at least %d nodes (the cloud has %zu)", NEAREST + 1, n);
    }
    tf_nbr g;
    double rad[3];
    for (int a = 0; a < 3; ++a) {
        rad[a] = 2 * spacing[a];
    }
    size_t cap = 256;
    uint32_t *cand = malloc(cap * sizeof *cand);
    if (cand == NULL || tf_nbr_build(&g, xyz, n, rad) != 0) {
        free(cand);
        return tf_fail(ctx, "out of memory for the radii of influence");
    }
    int rc = 0;
    for (size_t i = 0; i < n && rc == 0; ++i) {
        size_t nc = tf_nbr_query(&g, xyz + 3 * i, cand, cap);
        if (nc > cap) {
            uint32_t *grown = realloc(cand, nc * sizeof *cand);
            if (grown == NULL) {
                tf_fail(ctx, "out of memory for the radii of influence");
                rc = -1;
                break;
            }
            cand = grown;
            cap = nc;
            nc = tf_nbr_query(&g, xyz + 3 * i, cand, cap);
        }
        uint32_t bj[NEAREST];
        nearest(xyz, n, i, spacing, cand, nc, bj);
        for (int a = 0; a < 3 && rc == 0; ++a) {
            double c = 0;
            for (int k = 0; k < NEAREST; ++k) {
                c = fmax(c, fabs(xyz[3 * (size_t)bj[k] + a] - xyz[3 * i + a]));
            }
            if (!(c > 0)) {
                tf_fail(ctx,
                        "node at (%g, %g, %g) mm: its %d nearest neighbours lie in the plane "
                        "%c = %g, no spacing along %c for its radius of influence",
                        xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], NEAREST, 'x' + a,
                        xyz[3 * i + a], 'x' + a);
                rc = -1;
            }
            radius[3 * i + a] = scale * c;
        }
    }
    tf_nbr_free(&g);
    free(cand);
    return rc;
}

size_t tf_mls_reach(const double *xyz, const double *radius, uint32_t *idx, size_t n,
                    const double lo[3], const double hi[3])
{
    size_t m = 0;
    for (size_t k = 0; k < n; ++k) {
        const double *xi = xyz + 3 * (size_t)idx[k], *d = radius + 3 * (size_t)idx[k];
        double r2 = 0;
        for (int a = 0; a < 3; ++a) { /* nearest point of the box, scaled */
            double c = xi[a] < lo[a] ? lo[a] : xi[a] > hi[a] ? hi[a] : xi[a];
            r2 += ((xi[a] - c) / d[a]) * ((xi[a] - c) / d[a]);
        }
        if (r2 < 1) {
            idx[m++] = idx[k];
        }
    }
    return m;
}
