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

/* Inserts (d2, j) into the ascending list (d2s, out) of at most cap
 * entries, ties by index. */
static void keep_sorted(double d2, uint32_t j, double *d2s, uint32_t *out, size_t *m, size_t cap)
{
    size_t k = *m;
    if (k == cap) {
        if (d2 > d2s[k - 1] || (d2 == d2s[k - 1] && j > out[k - 1])) {
            return;
        }
        k--;
    } else {
        (*m)++;
    }
    while (k > 0 && (d2s[k - 1] > d2 || (d2s[k - 1] == d2 && out[k - 1] > j))) {
        d2s[k] = d2s[k - 1];
        out[k] = out[k - 1];
        --k;
    }
    d2s[k] = d2;
    out[k] = j;
}

/* Every node of bin k into the list. */
static void scan_bin(const tf_nbr *g, size_t k, const double x[3], size_t skip, double *d2s,
                     uint32_t *out, size_t *m, size_t cap)
{
    for (uint32_t p = g->start[k]; p < g->start[k + 1]; ++p) {
        uint32_t j = g->items[p];
        if (j == skip) {
            continue;
        }
        const double *y = g->xyz + 3 * (size_t)j;
        double d0 = y[0] - x[0], d1 = y[1] - x[1], d2 = y[2] - x[2];
        keep_sorted(d0 * d0 + d1 * d1 + d2 * d2, j, d2s, out, m, cap);
    }
}

size_t tf_nbr_nearest(const tf_nbr *g, const double x[3], size_t k, double tie, size_t skip,
                      uint32_t *out, double *dist, size_t cap)
{
    double *d2s = malloc((cap ? cap : 1) * sizeof *d2s);
    if (d2s == NULL || k == 0 || cap < k) {
        free(d2s);
        return 0;
    }
    unsigned b0[3];
    bin_of(g, x, b0);
    double step = fmin(g->bin[0], fmin(g->bin[1], g->bin[2]));
    unsigned rmax = 0;
    for (int a = 0; a < 3; ++a) {
        unsigned far = b0[a] > g->dims[a] - 1 - b0[a] ? b0[a] : g->dims[a] - 1 - b0[a];
        rmax = far > rmax ? far : rmax;
    }
    size_t m = 0;
    double lim = (1 + tie) * (1 + tie);
    for (unsigned r = 0; r <= rmax; ++r) {
        /* The shell of bins at Chebyshev distance r from b0, clipped. */
        long lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = (long)b0[a] - (long)r < 0 ? 0 : (long)b0[a] - (long)r;
            hi[a] = (long)b0[a] + (long)r > (long)g->dims[a] - 1 ? (long)g->dims[a] - 1
                                                                 : (long)b0[a] + (long)r;
        }
        for (long c = lo[2]; c <= hi[2]; ++c) {
            for (long b = lo[1]; b <= hi[1]; ++b) {
                for (long a = lo[0]; a <= hi[0]; ++a) {
                    long da = labs(a - (long)b0[0]), db = labs(b - (long)b0[1]),
                         dc = labs(c - (long)b0[2]);
                    long cheb = da > db ? (da > dc ? da : dc) : (db > dc ? db : dc);
                    if (cheb != (long)r) {
                        continue;
                    }
                    size_t bin = (size_t)a + (size_t)g->dims[0] * ((size_t)b + (size_t)g->dims[1] * (size_t)c);
                    scan_bin(g, bin, x, skip, d2s, out, &m, cap);
                }
            }
        }
        /* Every node closer than r bins is in the list now. */
        double reach = r * step;
        if (m >= k && d2s[k - 1] * lim < reach * reach) {
            break;
        }
    }
    size_t n = m < k ? m : k;
    while (tie > 0 && n < m && d2s[n] <= d2s[k - 1] * lim) {
        n++;
    }
    for (size_t i = 0; dist && i < n; ++i) {
        dist[i] = sqrt(d2s[i]);
    }
    free(d2s);
    return n;
}
