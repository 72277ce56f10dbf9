/*
 * cut.c — cut panels, side and distance functions, visibility and the
 * weight enrichment of seed 001 §4 (cut.h).
 */
#include "meshfree/cut.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int tf_cut_set_build(tf_ctx *ctx, tf_cut_set *set, const tf_cut *cuts, size_t n)
{
    size_t total = 0;
    set->panel = NULL;
    set->n = 0;
    set->where = NULL;
    set->n_cuts = 0;
    for (size_t c = 0; c < n; ++c) {
        if (cuts[c].n < 2 || cuts[c].n > TF_CUT_MAX_POINTS || !(cuts[c].depth > 0)) {
            return tf_fail(ctx, "cut %zu: needs 2 to %d points and a positive depth", c + 1,
                           TF_CUT_MAX_POINTS);
        }
        total += cuts[c].n - 1;
    }
    if (total == 0) {
        return 0;
    }
    set->panel = calloc(total, sizeof *set->panel);
    set->where = calloc(n, sizeof *set->where);
    if (set->panel == NULL || set->where == NULL) {
        tf_cut_set_free(set);
        return tf_fail(ctx, "out of memory for %zu cut panels", total);
    }
    set->n_cuts = n;
    for (size_t c = 0; c < n; ++c) {
        const tf_cut *k = &cuts[c];
        snprintf(set->where[c], sizeof set->where[c], "%s", k->where);
        for (size_t i = 0; i + 1 < k->n; ++i) {
            tf_cut_panel *p = &set->panel[set->n];
            double dx = k->xy[i + 1][0] - k->xy[i][0], dy = k->xy[i + 1][1] - k->xy[i][1];
            p->len = hypot(dx, dy);
            if (!(p->len > 0)) {
                tf_fail(ctx, "cut %zu: segment %zu has zero length", c + 1, i + 1);
                tf_cut_set_free(set);
                return -1;
            }
            p->a[0] = k->xy[i][0];
            p->a[1] = k->xy[i][1];
            p->a[2] = k->top;
            p->t[0] = dx / p->len;
            p->t[1] = dy / p->len;
            p->t[2] = 0;
            p->n[0] = p->t[1]; /* t x e_z */
            p->n[1] = -p->t[0];
            p->n[2] = 0;
            p->zlo = k->top - k->depth;
            p->zhi = k->top;
            p->cut = c;
            set->n++;
        }
    }
    return 0;
}

void tf_cut_set_free(tf_cut_set *set)
{
    free(set->panel);
    free(set->where);
    set->panel = NULL;
    set->where = NULL;
    set->n = 0;
    set->n_cuts = 0;
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double tf_cut_side(const tf_cut_panel *p, const double x[3])
{
    double r[3] = {x[0] - p->a[0], x[1] - p->a[1], x[2] - p->a[2]};
    return dot3(p->n, r);
}

/* Local coordinates: s, and the positive parts of the in-plane signed
 * distances d_f, d_g (eq 30) with the signs of f - L/2 and z - mid. */
typedef struct local {
    double s, df, dg, sf, sg;
} local;

static local to_local(const tf_cut_panel *p, const double x[3])
{
    double r[3] = {x[0] - p->a[0], x[1] - p->a[1], x[2] - p->a[2]};
    double f = dot3(p->t, r) - 0.5 * p->len, z = x[2] - 0.5 * (p->zlo + p->zhi);
    double df = fabs(f) - 0.5 * p->len, dg = fabs(z) - 0.5 * (p->zhi - p->zlo);
    local l = {dot3(p->n, r), 0.5 * (df + fabs(df)), 0.5 * (dg + fabs(dg)), f < 0 ? -1 : 1,
               z < 0 ? -1 : 1};
    return l;
}

double tf_cut_distance(const tf_cut_panel *p, const double x[3])
{
    local l = to_local(p, x);
    return sqrt(l.df * l.df + l.dg * l.dg + l.s * l.s); /* eq 29 */
}

double tf_cut_h(const tf_cut_panel *p, const double x[3], double grad[3])
{
    local l = to_local(p, x);
    double q = l.df * l.df + l.dg * l.dg, d = sqrt(q + l.s * l.s);
    if (grad) {
        grad[0] = grad[1] = grad[2] = 0;
    }
    if (!(d > 0)) {
        return 1; /* on the panel: the "+" side by convention */
    }
    double phi = l.s / d; /* eq 31: d d / d s */
    if (grad && q > 0) {  /* zero inside the span, where phi = sign(s) */
        double d3 = d * d * d, cs = q / d3, cf = -l.s * l.df * l.sf / d3,
               cg = -l.s * l.dg * l.sg / d3;
        for (int a = 0; a < 3; ++a) {
            grad[a] = 0.5 * (cs * p->n[a] + cf * p->t[a] + (a == 2 ? cg : 0));
        }
    }
    return 0.5 * (phi + 1); /* eq 32 */
}

static int crosses(const tf_cut_panel *p, const double a[3], const double b[3])
{
    double sa = tf_cut_side(p, a), sb = tf_cut_side(p, b);
    if ((sa >= 0) == (sb >= 0)) {
        return 0;
    }
    double u = sa / (sa - sb), x[3];
    for (int k = 0; k < 3; ++k) {
        x[k] = a[k] + u * (b[k] - a[k]);
    }
    double r[3] = {x[0] - p->a[0], x[1] - p->a[1], x[2] - p->a[2]}, f = dot3(p->t, r);
    return f >= 0 && f <= p->len && x[2] >= p->zlo && x[2] <= p->zhi;
}

int tf_cut_visible(const tf_cut_set *set, const double a[3], const double b[3])
{
    for (size_t k = 0; k < set->n; ++k) {
        if (crosses(&set->panel[k], a, b)) {
            return 0;
        }
    }
    return 1;
}

int tf_cut_blocks(const tf_cut_set *set, size_t cut, const double a[3], const double b[3])
{
    for (size_t k = 0; k < set->n; ++k) {
        if (set->panel[k].cut == cut && crosses(&set->panel[k], a, b)) {
            return 1;
        }
    }
    return 0;
}

size_t tf_cut_hiding(const tf_cut_set *set, const double *xyz, const uint32_t *idx, size_t n,
                     const double x[3], size_t *hidden)
{
    size_t best = SIZE_MAX, most = 0;
    for (size_t c = 0; c < set->n_cuts; ++c) {
        size_t count = 0;
        for (size_t i = 0; i < n; ++i) {
            count += (size_t)tf_cut_blocks(set, c, xyz + 3 * (size_t)idx[i], x);
        }
        if (count > most) {
            most = count;
            best = c;
        }
    }
    if (hidden) {
        *hidden = most;
    }
    return best;
}

double tf_cut_enrich(const tf_cut_set *set, const double xi[3], const double x[3],
                     double grad[3])
{
    double e = 1, g[3] = {0, 0, 0};
    for (size_t k = 0; k < set->n; ++k) {
        double dh[3], hi = tf_cut_h(&set->panel[k], xi, NULL);
        double h = tf_cut_h(&set->panel[k], x, dh);
        double ek = h * hi + (1 - h) * (1 - hi);
        for (int a = 0; a < 3; ++a) { /* product rule */
            g[a] = g[a] * ek + e * (2 * hi - 1) * dh[a];
        }
        e *= ek;
    }
    if (grad) {
        grad[0] = g[0];
        grad[1] = g[1];
        grad[2] = g[2];
    }
    return e;
}

int tf_cut_on_panel(const tf_cut_set *set, const double x[3], double tol)
{
    for (size_t k = 0; k < set->n; ++k) {
        const tf_cut_panel *p = &set->panel[k];
        double r[3] = {x[0] - p->a[0], x[1] - p->a[1], x[2] - p->a[2]}, f = dot3(p->t, r);
        if (fabs(dot3(p->n, r)) <= tol && f >= -tol && f <= p->len + tol && x[2] >= p->zlo - tol &&
            x[2] <= p->zhi + tol) {
            return 1;
        }
    }
    return 0;
}

/* Liang-Barsky: does the horizontal segment of p meet [lo, hi] in x, y? */
static int segment_meets_rect(const tf_cut_panel *p, const double lo[3], const double hi[3])
{
    double u0 = 0, u1 = 1;
    for (int a = 0; a < 2; ++a) {
        double d = p->t[a] * p->len;
        if (d == 0) {
            if (p->a[a] < lo[a] || p->a[a] > hi[a]) {
                return 0;
            }
            continue;
        }
        double ua = (lo[a] - p->a[a]) / d, ub = (hi[a] - p->a[a]) / d;
        u0 = fmax(u0, fmin(ua, ub));
        u1 = fmin(u1, fmax(ua, ub));
    }
    return u0 <= u1;
}

int tf_cut_meets_box(const tf_cut_set *set, const double lo[3], const double hi[3])
{
    for (size_t k = 0; k < set->n; ++k) {
        const tf_cut_panel *p = &set->panel[k];
        if (p->zhi >= lo[2] && p->zlo <= hi[2] && segment_meets_rect(p, lo, hi)) {
            return 1;
        }
    }
    return 0;
}

double tf_cut_set_distance(const tf_cut_set *set, const double x[3])
{
    double d = INFINITY;
    for (size_t k = 0; k < set->n; ++k) {
        d = fmin(d, tf_cut_distance(&set->panel[k], x));
    }
    return d;
}

void tf_cut_truncate(const tf_cut *c, double s, tf_cut *out)
{
    double total = 0;
    for (size_t i = 1; i < c->n; ++i) {
        total += hypot(c->xy[i][0] - c->xy[i - 1][0], c->xy[i][1] - c->xy[i - 1][1]);
    }
    *out = *c;
    out->n = 0;
    double want = s * total;
    if (!(want > 1e-9)) {
        return;
    }
    out->xy[0][0] = c->xy[0][0];
    out->xy[0][1] = c->xy[0][1];
    out->n = 1;
    for (size_t i = 1; i < c->n && want > 1e-9; ++i) {
        double dx = c->xy[i][0] - c->xy[i - 1][0], dy = c->xy[i][1] - c->xy[i - 1][1];
        double len = hypot(dx, dy), t = want >= len ? 1.0 : want / len;
        out->xy[out->n][0] = c->xy[i - 1][0] + t * dx;
        out->xy[out->n][1] = c->xy[i - 1][1] + t * dy;
        out->n++;
        want -= len;
    }
}
