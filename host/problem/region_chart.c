/*
 * region_chart.c — a contact region's chart on a box face or an organ
 * (region_chart.h).
 */
#include "problem/region_chart.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/vec3.h"

void tf_region_chart_coords(const tf_region_chart *c, const double x[3], double q[3])
{
    double d[3];
    tf_v3_sub(x, c->o, d);
    for (int k = 0; k < 3; ++k) {
        q[k] = tf_v3_dot(c->R + 3 * k, d);
    }
}

void tf_region_chart_point(const tf_region_chart *c, const double q[3], double x[3])
{
    for (int a = 0; a < 3; ++a) {
        x[a] = c->o[a] + q[0] * c->R[a] + q[1] * c->R[3 + a] + q[2] * c->R[6 + a];
    }
}

void tf_region_chart_free(tf_region_chart *c)
{
    free(c->tri);
    free(c->q);
    free(c->graph);
    c->tri = NULL;
    c->q = NULL;
    c->graph = NULL;
    c->n_tri = 0;
}

void tf_region_tip_extent(const tf_contact_region *r, double w[2])
{
    w[0] = r->tip == TF_TIP_RECT ? 0.5 * r->tip_size[0] : r->tip_radius;
    w[1] = r->tip == TF_TIP_RECT ? 0.5 * r->tip_size[1] : r->tip_radius;
}

/* ---- a box face ---------------------------------------------------------- */

static int face_chart(tf_ctx *ctx, const tf_problem *p, tf_contact_region *r)
{
    if (p->geometry.kind != TF_GEOMETRY_BOX) {
        return tf_fail(ctx, "a face region lies on a box (geometry.box); on an organ give "
                            "centre and radius (or size)");
    }
    const tf_cloud *cl = &p->cloud;
    int u, v, ax = tf_face_axis(r->face);
    tf_face_axes(r->face, &u, &v);
    double tol = tf_cloud_tol(cl), w[2];
    const double *rc = r->rect;
    if (!(rc[0] < rc[1] && rc[2] < rc[3])) {
        return tf_fail(ctx, "rect is [a0, a1, b0, b1] with a0 < a1 and b0 < b1 (got [%g, %g, %g, "
                            "%g])", rc[0], rc[1], rc[2], rc[3]);
    }
    if (rc[0] < cl->lo[u] - tol || rc[1] > cl->hi[u] + tol || rc[2] < cl->lo[v] - tol ||
        rc[3] > cl->hi[v] + tol) {
        return tf_fail(ctx, "the rectangle [%g, %g] x [%g, %g] mm must lie inside the face, "
                            "[%g, %g] x [%g, %g] mm in its (%c, %c) coordinates",
                       rc[0], rc[1], rc[2], rc[3], cl->lo[u], cl->hi[u], cl->lo[v], cl->hi[v],
                       "xyz"[u], "xyz"[v]);
    }
    tf_region_tip_extent(r, w);
    if (rc[0] - w[0] < cl->lo[u] - tol || rc[1] + w[0] > cl->hi[u] + tol ||
        rc[2] - w[1] < cl->lo[v] - tol || rc[3] + w[1] > cl->hi[v] + tol) {
        return tf_fail(ctx, "the tip reaches %g x %g mm beyond a site: at the rectangle's edge it "
                            "leaves the face; keep the rectangle that far inside the face",
                       w[0], w[1]);
    }
    tf_region_chart *c = &r->chart;
    double n[3] = {0, 0, 0}, e1[3] = {0, 0, 0}, e2[3];
    n[ax] = tf_face_is_max(r->face) ? 1 : -1;
    e1[u] = 1;
    tf_v3_cross(n, e1, e2);
    memcpy(c->R, e1, sizeof e1);
    memcpy(c->R + 3, e2, sizeof e2);
    memcpy(c->R + 6, n, sizeof n);
    c->o[ax] = tf_cloud_face_coord(cl, r->face);
    c->o[u] = rc[0];
    c->o[v] = e2[v] > 0 ? rc[2] : rc[3]; /* e2 runs along +v or -v */
    c->len[0] = rc[1] - rc[0];
    c->len[1] = rc[3] - rc[2];
    c->flat = 1;
    return 0;
}

/* ---- an organ ------------------------------------------------------------ */

/* The point of triangle abc nearest p (Ericson, Real-Time Collision
 * Detection, 2005, §5.1.5). */
static void closest_on_triangle(const double p[3], const double a[3], const double b[3],
                                const double c[3], double out[3])
{
    double ab[3], ac[3], ap[3], bp[3], cp[3];
    tf_v3_sub(b, a, ab);
    tf_v3_sub(c, a, ac);
    tf_v3_sub(p, a, ap);
    double d1 = tf_v3_dot(ab, ap), d2 = tf_v3_dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) {
        memcpy(out, a, 3 * sizeof *out);
        return;
    }
    tf_v3_sub(p, b, bp);
    double d3 = tf_v3_dot(ab, bp), d4 = tf_v3_dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) {
        memcpy(out, b, 3 * sizeof *out);
        return;
    }
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        double t = d1 / (d1 - d3);
        for (int k = 0; k < 3; ++k) {
            out[k] = a[k] + t * ab[k];
        }
        return;
    }
    tf_v3_sub(p, c, cp);
    double d5 = tf_v3_dot(ab, cp), d6 = tf_v3_dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) {
        memcpy(out, c, 3 * sizeof *out);
        return;
    }
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        double t = d2 / (d2 - d6);
        for (int k = 0; k < 3; ++k) {
            out[k] = a[k] + t * ac[k];
        }
        return;
    }
    double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        for (int k = 0; k < 3; ++k) {
            out[k] = b[k] + t * (c[k] - b[k]);
        }
        return;
    }
    double den = 1 / (va + vb + vc), v = vb * den, w = vc * den;
    for (int k = 0; k < 3; ++k) {
        out[k] = a[k] + ab[k] * v + ac[k] * w;
    }
}

/* Triangle k's corners, its outward unit normal and area. */
static void triangle(const tf_tetmesh *tm, size_t k, const double *x[3], double nrm[3],
                     double *area)
{
    double e1[3], e2[3];
    for (int i = 0; i < 3; ++i) {
        x[i] = tm->xyz + 3 * tm->tri[3 * k + (size_t)i];
    }
    tf_v3_sub(x[1], x[0], e1);
    tf_v3_sub(x[2], x[0], e2);
    tf_v3_cross(e1, e2, nrm);
    double l = tf_v3_norm(nrm);
    *area = 0.5 * l;
    for (int i = 0; i < 3 && l > 0; ++i) {
        nrm[i] /= l;
    }
}

/* The surface point nearest p and its triangle. */
static size_t nearest_surface_point(const tf_tetmesh *tm, const double p[3], double out[3])
{
    size_t best = 0;
    double d2 = INFINITY;
    for (size_t k = 0; k < tm->ntri; ++k) {
        const double *x[3];
        double y[3], d[3], nrm[3], area;
        triangle(tm, k, x, nrm, &area);
        closest_on_triangle(p, x[0], x[1], x[2], y);
        tf_v3_sub(y, p, d);
        if (tf_v3_dot(d, d) < d2) {
            d2 = tf_v3_dot(d, d);
            best = k;
            memcpy(out, y, 3 * sizeof *out);
        }
    }
    return best;
}

/* Rows e1, e2, n of R from the normal n: e1 the scene's x axis projected
 * onto the plane (y when x lies within 25 degrees of n), e2 = n x e1. */
static void frame_of(const double n[3], double R[9])
{
    double x[3] = {1, 0, 0};
    if (fabs(n[0]) > cos(25 * M_PI / 180)) {
        x[0] = 0;
        x[1] = 1;
    }
    double d = tf_v3_dot(x, n), e1[3], e2[3];
    for (int k = 0; k < 3; ++k) {
        e1[k] = x[k] - d * n[k];
    }
    double l = tf_v3_norm(e1);
    for (int k = 0; k < 3; ++k) {
        e1[k] /= l;
    }
    tf_v3_cross(n, e1, e2);
    memcpy(R, e1, sizeof e1);
    memcpy(R + 3, e2, sizeof e2);
    memcpy(R + 6, n, 3 * sizeof *n);
}

/* Keeps the triangles whose projection's bounding box meets the domain
 * widened by w, with their corners in chart coordinates. */
static int collect(const tf_tetmesh *tm, tf_region_chart *c, const double w[2], double tol)
{
    tf_region_chart_free(c);
    size_t n = 0;
    c->tri = malloc((3 * tm->ntri + 1) * sizeof *c->tri);
    c->q = malloc((9 * tm->ntri + 1) * sizeof *c->q);
    c->graph = calloc(tm->ntri + 1, 1);
    if (!c->tri || !c->q || !c->graph) {
        return -1;
    }
    for (size_t k = 0; k < tm->ntri; ++k) {
        double q[9], lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (int i = 0; i < 3; ++i) {
            tf_region_chart_coords(c, tm->xyz + 3 * tm->tri[3 * k + (size_t)i], q + 3 * i);
            for (int a = 0; a < 2; ++a) {
                lo[a] = fmin(lo[a], q[3 * i + a]);
                hi[a] = fmax(hi[a], q[3 * i + a]);
            }
        }
        if (hi[0] < -w[0] - tol || lo[0] > c->len[0] + w[0] + tol || hi[1] < -w[1] - tol ||
            lo[1] > c->len[1] + w[1] + tol) {
            continue;
        }
        for (int i = 0; i < 3; ++i) {
            c->tri[3 * n + (size_t)i] = (uint32_t)tm->tri[3 * k + (size_t)i];
        }
        memcpy(c->q + 9 * n, q, sizeof q);
        n++;
    }
    c->n_tri = n;
    return 0;
}

/* The outermost kept triangle on the line over (a, b): its index (or -1)
 * and the height there. */
static long outermost(const tf_region_chart *c, double a, double b, double *h)
{
    long which = -1;
    double best = -INFINITY;
    for (size_t k = 0; k < c->n_tri; ++k) {
        const double *q = c->q + 9 * k;
        double d = (q[4] - q[7]) * (q[0] - q[6]) + (q[6] - q[3]) * (q[1] - q[7]);
        if (fabs(d) <= 1e-14 * (fabs(q[0] - q[6]) + fabs(q[1] - q[7]) + 1e-300) *
                           (fabs(q[3] - q[6]) + fabs(q[4] - q[7]))) {
            continue; /* seen edge-on: its neighbours hold the line */
        }
        double l0 = ((q[4] - q[7]) * (a - q[6]) + (q[6] - q[3]) * (b - q[7])) / d;
        double l1 = ((q[7] - q[1]) * (a - q[6]) + (q[0] - q[6]) * (b - q[7])) / d;
        double l2 = 1 - l0 - l1, eps = 1e-10;
        if (l0 >= -eps && l1 >= -eps && l2 >= -eps) {
            double t = l0 * q[2] + l1 * q[5] + l2 * q[8];
            if (t > best) {
                best = t;
                which = (long)k;
            }
        }
    }
    *h = best;
    return which;
}

int tf_region_chart_height(const tf_region_chart *c, double a, double b, double *h)
{
    if (c->flat) {
        *h = 0;
        return 0;
    }
    return outermost(c, a, b, h) >= 0 ? 0 : -1;
}

/* The c component of kept triangle k's unit normal, its centroid (chart)
 * and its area. */
static double chart_normal(const tf_region_chart *c, size_t k, double centroid[3], double *area)
{
    const double *q = c->q + 9 * k;
    double e1[3], e2[3], m[3];
    tf_v3_sub(q + 3, q, e1);
    tf_v3_sub(q + 6, q, e2);
    tf_v3_cross(e1, e2, m);
    double l = tf_v3_norm(m);
    for (int i = 0; i < 3; ++i) {
        centroid[i] = (q[i] + q[3 + i] + q[6 + i]) / 3;
    }
    *area = 0.5 * l;
    return l > 0 ? m[2] / l : 0;
}

/* Marks the graph: kept triangles facing out that are the outermost
 * surface at their centroid's line. */
static void mark_graph(tf_region_chart *c, double tol)
{
    for (size_t k = 0; k < c->n_tri; ++k) {
        double m[3], area, h;
        c->graph[k] = 0;
        if (chart_normal(c, k, m, &area) <= 0) {
            continue;
        }
        long w = outermost(c, m[0], m[1], &h);
        c->graph[k] = w == (long)k || (w >= 0 && fabs(h - m[2]) <= tol);
    }
}

/* The part of triangle t (3 corners (a, b)) inside the domain's rectangle
 * [0, len0] x [0, len1] (clipped by its four sides): its area and
 * centroid.  Returns the area. */
static double clipped_area(const double t[6], const double len[2], double centroid[2])
{
    double poly[2][14];
    int n = 3, cur = 0;
    memcpy(poly[0], t, 6 * sizeof *t);
    for (int side = 0; side < 4 && n > 0; ++side) {
        int ax = side / 2;
        double lim = side % 2 ? len[ax] : 0, sgn = side % 2 ? -1 : 1; /* keep sgn (x - lim) >= 0 */
        const double *p = poly[cur];
        double *o = poly[1 - cur];
        int m = 0;
        for (int i = 0; i < n; ++i) {
            const double *c = p + 2 * i, *d = p + 2 * ((i + 1) % n);
            double dc = sgn * (c[ax] - lim), dd = sgn * (d[ax] - lim);
            if (dc >= 0) {
                o[2 * m] = c[0];
                o[2 * m + 1] = c[1];
                m++;
            }
            if ((dc >= 0) != (dd >= 0)) {
                double f = dc / (dc - dd);
                o[2 * m] = c[0] + f * (d[0] - c[0]);
                o[2 * m + 1] = c[1] + f * (d[1] - c[1]);
                m++;
            }
        }
        n = m;
        cur = 1 - cur;
    }
    double area = 0, ca = 0, cb = 0;
    const double *p = poly[cur];
    for (int i = 0; i < n; ++i) {
        const double *c = p + 2 * i, *d = p + 2 * ((i + 1) % n);
        double cr = c[0] * d[1] - d[0] * c[1];
        area += cr;
        ca += (c[0] + d[0]) * cr;
        cb += (c[1] + d[1]) * cr;
    }
    area *= 0.5;
    centroid[0] = area != 0 ? ca / (6 * area) : 0;
    centroid[1] = area != 0 ? cb / (6 * area) : 0;
    return fabs(area);
}

/* The outward normal (scene frame) and centroid of the graph over the
 * domain: each graph triangle weighted by the area of its part over the
 * domain (its projection clipped to the rectangle, so that the fit moves
 * continuously with the chart).  Returns the area. */
static double fit_plane(const tf_region_chart *c, double n[3], double centre[3])
{
    double total = 0;
    memset(n, 0, 3 * sizeof *n);
    memset(centre, 0, 3 * sizeof *centre);
    for (size_t k = 0; k < c->n_tri; ++k) {
        double m[3], area;
        double nc = chart_normal(c, k, m, &area);
        if (!c->graph[k]) {
            continue;
        }
        const double *q = c->q + 9 * k;
        const double t[6] = {q[0], q[1], q[3], q[4], q[6], q[7]};
        double g[2], part = clipped_area(t, c->len, g);
        if (!(part > 0)) {
            continue;
        }
        double y[3][3], e1[3], e2[3], cr[3], w = part / nc; /* the part's area on the surface */
        for (int i = 0; i < 3; ++i) {
            tf_region_chart_point(c, q + 3 * i, y[i]);
        }
        tf_v3_sub(y[1], y[0], e1);
        tf_v3_sub(y[2], y[0], e2);
        tf_v3_cross(e1, e2, cr);
        double l = tf_v3_norm(cr);
        /* the part's centroid on the triangle: barycentric in its projection */
        double d = (q[4] - q[7]) * (q[0] - q[6]) + (q[6] - q[3]) * (q[1] - q[7]);
        double l0 = ((q[4] - q[7]) * (g[0] - q[6]) + (q[6] - q[3]) * (g[1] - q[7])) / d;
        double l1 = ((q[7] - q[1]) * (g[0] - q[6]) + (q[0] - q[6]) * (g[1] - q[7])) / d;
        for (int i = 0; i < 3; ++i) {
            n[i] += w * cr[i] / l;
            centre[i] += w * (l0 * y[0][i] + l1 * y[1][i] + (1 - l0 - l1) * y[2][i]);
        }
        total += w;
    }
    double l = tf_v3_norm(n);
    for (int i = 0; i < 3 && l > 0; ++i) {
        n[i] /= l;
        centre[i] /= total;
    }
    return total;
}

/* The chart of normal n and plane point pbar around the surface point c0. */
static int organ_frame(const tf_tetmesh *tm, tf_region_chart *c, const double n[3],
                       const double pbar[3], const double c0[3], const double w[2], double tol)
{
    frame_of(n, c->R);
    double d[3], off;
    tf_v3_sub(c0, pbar, d);
    off = tf_v3_dot(d, n);
    for (int i = 0; i < 3; ++i) {
        c->o[i] = c0[i] - off * n[i] - 0.5 * c->len[0] * c->R[i] - 0.5 * c->len[1] * c->R[3 + i];
    }
    if (collect(tm, c, w, tol) != 0) {
        return -1;
    }
    mark_graph(c, tol);
    return 0;
}

/* Every line over the widened domain meets the surface, and the outermost
 * triangle there is tilted at most TF_REGION_MAX_TILT_DEG from n. */
static int check_graph(tf_ctx *ctx, const tf_region_chart *c, const double w[2])
{
    double lo[2] = {-w[0], -w[1]}, hi[2] = {c->len[0] + w[0], c->len[1] + w[1]};
    double step = fmin(c->len[0], c->len[1]) / 32;
    if (w[0] > 0) {
        step = fmin(step, 0.5 * fmin(w[0], w[1]));
    }
    unsigned na = (unsigned)ceil((hi[0] - lo[0]) / step) + 1;
    unsigned nb = (unsigned)ceil((hi[1] - lo[1]) / step) + 1;
    double cmax = cos(TF_REGION_MAX_TILT_DEG * M_PI / 180);
    for (unsigned j = 0; j < nb; ++j) {
        for (unsigned i = 0; i < na; ++i) {
            double q[3] = {lo[0] + (hi[0] - lo[0]) * i / (na - 1),
                           lo[1] + (hi[1] - lo[1]) * j / (nb - 1), 0},
                   x[3], m[3], area;
            long k = outermost(c, q[0], q[1], &q[2]);
            if (k < 0) {
                q[2] = 0;
                tf_region_chart_point(c, q, x);
                return tf_fail(ctx, "the region is not a graph over its plane: the line through "
                                    "chart point (%.3g, %.3g) mm, scene (%.4g, %.4g, %.4g) mm, "
                                    "meets no surface (a smaller region, or another centre)",
                               q[0], q[1], x[0], x[1], x[2]);
            }
            double nc = chart_normal(c, (size_t)k, m, &area);
            if (nc < cmax) {
                tf_region_chart_point(c, m, x);
                return tf_fail(ctx, "the region is not a graph over its plane: the surface at "
                                    "(%.4g, %.4g, %.4g) mm (chart point (%.3g, %.3g) mm) faces "
                                    "%.1f degrees away from the region's normal (%.4g, %.4g, "
                                    "%.4g), more than %g (a smaller region, or another centre)",
                               x[0], x[1], x[2], q[0], q[1], acos(fmax(-1, fmin(1, nc))) * 180 / M_PI,
                               c->R[6], c->R[7], c->R[8], TF_REGION_MAX_TILT_DEG);
            }
        }
    }
    return 0;
}

static int organ_chart(tf_ctx *ctx, const tf_problem *p, tf_contact_region *r)
{
    const tf_mesh_geometry *mg = tf_problem_mesh(p);
    if (mg == NULL) {
        return tf_fail(ctx, "a region given by centre lies on an organ (geometry.surface); on a "
                            "box give face and rect");
    }
    const tf_tetmesh *tm = &mg->tm;
    tf_region_chart *c = &r->chart;
    double w[2], c0[3], n[3], pbar[3], area;
    tf_region_tip_extent(r, w);
    c->len[0] = r->size[0];
    c->len[1] = r->size[1];
    c->flat = 0;
    double lo[3], hi[3];
    tf_problem_bounds(p, lo, hi);
    double diag = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                       (hi[2] - lo[2]) * (hi[2] - lo[2]));
    double tol = 1e-9 * diag;
    const double *x[3];
    triangle(tm, nearest_surface_point(tm, r->centre, c0), x, n, &area);
    memcpy(pbar, c0, sizeof pbar);
    /* Fixed point: the normal and centroid of the graph over the domain of
     * the chart they make.  The plain iteration overshoots on a strongly
     * curved region (a strip across a sphere alternates between two tilts
     * for ever), so after the first step each step goes half-way. */
    for (int it = 0; it < 200; ++it) {
        double n2[3], p2[3], d[3], f = it == 0 ? 1 : 0.5;
        if (organ_frame(tm, c, n, pbar, c0, w, tol) != 0) {
            return tf_fail(ctx, "out of memory");
        }
        if (fit_plane(c, n2, p2) <= 0) {
            return tf_fail(ctx, "no surface triangle faces outward over the region");
        }
        tf_v3_sub(p2, pbar, d);
        int settled = tf_v3_dot(n, n2) > 1 - 1e-13 && fabs(tf_v3_dot(d, n2)) <= tol;
        for (int i = 0; i < 3; ++i) {
            n[i] += f * (n2[i] - n[i]);
            pbar[i] += f * (p2[i] - pbar[i]);
        }
        double l = tf_v3_norm(n);
        for (int i = 0; i < 3; ++i) {
            n[i] /= l;
        }
        if (settled) {
            break;
        }
    }
    if (organ_frame(tm, c, n, pbar, c0, w, tol) != 0) {
        return tf_fail(ctx, "out of memory");
    }
    return check_graph(ctx, c, w);
}

int tf_region_chart_build(tf_ctx *ctx, const tf_problem *p, tf_contact_region *r)
{
    switch (r->kind) {
    case TF_CONTACT_REGION_FACE:
        return face_chart(ctx, p, r);
    case TF_CONTACT_REGION_ORGAN: {
        int rc = organ_chart(ctx, p, r);
        if (rc != 0) {
            tf_region_chart_free(&r->chart);
        }
        return rc;
    }
    case TF_CONTACT_REGION_NONE:
        break;
    }
    return tf_fail(ctx, "not a contact region");
}
