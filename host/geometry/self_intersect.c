/*
 * self_intersect.c — crossing triangle pairs (self_intersect.h).  Each
 * triangle is filed in the cells of a uniform grid that its bounding box
 * overlaps (about one triangle per cell); two triangles are tested only in
 * the cell holding the lowest corner of their boxes' overlap, so each pair
 * once.  Two triangles that do not share a vertex cross when an edge of one
 * passes through the other (non-coplanar case).
 */
#include "geometry/self_intersect.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/vec3.h"

int tf_segment_crosses_triangle(const double p[3], const double q[3], const double a[3],
                                const double b[3], const double c[3], double at[3])
{
    double sp = tf_v3_orient(a, b, c, p), sq = tf_v3_orient(a, b, c, q);
    if (!((sp > 0 && sq < 0) || (sp < 0 && sq > 0))) {
        return 0;
    }
    double e0 = tf_v3_orient(p, q, a, b), e1 = tf_v3_orient(p, q, b, c),
           e2 = tf_v3_orient(p, q, c, a);
    if (!((e0 > 0 && e1 > 0 && e2 > 0) || (e0 < 0 && e1 < 0 && e2 < 0))) {
        return 0;
    }
    double f = sp / (sp - sq);
    for (int k = 0; k < 3; ++k) {
        at[k] = p[k] + f * (q[k] - p[k]);
    }
    return 1;
}

typedef struct grid {
    double lo[3], inv[3];
    size_t n[3];
    size_t *start; /* cells + 1 offsets into item */
    size_t *item;  /* triangle indices by cell */
    double *box;   /* 6 per triangle: lo, hi */
} grid;

static size_t cell_of(const grid *g, int a, double x)
{
    double c = floor((x - g->lo[a]) * g->inv[a]);
    return c < 0 ? 0 : c >= (double)g->n[a] ? g->n[a] - 1 : (size_t)c;
}

static const double *vertex(const tf_surface *s, size_t t, int k)
{
    return s->xyz + 3 * s->tri[3 * t + k];
}

/* For every cell each triangle's box overlaps: fill = 0 counts it (in
 * start[cell + 1]), fill = 1 files it (at start[cell], which advances). */
static void file_triangles(grid *g, const tf_surface *s, int fill)
{
    for (size_t t = 0; t < s->nt; ++t) {
        const double *bx = g->box + 6 * t;
        size_t c0[3], c1[3];
        for (int a = 0; a < 3; ++a) {
            c0[a] = cell_of(g, a, bx[a]);
            c1[a] = cell_of(g, a, bx[3 + a]);
        }
        for (size_t k = c0[2]; k <= c1[2]; ++k) {
            for (size_t j = c0[1]; j <= c1[1]; ++j) {
                for (size_t i = c0[0]; i <= c1[0]; ++i) {
                    size_t cell = i + g->n[0] * (j + g->n[1] * k);
                    if (fill) {
                        g->item[g->start[cell]++] = t;
                    } else {
                        g->start[cell + 1]++;
                    }
                }
            }
        }
    }
}

static int grid_build(grid *g, const tf_surface *s)
{
    memset(g, 0, sizeof *g);
    double hi[3];
    tf_surface_bbox(s, g->lo, hi);
    double ext[3], vol = 1;
    for (int a = 0; a < 3; ++a) {
        ext[a] = fmax(hi[a] - g->lo[a], 1e-12 * (fabs(hi[a]) + fabs(g->lo[a]) + 1));
        vol *= ext[a];
    }
    /* About one cell per triangle; a flat box must not make billions. */
    size_t cells = 0;
    for (double h = cbrt(vol / (double)(s->nt + 1)); cells == 0 || cells > 8 * (s->nt + 1);
         h *= 1.25) {
        cells = 1;
        for (int a = 0; a < 3; ++a) {
            double n = ceil(ext[a] / h);
            g->n[a] = n < 1 ? 1 : n > 4096 ? 4096 : (size_t)n;
            g->inv[a] = (double)g->n[a] / ext[a];
            cells *= g->n[a];
        }
    }
    g->box = malloc((6 * s->nt + 1) * sizeof *g->box);
    g->start = calloc(cells + 1, sizeof *g->start);
    if (g->box == NULL || g->start == NULL) {
        return -1;
    }
    for (size_t t = 0; t < s->nt; ++t) {
        for (int a = 0; a < 3; ++a) {
            double x0 = vertex(s, t, 0)[a], x1 = vertex(s, t, 1)[a], x2 = vertex(s, t, 2)[a];
            g->box[6 * t + a] = fmin(x0, fmin(x1, x2));
            g->box[6 * t + 3 + a] = fmax(x0, fmax(x1, x2));
        }
    }
    file_triangles(g, s, 0);
    for (size_t c = 0; c < cells; ++c) {
        g->start[c + 1] += g->start[c];
    }
    g->item = malloc((g->start[cells] + 1) * sizeof *g->item);
    if (g->item == NULL) {
        return -1;
    }
    file_triangles(g, s, 1); /* leaves start[c] at the end of cell c */
    memmove(g->start + 1, g->start, cells * sizeof *g->start);
    g->start[0] = 0;
    return 0;
}

static void grid_free(grid *g)
{
    free(g->box);
    free(g->start);
    free(g->item);
}

static int share_vertex(const tf_surface *s, size_t t, size_t u)
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (s->tri[3 * t + i] == s->tri[3 * u + j]) {
                return 1;
            }
        }
    }
    return 0;
}

/* An edge of t through u, or of u through t. */
static int cross(const tf_surface *s, size_t t, size_t u, double at[3])
{
    for (int pass = 0; pass < 2; ++pass) {
        size_t e = pass ? u : t, f = pass ? t : u;
        for (int k = 0; k < 3; ++k) {
            if (tf_segment_crosses_triangle(vertex(s, e, k), vertex(s, e, (k + 1) % 3),
                                            vertex(s, f, 0), vertex(s, f, 1), vertex(s, f, 2),
                                            at)) {
                return 1;
            }
        }
    }
    return 0;
}

/* Is `cell` the one holding the lowest corner of the overlap of the boxes
 * of t and u?  (0 when the boxes do not overlap.) */
static int owns_pair(const grid *g, size_t cell, size_t t, size_t u)
{
    const double *bt = g->box + 6 * t, *bu = g->box + 6 * u;
    size_t c[3];
    for (int a = 0; a < 3; ++a) {
        if (bt[a] > bu[3 + a] || bu[a] > bt[3 + a]) {
            return 0;
        }
        c[a] = cell_of(g, a, fmax(bt[a], bu[a]));
    }
    return cell == c[0] + g->n[0] * (c[1] + g->n[1] * c[2]);
}

static void note(tf_crossing *c, size_t t, size_t u, const double at[3])
{
    size_t lo = t < u ? t : u, hi = t < u ? u : t;
    if (c->pairs++ == 0 || lo < c->tri[0] || (lo == c->tri[0] && hi < c->tri[1])) {
        c->tri[0] = lo;
        c->tri[1] = hi;
        memcpy(c->at, at, sizeof c->at);
    }
}

int tf_surface_crossings(const tf_surface *s, tf_crossing *c)
{
    memset(c, 0, sizeof *c);
    grid g;
    if (grid_build(&g, s) != 0) {
        grid_free(&g);
        return -1;
    }
    size_t cells = g.n[0] * g.n[1] * g.n[2];
    for (size_t cell = 0; cell < cells; ++cell) {
        for (size_t i = g.start[cell]; i < g.start[cell + 1]; ++i) {
            for (size_t j = i + 1; j < g.start[cell + 1]; ++j) {
                size_t t = g.item[i], u = g.item[j];
                double at[3];
                if (owns_pair(&g, cell, t, u) && !share_vertex(s, t, u) && cross(s, t, u, at)) {
                    note(c, t, u, at);
                }
            }
        }
    }
    grid_free(&g);
    return 0;
}
