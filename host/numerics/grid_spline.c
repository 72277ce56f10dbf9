/*
 * grid_spline.c — tensor-product cubic B-spline interpolation and
 * evaluation over a grid of sites (grid_spline.h).
 */
#include "numerics/grid_spline.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void tf_bspline_weights(double t, double w[4], double dw[4])
{
    double s = 1 - t;
    w[0] = s * s * s / 6;
    w[1] = (3 * t * t * t - 6 * t * t + 4) / 6;
    w[2] = (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6;
    w[3] = t * t * t / 6;
    if (dw != NULL) {
        dw[0] = -s * s / 2;
        dw[1] = (9 * t * t - 12 * t) / 6;
        dw[2] = (-9 * t * t + 6 * t + 3) / 6;
        dw[3] = t * t / 2;
    }
}

int tf_bspline_cell(double g, unsigned n, unsigned *i, double *t)
{
    double top = (double)(n - 1);
    int clamped = !(g >= 0 && g <= top);
    g = g > top ? top : g >= 0 ? g : 0; /* (NaN -> 0) */
    double f = floor(g);
    unsigned k = f >= (double)(n - 2) ? n - 2 : (unsigned)f;
    *i = k;
    *t = g - k;
    return clamped;
}

/* The (n + 2)-square not-a-knot interpolation matrix of one axis,
 * LU-factored with partial pivoting in place (row-major), pivots in piv. */
static int axis_lu(unsigned n, double *a, unsigned *piv)
{
    unsigned m = n + 2;
    memset(a, 0, (size_t)m * m * sizeof *a);
    static const double nak[5] = {-1, 4, -6, 4, -1};
    for (unsigned k = 0; k < 5; ++k) {
        a[k] = nak[k];                                 /* at knot 1 */
        a[(size_t)(m - 1) * m + (n - 3) + k] = nak[k]; /* at knot n - 2 */
    }
    for (unsigned i = 0; i < n; ++i) { /* site i: control values i - 1, i, i + 1 */
        a[(size_t)(i + 1) * m + i] = 1.0 / 6;
        a[(size_t)(i + 1) * m + i + 1] = 4.0 / 6;
        a[(size_t)(i + 1) * m + i + 2] = 1.0 / 6;
    }
    for (unsigned c = 0; c < m; ++c) {
        unsigned p = c;
        for (unsigned r = c + 1; r < m; ++r) {
            if (fabs(a[(size_t)r * m + c]) > fabs(a[(size_t)p * m + c])) {
                p = r;
            }
        }
        if (a[(size_t)p * m + c] == 0) {
            return -1;
        }
        piv[c] = p;
        if (p != c) {
            for (unsigned k = 0; k < m; ++k) {
                double t = a[(size_t)c * m + k];
                a[(size_t)c * m + k] = a[(size_t)p * m + k];
                a[(size_t)p * m + k] = t;
            }
        }
        for (unsigned r = c + 1; r < m; ++r) {
            double f = a[(size_t)r * m + c] / a[(size_t)c * m + c];
            a[(size_t)r * m + c] = f;
            for (unsigned k = c + 1; k < m; ++k) {
                a[(size_t)r * m + k] -= f * a[(size_t)c * m + k];
            }
        }
    }
    return 0;
}

/* Solves the factored system for right-hand side x (n + 2 values, the
 * first and last 0 on entry: the end conditions), in place. */
static void axis_solve(unsigned n, const double *a, const unsigned *piv, double *x)
{
    unsigned m = n + 2;
    for (unsigned c = 0; c < m; ++c) { /* the row exchanges, in order */
        double t = x[c];
        x[c] = x[piv[c]];
        x[piv[c]] = t;
    }
    for (unsigned c = 0; c < m; ++c) {
        for (unsigned r = c + 1; r < m; ++r) {
            x[r] -= a[(size_t)r * m + c] * x[c];
        }
    }
    for (unsigned c = m; c-- > 0;) {
        for (unsigned k = c + 1; k < m; ++k) {
            x[c] -= a[(size_t)c * m + k] * x[k];
        }
        x[c] /= a[(size_t)c * m + c];
    }
}

int tf_spline_interpolate(tf_ctx *ctx, unsigned nx, unsigned ny, size_t m, const double *site,
                          double *ctrl)
{
    if (nx < TF_SPLINE_MIN_SITES || ny < TF_SPLINE_MIN_SITES) {
        return tf_fail(ctx, "a spline over %u x %u sites: at least %d per axis", nx, ny,
                       TF_SPLINE_MIN_SITES);
    }
    unsigned mx = nx + 2, my = ny + 2, big = mx > my ? mx : my;
    double *ax = malloc((size_t)mx * mx * sizeof *ax), *ay = malloc((size_t)my * my * sizeof *ay);
    double *row = malloc((size_t)big * sizeof *row);
    double *mid = malloc((size_t)mx * ny * m * sizeof *mid); /* along a done, ny rows */
    unsigned *px = malloc(mx * sizeof *px), *py = malloc(my * sizeof *py);
    int rc = 0;
    if (!ax || !ay || !row || !mid || !px || !py) {
        rc = tf_fail(ctx, "out of memory");
    } else if (axis_lu(nx, ax, px) != 0 || axis_lu(ny, ay, py) != 0) {
        rc = tf_fail(ctx, "singular spline interpolation matrix (%u x %u sites)", nx, ny);
    }
    for (unsigned j = 0; rc == 0 && j < ny; ++j) {
        for (size_t q = 0; q < m; ++q) {
            row[0] = row[mx - 1] = 0;
            for (unsigned i = 0; i < nx; ++i) {
                row[i + 1] = site[((size_t)j * nx + i) * m + q];
            }
            axis_solve(nx, ax, px, row);
            for (unsigned i = 0; i < mx; ++i) {
                mid[((size_t)j * mx + i) * m + q] = row[i];
            }
        }
    }
    for (unsigned i = 0; rc == 0 && i < mx; ++i) {
        for (size_t q = 0; q < m; ++q) {
            row[0] = row[my - 1] = 0;
            for (unsigned j = 0; j < ny; ++j) {
                row[j + 1] = mid[((size_t)j * mx + i) * m + q];
            }
            axis_solve(ny, ay, py, row);
            for (unsigned j = 0; j < my; ++j) {
                ctrl[((size_t)j * mx + i) * m + q] = row[j];
            }
        }
    }
    free(ax);
    free(ay);
    free(row);
    free(mid);
    free(px);
    free(py);
    return rc;
}

/* Q(g) and its derivatives over the control values cd (double) or, when
 * cd is NULL, cf (float): one sum for both. */
static void eval(unsigned nx, unsigned ny, size_t m, const double *cd, const float *cf, double ga,
                 double gb, double *q, double *dqa, double *dqb)
{
    unsigned ia, jb;
    double ta, tb, wa[4], wb[4], da[4], db[4];
    tf_bspline_cell(ga, nx, &ia, &ta);
    tf_bspline_cell(gb, ny, &jb, &tb);
    tf_bspline_weights(ta, wa, da);
    tf_bspline_weights(tb, wb, db);
    size_t mx = nx + 2;
    memset(q, 0, m * sizeof *q);
    if (dqa) {
        memset(dqa, 0, m * sizeof *dqa);
    }
    if (dqb) {
        memset(dqb, 0, m * sizeof *dqb);
    }
    for (unsigned l = 0; l < 4; ++l) {
        for (unsigned k = 0; k < 4; ++k) {
            const size_t first = ((size_t)(jb + l) * mx + ia + k) * m;
            double w = wb[l] * wa[k];
            for (size_t p = 0; p < m; ++p) {
                const double c = cd != NULL ? cd[first + p] : (double)cf[first + p];
                q[p] += w * c;
                if (dqa) {
                    dqa[p] += wb[l] * da[k] * c;
                }
                if (dqb) {
                    dqb[p] += db[l] * wa[k] * c;
                }
            }
        }
    }
}

void tf_spline_eval(unsigned nx, unsigned ny, size_t m, const double *ctrl, double ga, double gb,
                    double *q, double *dqa, double *dqb)
{
    eval(nx, ny, m, ctrl, NULL, ga, gb, q, dqa, dqb);
}

void tf_spline_eval_float(unsigned nx, unsigned ny, size_t m, const float *ctrl, double ga,
                          double gb, double *q, double *dqa, double *dqb)
{
    eval(nx, ny, m, NULL, ctrl, ga, gb, q, dqa, dqb);
}
