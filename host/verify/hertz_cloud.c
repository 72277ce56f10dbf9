/*
 * hertz_cloud.c — nested-grid quarter blocks for the Hertz test
 * (hertz_cloud.h).
 */
#include "verify/hertz_cloud.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "meshfree/neighbours.h"

typedef struct levels {
    double h0, ratio;
    int cells, count;
} levels;

static double spacing(const levels *lv, int l) { return lv->h0 * pow(lv->ratio, l); }
static double box(const levels *lv, int l) { return lv->cells * spacing(lv, l); }

/* Inside the box of half-width b: x, y <= b and -z <= b. */
static int within(const double x[3], double b)
{
    return x[0] <= b && x[1] <= b && -x[2] <= b;
}

/* Level l's grid points; only counts when X is NULL. */
static size_t level_points(const levels *lv, int l, double *X, unsigned char *fixed)
{
    double h = spacing(lv, l), inner = l > 0 ? box(lv, l - 1) + h / 2 : -1;
    long m = lv->cells;
    size_t n = 0;
    for (long k = 0; k <= m; ++k) {
        for (long j = 0; j <= m; ++j) {
            for (long i = 0; i <= m; ++i) {
                double x[3] = {(double)i * h, (double)j * h, -(double)k * h};
                if (l > 0 && within(x, inner * (1 - 1e-12))) {
                    continue; /* a finer level's region */
                }
                if (X) {
                    int edge = l == lv->count - 1 && (i == m || j == m || k == m);
                    for (int a = 0; a < 3; ++a) {
                        X[3 * n + a] = x[a];
                    }
                    fixed[n] = edge ? 7 : 0;
                }
                n++;
            }
        }
    }
    return n;
}

/* Length of [lo, hi] outside [0, b]. */
static double outside(double lo, double hi, double b)
{
    return (hi - lo) - fmax(0, fmin(hi, b) - fmax(lo, 0));
}

/* Voronoi volumes by sampling each level's region at a quarter of its
 * spacing: a sampling cell counts with its part outside the finer box. */
static int voronoi(tf_hertz_cloud *hc, const levels *lv)
{
    tf_nbr g;
    double r[3] = {lv->h0, lv->h0, lv->h0};
    if (tf_nbr_build(&g, hc->X, hc->n, r) != 0) {
        return -1;
    }
    for (size_t i = 0; i < hc->n; ++i) {
        hc->volume[i] = 0;
    }
    for (int l = 0; l < lv->count; ++l) {
        double hs = spacing(lv, l) / 4, b = l > 0 ? box(lv, l - 1) : 0;
        long m = 4L * lv->cells;
        for (long k = 0; k < m; ++k) {
            for (long j = 0; j < m; ++j) {
                for (long i = 0; i < m; ++i) {
                    double lo[3] = {(double)i * hs, (double)j * hs, (double)k * hs}, in = 1;
                    for (int a = 0; a < 3; ++a) { /* the part of the cell inside the box */
                        in *= hs - outside(lo[a], lo[a] + hs, b);
                    }
                    double dv = hs * hs * hs - in;
                    if (!(dv > 1e-12 * hs * hs * hs)) {
                        continue;
                    }
                    double x[3] = {lo[0] + hs / 2, lo[1] + hs / 2, -(lo[2] + hs / 2)};
                    uint32_t near;
                    if (tf_nbr_nearest(&g, x, 1, 0, SIZE_MAX, &near, NULL, 1) != 1) {
                        tf_nbr_free(&g);
                        return -1;
                    }
                    hc->volume[near] += dv;
                }
            }
        }
    }
    tf_nbr_free(&g);
    return 0;
}

int tf_hertz_cloud_make(tf_hertz_cloud *hc, double h0, int cells, int count, double ratio)
{
    *hc = (tf_hertz_cloud){0};
    if (cells < 2 || count < 1 || count > 40 || !(h0 > 0) || !(ratio >= 1.2 && ratio <= 4)) {
        return -1;
    }
    levels lv = {.h0 = h0, .ratio = ratio, .cells = cells, .count = count};
    size_t n = 0;
    for (int l = 0; l < count; ++l) {
        n += level_points(&lv, l, NULL, NULL);
    }
    hc->X = malloc(3 * n * sizeof *hc->X);
    hc->volume = malloc(n * sizeof *hc->volume);
    hc->fixed = malloc(n);
    if (!hc->X || !hc->volume || !hc->fixed) {
        tf_hertz_cloud_free(hc);
        return -1;
    }
    for (int l = 0; l < count; ++l) {
        hc->n += level_points(&lv, l, hc->X + 3 * hc->n, hc->fixed + hc->n);
    }
    hc->L = box(&lv, count - 1);
    hc->volume_total = hc->L * hc->L * hc->L;
    if (voronoi(hc, &lv) != 0) {
        tf_hertz_cloud_free(hc);
        return -1;
    }
    return 0;
}

void tf_hertz_cloud_free(tf_hertz_cloud *hc)
{
    free(hc->X);
    free(hc->volume);
    free(hc->fixed);
    *hc = (tf_hertz_cloud){0};
}
