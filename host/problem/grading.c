/*
 * grading.c — graded grid lines along one axis (grading.h).
 */
#include "problem/grading.h"

#include <math.h>
#include <stdlib.h>

#define SUBSTEPS 256

void tf_cloud_grading_add(tf_cloud_grading *g, int a, double a0, double a1, double lo, double hi)
{
    if (a0 > a1) {
        double t = a0;
        a0 = a1;
        a1 = t;
    }
    a0 = fmin(fmax(a0, lo), hi);
    a1 = fmin(fmax(a1, lo), hi);
    for (size_t k = 0; k < g->n[a]; ++k) {
        if (g->at[a][k][0] == a0 && g->at[a][k][1] == a1) {
            return;
        }
    }
    if (g->n[a] < TF_CLOUD_GRADING_MAX) {
        g->at[a][g->n[a]][0] = a0;
        g->at[a][g->n[a]][1] = a1;
        g->n[a]++;
    }
}

/* Distance from x to the nearest attractor interval. */
static double distance(double x, const double (*at)[2], size_t na)
{
    double d = INFINITY;
    for (size_t k = 0; k < na; ++k) {
        double e = x < at[k][0] ? at[k][0] - x : x > at[k][1] ? x - at[k][1] : 0;
        d = fmin(d, e);
    }
    return d;
}

static void uniform(double lo, double hi, unsigned n, double *x)
{
    double h = (hi - lo) / (n - 1);
    for (unsigned i = 0; i + 1 < n; ++i) {
        x[i] = lo + i * h;
    }
    x[n - 1] = hi;
}

int tf_cloud_grading_axis(double lo, double hi, unsigned n, double ratio, const double (*at)[2],
                    size_t na, double *x)
{
    size_t m = (size_t)SUBSTEPS * (n - 1);
    double *phi = malloc((m + 1) * sizeof *phi), *d = malloc((m + 1) * sizeof *d);
    if (phi == NULL || d == NULL) {
        free(phi);
        free(d);
        return -1;
    }
    double dx = (hi - lo) / (double)m, dmax = 0;
    for (size_t k = 0; k <= m; ++k) {
        d[k] = na ? distance(lo + (double)k * dx, at, na) : 0;
        dmax = fmax(dmax, d[k]);
    }
    if (!(ratio > 1) || !(dmax > 0)) {
        uniform(lo, hi, n, x);
        free(phi);
        free(d);
        return 0;
    }
    /* phi(x) = ∫ dx / h, h = 1 + (ratio - 1) d / dmax (trapezoid rule) */
    phi[0] = 0;
    double w0 = 1 / (1 + (ratio - 1) * d[0] / dmax);
    for (size_t k = 1; k <= m; ++k) {
        double w1 = 1 / (1 + (ratio - 1) * d[k] / dmax);
        phi[k] = phi[k - 1] + 0.5 * (w0 + w1) * dx;
        w0 = w1;
    }
    /* x_i where phi = i / (n - 1) of the total, by linear interpolation */
    x[0] = lo;
    x[n - 1] = hi;
    size_t k = 0;
    for (unsigned i = 1; i + 1 < n; ++i) {
        double target = phi[m] * i / (n - 1);
        while (k + 1 < m && phi[k + 1] < target) {
            k++;
        }
        double t = (target - phi[k]) / (phi[k + 1] - phi[k]);
        x[i] = lo + ((double)k + t) * dx;
    }
    free(phi);
    free(d);
    return 0;
}

unsigned tf_cloud_lines_interval(const double *lines, unsigned n, double x)
{
    unsigned lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        unsigned mid = (lo + hi) / 2;
        if (lines[mid] <= x) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return lo;
}
