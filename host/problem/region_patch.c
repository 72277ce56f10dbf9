/*
 * region_patch.c — the probe's patch at a site of a contact region
 * (region_chart.h) as quadrature points: the tip's outline (a rectangle,
 * or a 128-gon inscribed in its disc) clipped to each cell of a box face's
 * node grid, or to each triangle of an organ's surface graph, so that the
 * patch, and the load it carries, move continuously with the site and no
 * piece straddles a change of the shape functions' supports.
 */
#include "problem/region_chart.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/simplex_rules.h"
#include "geometry/vec3.h"

/* Sides of the polygon inscribed in the tip's disc. */
#define DISC_SIDES 128
/* Degree of the rule on each clipped piece (the organ contact site's). */
#define PIECE_DEGREE 5
/* A triangle or rectangle clipped by a convex DISC_SIDES-gon has at most
 * this many corners. */
#define POLY_MAX (4 + DISC_SIDES)

/* Sutherland-Hodgman: the part of convex polygon p (n corners, ccw, (a, b)
 * pairs) left of the directed edge s -> e, into out.  Returns its size. */
static int clip_edge(const double *p, int n, const double s[2], const double e[2], double *out)
{
    int m = 0;
    for (int i = 0; i < n; ++i) {
        const double *cur = p + 2 * i, *nxt = p + 2 * ((i + 1) % n);
        double dc = (e[0] - s[0]) * (cur[1] - s[1]) - (e[1] - s[1]) * (cur[0] - s[0]);
        double dn = (e[0] - s[0]) * (nxt[1] - s[1]) - (e[1] - s[1]) * (nxt[0] - s[0]);
        if (dc >= 0) {
            out[2 * m] = cur[0];
            out[2 * m + 1] = cur[1];
            m++;
        }
        if ((dc >= 0) != (dn >= 0)) {
            double t = dc / (dc - dn);
            out[2 * m] = cur[0] + t * (nxt[0] - cur[0]);
            out[2 * m + 1] = cur[1] + t * (nxt[1] - cur[1]);
            m++;
        }
    }
    return m;
}

typedef struct points {
    double *v; /* 4 per point */
    size_t n, cap;
} points;

static int push(points *p, const double x[3], double w)
{
    if (p->n == p->cap) {
        size_t cap = p->cap ? 2 * p->cap : 256;
        double *v = realloc(p->v, 4 * cap * sizeof *v);
        if (v == NULL) {
            return -1;
        }
        p->v = v;
        p->cap = cap;
    }
    memcpy(p->v + 4 * p->n, x, 3 * sizeof *x);
    p->v[4 * p->n + 3] = w;
    p->n++;
    return 0;
}

/* An affine map from the chart plane onto a plane of the scene:
 * x = x0 + a da + b db. */
typedef struct plane_map {
    double x0[3], da[3], db[3];
} plane_map;

static void map_point(const plane_map *m, double a, double b, double x[3])
{
    for (int i = 0; i < 3; ++i) {
        x[i] = m->x0[i] + a * m->da[i] + b * m->db[i];
    }
}

/* The map onto kept triangle k's plane: its barycentric coordinates in its
 * projection, applied to its corners. */
static void triangle_map(const tf_problem *p, const tf_region_chart *c, size_t k, plane_map *m)
{
    const double *q = c->q + 9 * k;
    double d = (q[4] - q[7]) * (q[0] - q[6]) + (q[6] - q[3]) * (q[1] - q[7]);
    /* l0 = (A0 a + B0 b + C0) / d, l1 likewise, l2 = 1 - l0 - l1 */
    double A0 = q[4] - q[7], B0 = q[6] - q[3], C0 = -(q[4] - q[7]) * q[6] - (q[6] - q[3]) * q[7];
    double A1 = q[7] - q[1], B1 = q[0] - q[6], C1 = -(q[7] - q[1]) * q[6] - (q[0] - q[6]) * q[7];
    const double *y0 = p->cloud.xyz + 3 * (size_t)c->tri[3 * k];
    const double *y1 = p->cloud.xyz + 3 * (size_t)c->tri[3 * k + 1];
    const double *y2 = p->cloud.xyz + 3 * (size_t)c->tri[3 * k + 2];
    for (int i = 0; i < 3; ++i) {
        m->x0[i] = y2[i] + (C0 * (y0[i] - y2[i]) + C1 * (y1[i] - y2[i])) / d;
        m->da[i] = (A0 * (y0[i] - y2[i]) + A1 * (y1[i] - y2[i])) / d;
        m->db[i] = (B0 * (y0[i] - y2[i]) + B1 * (y1[i] - y2[i])) / d;
    }
}

/* The points of convex polygon sub (ns corners, ccw, (a, b) pairs) inside
 * convex polygon clip (nc corners, ccw), on the plane m maps it to: the
 * intersection fanned into triangles, the rule on each. */
static int piece_points(const double *sub, int ns, const double *clip, int nc, const plane_map *m,
                        const tf_simplex_rule *rule, points *out)
{
    double poly[2][2 * POLY_MAX];
    int n = ns, cur = 0;
    memcpy(poly[0], sub, 2 * (size_t)ns * sizeof *sub);
    for (int e = 0; e < nc && n > 0; ++e) {
        n = clip_edge(poly[cur], n, clip + 2 * e, clip + 2 * ((e + 1) % nc), poly[1 - cur]);
        cur = 1 - cur;
    }
    for (int i = 1; i + 1 < n; ++i) {
        double corner[3][3], x[TF_SIMPLEX_MAX_POINTS][3], w[TF_SIMPLEX_MAX_POINTS];
        const int idx[3] = {0, i, i + 1};
        for (int j = 0; j < 3; ++j) {
            map_point(m, poly[cur][2 * idx[j]], poly[cur][2 * idx[j] + 1], corner[j]);
        }
        if (tf_v3_area(corner[0], corner[1], corner[2]) <= 0) {
            continue;
        }
        tf_tri_points(rule, (const double(*)[3])corner, x, w);
        for (unsigned j = 0; j < rule->n; ++j) {
            if (push(out, x[j], w[j]) != 0) {
                return -1;
            }
        }
    }
    return 0;
}

/* The tip's outline around (a, b), ccw: a rectangle, or a DISC_SIDES-gon
 * inscribed in the disc.  Returns its corner count. */
static int tip_outline(const tf_contact_region *r, double a, double b, double *tp)
{
    if (r->tip == TF_TIP_RECT) {
        double wa = 0.5 * r->tip_size[0], wb = 0.5 * r->tip_size[1];
        const double box[8] = {a - wa, b - wb, a + wa, b - wb, a + wa, b + wb, a - wa, b + wb};
        memcpy(tp, box, sizeof box);
        return 4;
    }
    for (int e = 0; e < DISC_SIDES; ++e) {
        double t = 2 * M_PI * e / DISC_SIDES;
        tp[2 * e] = a + r->tip_radius * cos(t);
        tp[2 * e + 1] = b + r->tip_radius * sin(t);
    }
    return DISC_SIDES;
}

/* Fills patch (TF_PATCH_POINTS) from the points, at site point x. */
static int finish(tf_ctx *ctx, points *pts, const double x[3], double radius, tf_patch *patch,
                  double a, double b)
{
    memset(patch, 0, sizeof *patch);
    patch->shape = TF_PATCH_POINTS;
    patch->radius = radius;
    memcpy(patch->at, x, sizeof patch->at);
    patch->pts = pts->v;
    patch->n_pts = pts->n;
    for (size_t k = 0; k < pts->n; ++k) {
        patch->area += pts->v[4 * k + 3];
    }
    if (!(patch->area > 0)) {
        tf_patch_release(patch);
        return tf_fail(ctx, "no surface within the tip at chart point (%g, %g) mm", a, b);
    }
    return 0;
}

/* A box face: the tip's outline clipped to each cell of the face's grid
 * (the node grid lines, where the shape functions' supports change), so
 * that no piece straddles a cell and each is integrated accurately. */
static int face_patch(tf_ctx *ctx, const tf_problem *p, const tf_contact_region *r, double a,
                      double b, tf_patch *patch, double x[3])
{
    const tf_region_chart *c = &r->chart;
    const tf_cloud *cl = &p->cloud;
    int u, v;
    tf_face_axes(r->face, &u, &v);
    double tp[2 * DISC_SIDES], w[2], q[3] = {a, b, 0};
    int nt = tip_outline(r, a, b, tp);
    tf_region_tip_extent(r, w);
    plane_map m;
    memcpy(m.x0, c->o, sizeof m.x0);
    memcpy(m.da, c->R, sizeof m.da);
    memcpy(m.db, c->R + 3, sizeof m.db);
    double sv = c->R[3 + v]; /* b runs along +v or -v */
    tf_simplex_rule rule;
    tf_tri_rule(PIECE_DEGREE, &rule);
    points pts = {NULL, 0, 0};
    unsigned nu = cl->grid[u], nv = cl->grid[v];
    for (unsigned j = 0; j + 1 < nv; ++j) {
        double b0 = sv * (cl->axis[v][j] - c->o[v]), b1 = sv * (cl->axis[v][j + 1] - c->o[v]);
        double lo_b = fmin(b0, b1), hi_b = fmax(b0, b1);
        if (hi_b <= b - w[1] || lo_b >= b + w[1]) {
            continue;
        }
        for (unsigned i = 0; i + 1 < nu; ++i) {
            double lo_a = cl->axis[u][i] - c->o[u], hi_a = cl->axis[u][i + 1] - c->o[u];
            if (hi_a <= a - w[0] || lo_a >= a + w[0]) {
                continue;
            }
            const double cell[8] = {lo_a, lo_b, hi_a, lo_b, hi_a, hi_b, lo_a, hi_b};
            if (piece_points(cell, 4, tp, nt, &m, &rule, &pts) != 0) {
                free(pts.v);
                return tf_fail(ctx, "out of memory");
            }
        }
    }
    double xs[3];
    tf_region_chart_point(c, q, xs);
    if (x != NULL) {
        memcpy(x, xs, sizeof xs);
    }
    return finish(ctx, &pts, xs, r->tip == TF_TIP_DISC ? r->tip_radius : 0, patch, a, b);
}

/* An organ: every graph triangle's projection clipped to the tip's disc. */
static int organ_patch(tf_ctx *ctx, const tf_problem *p, const tf_contact_region *r, double a,
                       double b, tf_patch *patch, double x[3])
{
    const tf_region_chart *c = &r->chart;
    double rad = r->tip_radius, tp[2 * DISC_SIDES], q[3] = {a, b, 0}, xs[3];
    int nt = tip_outline(r, a, b, tp);
    if (tf_region_chart_height(c, a, b, &q[2]) != 0) {
        return tf_fail(ctx, "no surface under the site at chart point (%g, %g) mm", a, b);
    }
    tf_simplex_rule rule;
    tf_tri_rule(PIECE_DEGREE, &rule);
    points pts = {NULL, 0, 0};
    for (size_t k = 0; k < c->n_tri; ++k) {
        const double *t = c->q + 9 * k;
        if (!c->graph[k] || fmax(fmax(t[0], t[3]), t[6]) < a - rad ||
            fmin(fmin(t[0], t[3]), t[6]) > a + rad || fmax(fmax(t[1], t[4]), t[7]) < b - rad ||
            fmin(fmin(t[1], t[4]), t[7]) > b + rad) {
            continue;
        }
        double sub[6] = {t[0], t[1], t[3], t[4], t[6], t[7]};
        if ((t[3] - t[0]) * (t[7] - t[1]) - (t[4] - t[1]) * (t[6] - t[0]) < 0) {
            sub[2] = t[6]; /* make it counter-clockwise */
            sub[3] = t[7];
            sub[4] = t[3];
            sub[5] = t[4];
        }
        plane_map m;
        triangle_map(p, c, k, &m);
        if (piece_points(sub, 3, tp, nt, &m, &rule, &pts) != 0) {
            free(pts.v);
            return tf_fail(ctx, "out of memory");
        }
    }
    tf_region_chart_point(c, q, xs);
    if (x != NULL) {
        memcpy(x, xs, sizeof xs);
    }
    return finish(ctx, &pts, xs, rad, patch, a, b);
}

int tf_region_site_patch(tf_ctx *ctx, const tf_problem *p, const tf_contact_region *r, double a,
                         double b, tf_patch *patch, double x[3])
{
    if (r->kind == TF_CONTACT_REGION_FACE) {
        return face_patch(ctx, p, r, a, b, patch, x);
    }
    return organ_patch(ctx, p, r, a, b, patch, x);
}
