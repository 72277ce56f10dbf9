/*
 * surface_prepare.c — read, check, repair and place a surface
 * (surface_prepare.h).
 */
#include "geometry/surface_prepare.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/self_intersect.h"
#include "geometry/surface_edges.h"
#include "geometry/surface_pieces.h"
#include "geometry/surface_read.h"
#include "geometry/surface_vertices.h"

static int out_of_memory(tf_geom_msg *m)
{
    return tf_geom_fail(m, TF_GEOM_FAILED, "out of memory");
}

static const double *at(const tf_surface *s, size_t v)
{
    return s->xyz + 3 * v;
}

/* Every coordinate a finite number (a NaN, or 1e300 read as float32's
 * infinity, was reported as a degenerate triangle). */
static int finite_vertices(const tf_surface *s, tf_geom_msg *m)
{
    for (size_t v = 0; v < s->nv; ++v) {
        const double *x = at(s, v);
        if (!isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2])) {
            return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                                "vertex %ld at (%g, %g, %g): a coordinate is not a finite "
                                "number (the reader holds float32: at most 3.4e38)",
                                s->source[v], x[0], x[1], x[2]);
        }
    }
    return TF_GEOM_OK;
}

/* The ratio of the coordinates' size to the surface's: above about 1e5
 * float32's 24 bits no longer tell neighbouring vertices apart. */
static double offset_ratio(const tf_surface *s)
{
    double lo[3], hi[3], ext = 0, far = 0;
    tf_surface_bbox(s, lo, hi);
    for (int a = 0; a < 3; ++a) {
        ext = fmax(ext, hi[a] - lo[a]);
        far = fmax(far, fmax(fabs(lo[a]), fabs(hi[a])));
    }
    return ext > 0 ? far / ext : INFINITY;
}

static int repeated_vertices(const tf_surface *s, tf_geom_msg *m)
{
    for (size_t t = 0; t < s->nt; ++t) {
        const size_t *v = s->tri + 3 * t;
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) {
            double r = offset_ratio(s);
            return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                                "degenerate triangle %zu: it names vertex %ld twice%s", t,
                                s->source[v[0] == v[1] || v[0] == v[2] ? v[0] : v[1]],
                                r > 1e4 ? " (the coordinates lie far from the origin for the "
                                          "surface's size, and the reader's float32 merges "
                                          "vertices there: move the file's origin into the "
                                          "organ)"
                                        : "");
        }
    }
    return TF_GEOM_OK;
}

static int drop_unused(tf_surface *s, tf_geom_msg *m)
{
    unsigned char *keep = malloc(s->nt + 1);
    if (keep == NULL) {
        return out_of_memory(m);
    }
    memset(keep, 1, s->nt + 1);
    size_t nv = s->nv;
    int rc = tf_surface_select(s, keep);
    free(keep);
    if (rc != 0) {
        return out_of_memory(m);
    }
    if (s->nv < nv) {
        tf_geom_note(m, "dropped %zu vertices that no triangle uses", nv - s->nv);
    }
    return TF_GEOM_OK;
}

static int edge_fault(const tf_surface *s, const tf_edge_fault *f, const char *what,
                      tf_geom_msg *m)
{
    const double *a = at(s, f->v[0]), *b = at(s, f->v[1]);
    char tris[64];
    if (f->tri[0] == f->tri[1]) {
        snprintf(tris, sizeof tris, "triangle %zu", f->tri[0]);
    } else {
        snprintf(tris, sizeof tris, "triangles %zu and %zu", f->tri[0], f->tri[1]);
    }
    return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                        "%s: %zu edge%s; the first joins vertices %ld (%.6g, %.6g, %.6g) and "
                        "%ld (%.6g, %.6g, %.6g), %s",
                        what, f->count, f->count == 1 ? "" : "s", s->source[f->v[0]], a[0],
                        a[1], a[2], s->source[f->v[1]], b[0], b[1], b[2], tris);
}

static int closed_and_wound(const tf_surface *s, tf_geom_msg *m)
{
    tf_edge_report r;
    if (tf_surface_edges(s, &r) != 0) {
        return out_of_memory(m);
    }
    if (r.open.count) {
        return edge_fault(s, &r.open, "open surface (edges of only one triangle)", m);
    }
    if (r.nonmanifold.count) {
        return edge_fault(s, &r.nonmanifold, "non-manifold surface (edges of three or more "
                                             "triangles)", m);
    }
    if (r.flipped.count) {
        return edge_fault(s, &r.flipped, "inconsistent winding (two triangles traverse an "
                                         "edge the same way: one of them is flipped)", m);
    }
    tf_vertex_fault f;
    if (tf_surface_vertex_fans(s, &f) != 0) {
        return out_of_memory(m);
    }
    if (f.count) {
        const double *x = at(s, f.v);
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                            "non-manifold vertex (its triangles form more than one fan: "
                            "surfaces touching at a point): %zu vertex%s; the first, vertex "
                            "%ld at (%.6g, %.6g, %.6g), joins %zu fans; give one closed organ "
                            "surface per file, or separate the surfaces there",
                            f.count, f.count == 1 ? "" : "es", s->source[f.v], x[0], x[1], x[2],
                            f.fans);
    }
    return TF_GEOM_OK;
}

/* Signed volume of every piece (as tf_surface_volume). */
static void piece_volumes(const tf_surface *s, const size_t *piece, double *vol, size_t n)
{
    double o[3];
    tf_surface_centre(s, o);
    for (size_t k = 0; k < n; ++k) {
        vol[k] = 0;
    }
    for (size_t t = 0; t < s->nt; ++t) {
        vol[piece[t]] += tf_surface_cone_volume(s, t, o);
    }
}

static size_t largest(const double *vol, size_t n)
{
    size_t best = 0;
    for (size_t k = 1; k < n; ++k) {
        best = fabs(vol[k]) > fabs(vol[best]) ? k : best;
    }
    return best;
}

/* Keeps the largest piece when every other one is a speck. */
static int keep_largest(tf_surface *s, const size_t *piece, const double *vol, size_t n,
                        tf_geom_msg *m)
{
    size_t big = largest(vol, n), dropped = 0;
    double fraction = 0;
    for (size_t k = 0; k < n; ++k) {
        double f = fabs(vol[k]) / fabs(vol[big]);
        if (k != big && f > TF_SURFACE_SPECK) {
            size_t t = 0;
            while (piece[t] != k) {
                t++;
            }
            return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                                "%zu separate pieces: piece %zu (from triangle %zu) encloses "
                                "%.3g %% of the largest; give one closed organ surface per file",
                                n, k + 1, t, 100 * f);
        }
        fraction += k == big ? 0 : f;
    }
    unsigned char *keep = malloc(s->nt + 1);
    if (keep == NULL) {
        return out_of_memory(m);
    }
    for (size_t t = 0; t < s->nt; ++t) {
        keep[t] = piece[t] == big;
        dropped += !keep[t];
    }
    int rc = tf_surface_select(s, keep);
    free(keep);
    if (rc != 0) {
        return out_of_memory(m);
    }
    tf_geom_note(m, "kept the largest of %zu pieces; dropped %zu triangles enclosing %.2g %% "
                    "of its volume",
                 n, dropped, 100 * fraction);
    return TF_GEOM_OK;
}

static int one_piece(tf_surface *s, tf_geom_msg *m)
{
    size_t *piece = malloc((s->nt + 1) * sizeof *piece), n = 0;
    double *vol = NULL;
    int rc = TF_GEOM_OK;
    if (piece == NULL || tf_surface_pieces(s, piece, &n) != 0 ||
        (vol = malloc((n + 1) * sizeof *vol)) == NULL) {
        rc = out_of_memory(m);
    } else if (n > 1) {
        piece_volumes(s, piece, vol, n);
        rc = keep_largest(s, piece, vol, n, m);
    }
    free(piece);
    free(vol);
    return rc;
}

static int outward(tf_surface *s, tf_geom_msg *m)
{
    double v = tf_surface_volume(s);
    if (!(fabs(v) > 0) || !isfinite(v)) {
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT, "the surface encloses no volume (%g)", v);
    }
    if (v < 0) {
        tf_surface_reverse(s);
        tf_geom_note(m, "the triangles wound inward (enclosed volume %.6g): reversed them", v);
    }
    return TF_GEOM_OK;
}

int tf_surface_clean(tf_surface *s, tf_geom_msg *m)
{
    int rc = finite_vertices(s, m);
    rc = rc ? rc : repeated_vertices(s, m);
    rc = rc ? rc : drop_unused(s, m);
    rc = rc ? rc : closed_and_wound(s, m);
    rc = rc ? rc : one_piece(s, m);
    rc = rc ? rc : outward(s, m);
    return rc;
}

static int units(const tf_surface *s, tf_geom_msg *m)
{
    double lo[3], hi[3], ext = 0;
    tf_surface_bbox(s, lo, hi);
    for (int a = 0; a < 3; ++a) {
        ext = fmax(ext, hi[a] - lo[a]);
    }
    if (ext < TF_SURFACE_MIN_MM || ext > TF_SURFACE_MAX_MM) {
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                            "absurd size: the bounding box is %.4g x %.4g x %.4g mm after "
                            "scaling, %s; is the scale (file units -> mm) right?",
                            hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2],
                            ext < TF_SURFACE_MIN_MM ? "under 1 mm" : "over 1 m");
    }
    return TF_GEOM_OK;
}

int tf_surface_check_placed(const tf_surface *s, tf_geom_msg *m)
{
    int rc = units(s, m);
    if (rc) {
        return rc;
    }
    tf_crossing c;
    if (tf_surface_crossings(s, &c) != 0) {
        return out_of_memory(m);
    }
    if (c.pairs) {
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                            "self-intersecting surface: %zu crossing triangle pair%s; the "
                            "first, triangles %zu and %zu, cross at (%.6g, %.6g, %.6g) mm; the "
                            "volume mesher cannot fill it: repair the surface",
                            c.pairs, c.pairs == 1 ? "" : "s", c.tri[0], c.tri[1], c.at[0],
                            c.at[1], c.at[2]);
    }
    return TF_GEOM_OK;
}

int tf_surface_load(const char *path, const tf_transform *t, tf_surface *s, tf_geom_msg *m)
{
    memset(s, 0, sizeof *s);
    m->error[0] = m->notes[0] = '\0';
    int rc = tf_surface_read(path, s, m);
    rc = rc ? rc : tf_surface_clean(s, m);
    rc = rc ? rc : tf_transform_apply(t, s, m);
    rc = rc ? rc : tf_surface_check_placed(s, m);
    if (rc) {
        tf_surface_free(s);
    }
    return rc;
}
