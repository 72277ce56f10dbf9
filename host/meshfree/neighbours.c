/*
 * neighbours.c — uniform bin grid for support-domain queries (neighbours.h).
 */
#include "meshfree/neighbours.h"

#include <math.h>
#include <stdlib.h>

/* Bins in a grid bounded to about one per node, whatever the radius.  The
 * counts are compared in double: a tiny radius (solver.support=1e-16) asks
 * for more bins per axis than an unsigned holds, and converting such a
 * count is undefined (it gave 0 bins). */
static void choose_bins(tf_nbr *g, const double hi[3], size_t n)
{
    const double most = 2.0 * (double)n + 64;
    for (int a = 0; a < 3; ++a) {
        if (!(g->bin[a] > 0 && isfinite(g->bin[a]))) {
            g->bin[a] = hi[a] > g->lo[a] ? hi[a] - g->lo[a] : 1;
        }
    }
    for (;;) {
        double count[3], total = 1;
        for (int a = 0; a < 3; ++a) {
            count[a] = fmax(floor((hi[a] - g->lo[a]) / g->bin[a]) + 1, 1);
            total *= count[a];
        }
        if (total <= most) {
            for (int a = 0; a < 3; ++a) {
                g->dims[a] = (unsigned)count[a];
            }
            return;
        }
        double grow = fmax(1.25, cbrt(total / most));
        for (int a = 0; a < 3; ++a) {
            g->bin[a] *= grow;
        }
    }
}

static size_t bin_of(const tf_nbr *g, const double x[3], unsigned b[3])
{
    for (int a = 0; a < 3; ++a) {
        double t = floor((x[a] - g->lo[a]) / g->bin[a]);
        b[a] = !(t >= 0) ? 0 : t >= g->dims[a] ? g->dims[a] - 1 : (unsigned)t;
    }
    return b[0] + (size_t)g->dims[0] * (b[1] + (size_t)g->dims[1] * b[2]);
}

int tf_nbr_build(tf_nbr *g, const double *xyz, size_t n, const double radius[3])
{
    double hi[3];
    g->xyz = xyz;
    g->n = n;
    for (int a = 0; a < 3; ++a) {
        g->radius[a] = radius[a];
        g->bin[a] = radius[a];
        g->lo[a] = hi[a] = n ? xyz[a] : 0;
    }
    for (size_t i = 0; i < n; ++i) {
        for (int a = 0; a < 3; ++a) {
            g->lo[a] = fmin(g->lo[a], xyz[3 * i + a]);
            hi[a] = fmax(hi[a], xyz[3 * i + a]);
        }
    }
    choose_bins(g, hi, n);
    size_t nb = (size_t)g->dims[0] * g->dims[1] * g->dims[2];
    g->start = calloc(nb + 1, sizeof *g->start);
    g->items = malloc((n ? n : 1) * sizeof *g->items);
    uint32_t *fill = malloc((nb + 1) * sizeof *fill);
    if (g->start == NULL || g->items == NULL || fill == NULL) {
        free(fill);
        tf_nbr_free(g);
        return -1;
    }
    /* Counting sort by bin; nodes enter their bin in ascending order. */
    unsigned b[3];
    for (size_t i = 0; i < n; ++i) {
        g->start[bin_of(g, xyz + 3 * i, b) + 1]++;
    }
    for (size_t k = 0; k < nb; ++k) {
        g->start[k + 1] += g->start[k];
    }
    for (size_t k = 0; k <= nb; ++k) {
        fill[k] = g->start[k];
    }
    for (size_t i = 0; i < n; ++i) {
        g->items[fill[bin_of(g, xyz + 3 * i, b)]++] = (uint32_t)i;
    }
    free(fill);
    return 0;
}

void tf_nbr_free(tf_nbr *g)
{
    free(g->start);
    free(g->items);
    g->start = NULL;
    g->items = NULL;
}

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

static size_t query_radii(const tf_nbr *g, const double x[3], const double radius[3],
                          uint32_t *out, size_t cap);

size_t tf_nbr_query(const tf_nbr *g, const double x[3], uint32_t *out, size_t cap)
{
    return query_radii(g, x, g->radius, out, cap);
}

size_t tf_nbr_query_ball(const tf_nbr *g, const double x[3], double r, uint32_t *out, size_t cap)
{
    const double radius[3] = {r, r, r};
    return query_radii(g, x, radius, out, cap);
}

static size_t query_radii(const tf_nbr *g, const double x[3], const double radius[3],
                          uint32_t *out, size_t cap)
{
    unsigned lo[3], hi[3], b[3];
    double xl[3], xh[3];
    for (int a = 0; a < 3; ++a) {
        xl[a] = x[a] - radius[a];
        xh[a] = x[a] + radius[a];
    }
    bin_of(g, xl, lo);
    bin_of(g, xh, hi);
    size_t count = 0;
    for (b[2] = lo[2]; b[2] <= hi[2]; ++b[2]) {
        for (b[1] = lo[1]; b[1] <= hi[1]; ++b[1]) {
            for (b[0] = lo[0]; b[0] <= hi[0]; ++b[0]) {
                size_t k = b[0] + (size_t)g->dims[0] * (b[1] + (size_t)g->dims[1] * b[2]);
                for (uint32_t p = g->start[k]; p < g->start[k + 1]; ++p) {
                    const double *y = g->xyz + 3 * (size_t)g->items[p];
                    double s = 0;
                    for (int a = 0; a < 3; ++a) {
                        double t = (y[a] - x[a]) / radius[a];
                        s += t * t;
                    }
                    if (s <= 1) {
                        if (count < cap) {
                            out[count] = g->items[p];
                        }
                        count++;
                    }
                }
            }
        }
    }
    if (count <= cap && count > 1) { /* out may be NULL when nothing was found */
        qsort(out, count, sizeof *out, cmp_u32);
    }
    return count;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double tf_nbr_kth_distance(const tf_nbr *g, const double x[3], size_t k)
{
    double r = fmax(g->bin[0], fmax(g->bin[1], g->bin[2]));
    size_t cap = 64, n;
    uint32_t *idx = malloc(cap * sizeof *idx);
    for (;;) { /* grow the ball until it holds k nodes (the first guess usually does) */
        if (idx == NULL) {
            return -1;
        }
        n = tf_nbr_query_ball(g, x, r, idx, cap);
        if (n > cap) {
            uint32_t *grown = realloc(idx, n * sizeof *idx);
            if (grown == NULL) {
                free(idx);
                return -1;
            }
            idx = grown;
            cap = n;
            continue;
        }
        if (n >= k || n == g->n) {
            break;
        }
        r *= 2;
    }
    double *d = malloc((n + 1) * sizeof *d);
    if (d == NULL) {
        free(idx);
        return -1;
    }
    for (size_t i = 0; i < n; ++i) {
        const double *y = g->xyz + 3 * (size_t)idx[i];
        d[i] = sqrt((y[0] - x[0]) * (y[0] - x[0]) + (y[1] - x[1]) * (y[1] - x[1]) +
                    (y[2] - x[2]) * (y[2] - x[2]));
    }
    qsort(d, n, sizeof *d, cmp_double);
    double dk = d[(k < n ? k : n) - 1];
    free(d);
    free(idx);
    return dk;
}
