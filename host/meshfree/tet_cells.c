/*
 * tet_cells.c — tetrahedral cells: rules, geometry and point location
 * (tet_cells.h).
 */
#include "meshfree/tet_cells.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void corners(const tf_cells *c, size_t cell, double x[4][3])
{
    for (int k = 0; k < 4; ++k) {
        memcpy(x[k], c->tet_xyz + 3 * c->tet[4 * cell + (size_t)k], sizeof x[k]);
    }
}

void tf_cells_tet_point(const tf_cells *c, size_t cell, size_t p, double x[3], double *w)
{
    double v[4][3];
    corners(c, cell, v);
    /* tf_tet_points of the whole rule, point p only (same arithmetic). */
    double xs[TF_SIMPLEX_MAX_POINTS][3], ws[TF_SIMPLEX_MAX_POINTS];
    tf_tet_points(&c->rule, (const double(*)[3])v, xs, ws);
    memcpy(x, xs[p], 3 * sizeof *x);
    *w = ws[p];
}

void tf_cells_tet_box(const tf_cells *c, size_t cell, double centre[3], double half[3])
{
    double v[4][3];
    corners(c, cell, v);
    for (int a = 0; a < 3; ++a) {
        double lo = fmin(fmin(v[0][a], v[1][a]), fmin(v[2][a], v[3][a]));
        double hi = fmax(fmax(v[0][a], v[1][a]), fmax(v[2][a], v[3][a]));
        centre[a] = (v[0][a] + v[1][a] + v[2][a] + v[3][a]) / 4;
        half[a] = 0.5 * (hi - lo);
    }
}

static size_t bin_index(const tf_tet_locator *l, const unsigned b[3])
{
    return b[0] + (size_t)l->dims[0] * (b[1] + (size_t)l->dims[1] * b[2]);
}

static void bin_of(const tf_tet_locator *l, const double x[3], unsigned b[3])
{
    for (int a = 0; a < 3; ++a) {
        double t = floor((x[a] - l->lo[a]) / l->bin[a]);
        b[a] = t < 0 ? 0 : t >= l->dims[a] ? l->dims[a] - 1 : (unsigned)t;
    }
}

/* Bins of the bounding box of cell e: lo[] .. hi[] per axis. */
static void cell_bins(const tf_cells *c, size_t e, unsigned lo[3], unsigned hi[3])
{
    double centre[3], half[3], a[3], b[3];
    tf_cells_tet_box(c, e, centre, half);
    for (int k = 0; k < 3; ++k) {
        a[k] = centre[k] - half[k];
        b[k] = centre[k] + half[k];
    }
    bin_of(&c->loc, a, lo);
    bin_of(&c->loc, b, hi);
}

/* Two passes over the cells' bins: count, then fill (cells ascending). */
static int fill_bins(tf_cells *c)
{
    tf_tet_locator *l = &c->loc;
    size_t nb = (size_t)l->dims[0] * l->dims[1] * l->dims[2], total = 0;
    l->start = calloc(nb + 1, sizeof *l->start);
    for (int pass = 0; pass < 2 && l->start != NULL; ++pass) {
        if (pass == 1) {
            for (size_t k = 0; k < nb; ++k) {
                l->start[k + 1] += l->start[k];
            }
            total = l->start[nb];
            l->items = malloc((total + 1) * sizeof *l->items);
            if (l->items == NULL) {
                return -1;
            }
        }
        uint32_t *cursor = pass == 1 ? calloc(nb + 1, sizeof *cursor) : NULL;
        if (pass == 1 && cursor == NULL) {
            return -1;
        }
        for (size_t e = 0; e < c->ntet; ++e) {
            unsigned lo[3], hi[3], b[3];
            cell_bins(c, e, lo, hi);
            for (b[2] = lo[2]; b[2] <= hi[2]; ++b[2]) {
                for (b[1] = lo[1]; b[1] <= hi[1]; ++b[1]) {
                    for (b[0] = lo[0]; b[0] <= hi[0]; ++b[0]) {
                        size_t k = bin_index(l, b);
                        if (pass == 0) {
                            l->start[k + 1]++;
                        } else {
                            l->items[l->start[k] + cursor[k]++] = (uint32_t)e;
                        }
                    }
                }
            }
        }
        free(cursor);
    }
    return l->start ? 0 : -1;
}

/* A grid of about one bin per cell over the cells' bounding box. */
static int build_locator(tf_cells *c)
{
    tf_tet_locator *l = &c->loc;
    double hi[3];
    for (int a = 0; a < 3; ++a) {
        l->lo[a] = INFINITY;
        hi[a] = -INFINITY;
    }
    for (size_t e = 0; e < c->ntet; ++e) {
        for (int k = 0; k < 4; ++k) {
            const double *x = c->tet_xyz + 3 * c->tet[4 * e + (size_t)k];
            for (int a = 0; a < 3; ++a) {
                l->lo[a] = fmin(l->lo[a], x[a]);
                hi[a] = fmax(hi[a], x[a]);
            }
        }
    }
    double volume = 1, side;
    for (int a = 0; a < 3; ++a) {
        volume *= fmax(hi[a] - l->lo[a], 1e-12);
    }
    side = cbrt(volume / (double)c->ntet);
    for (int a = 0; a < 3; ++a) {
        double d = floor((hi[a] - l->lo[a]) / side) + 1;
        l->dims[a] = d > 1 ? (unsigned)d : 1;
        l->bin[a] = fmax(hi[a] - l->lo[a], 1e-12) / l->dims[a];
    }
    return fill_bins(c);
}

int tf_cells_use_tets(tf_cells *c, const double *xyz, const size_t *tet, size_t ntet,
                      unsigned degree)
{
    if (ntet == 0 || tf_tet_rule(degree, &c->rule) != 0) {
        return -1;
    }
    c->tet_xyz = xyz;
    c->tet = tet;
    c->ntet = ntet;
    if (build_locator(c) != 0) {
        tf_cells_tet_free(c);
        return -1;
    }
    return 0;
}

void tf_cells_tet_free(tf_cells *c)
{
    free(c->loc.start);
    free(c->loc.items);
    c->loc.start = c->loc.items = NULL;
    c->tet = NULL;
    c->tet_xyz = NULL;
    c->ntet = 0;
}

/* The smallest barycentric coordinate of x in cell e: >= 0 inside. */
static double inside(const tf_cells *c, size_t e, const double x[3])
{
    double v[4][3], m[3][3], r[3];
    corners(c, e, v);
    for (int a = 0; a < 3; ++a) {
        for (int k = 0; k < 3; ++k) {
            m[a][k] = v[k + 1][a] - v[0][a];
        }
        r[a] = x[a] - v[0][a];
    }
    double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                 m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                 m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    double l[4];
    for (int k = 0; k < 3; ++k) { /* Cramer's rule, column k replaced by r */
        double q[3][3];
        memcpy(q, m, sizeof q);
        for (int a = 0; a < 3; ++a) {
            q[a][k] = r[a];
        }
        l[k + 1] = (q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1]) -
                    q[0][1] * (q[1][0] * q[2][2] - q[1][2] * q[2][0]) +
                    q[0][2] * (q[1][0] * q[2][1] - q[1][1] * q[2][0])) /
                   det;
    }
    l[0] = 1 - l[1] - l[2] - l[3];
    return fmin(fmin(l[0], l[1]), fmin(l[2], l[3]));
}

size_t tf_cells_locate(const tf_cells *c, const double x[3])
{
    const tf_tet_locator *l = &c->loc;
    unsigned b[3];
    bin_of(l, x, b);
    size_t k = bin_index(l, b), best = SIZE_MAX;
    double score = -INFINITY;
    for (uint32_t p = l->start[k]; p < l->start[k + 1]; ++p) {
        double s = inside(c, l->items[p], x);
        if (s > score) {
            score = s;
            best = l->items[p];
        }
    }
    for (size_t e = 0; best == SIZE_MAX && e < c->ntet; ++e) { /* outside every bin's cells */
        double s = inside(c, e, x);
        if (s > score) {
            score = s;
            best = e;
        }
    }
    return best == SIZE_MAX ? 0 : best;
}

tf_qpoint *tf_patch_surface_points(const tf_patch *p, const tf_cloud *cloud, size_t *n)
{
    tf_simplex_rule r;
    tf_tri_rule(5, &r);
    tf_qpoint *q = malloc((p->n_tri * r.n + 1) * sizeof *q);
    *n = 0;
    for (size_t t = 0; q != NULL && t < p->n_tri; ++t) {
        double c[3][3], x[TF_SIMPLEX_MAX_POINTS][3], w[TF_SIMPLEX_MAX_POINTS];
        for (int k = 0; k < 3; ++k) {
            memcpy(c[k], cloud->xyz + 3 * (size_t)p->tri[3 * t + (size_t)k], sizeof c[k]);
        }
        tf_tri_points(&r, (const double(*)[3])c, x, w);
        for (unsigned k = 0; k < r.n; ++k) {
            memcpy(q[*n].x, x[k], sizeof q[*n].x);
            q[*n].w = w[k];
            (*n)++;
        }
    }
    return q;
}
