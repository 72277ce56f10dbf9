/*
 * shape.c — supports and RPIM shape functions at a point (shape.h).
 */
#include "meshfree/shape.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "meshfree/tet_cells.h"

int tf_shape_init(tf_shape *sh, const tf_cloud *cloud, const double lo[3], const double hi[3],
                  const tf_solver_opts *o)
{
    sh->cloud = cloud;
    sh->rpim.shape = o->alpha_c * o->d_c;
    sh->alpha_c = o->alpha_c;
    sh->d_c_spacings = o->d_c_spacings;
    sh->xi = NULL;
    sh->nbr.start = NULL;
    sh->nbr.items = NULL;
    sh->rpim.q = o->q;
    sh->rpim.poly = o->polynomial;
    sh->centre = o->centre;
    sh->rcond_warn = o->rcond_warn;
    sh->support = o->support;
    sh->mls_radius = NULL;
    sh->cuts.panel = NULL;
    sh->cuts.n = 0;
    sh->cuts.where = NULL;
    sh->cuts.n_cuts = 0;
    sh->cut_node = NULL;
    sh->cut_all = 0;
    sh->cell_radius = NULL;
    sh->cell_spacing = NULL;
    sh->scale = 0;
    for (int a = 0; a < 3; ++a) {
        sh->radius[a] = o->support * cloud->spacing[a];
        sh->scale = fmax(sh->scale, sh->radius[a]);
    }
    int rc = cloud->graded ? tf_cells_init_cloud(&sh->cells, cloud, o->cells, o->gauss)
                           : tf_cells_init(&sh->cells, lo, hi, o->cells, o->gauss);
    if (rc != 0) {
        return -1;
    }
    /* Supports are balls of radius alpha_s in index space. */
    const double unit[3] = {o->support, o->support, o->support};
    sh->xi = malloc((3 * cloud->n + 1) * sizeof *sh->xi);
    if (sh->xi == NULL) {
        tf_shape_free(sh);
        return -1;
    }
    for (size_t i = 0; i < cloud->n; ++i) {
        for (int a = 0; a < 3; ++a) {
            sh->xi[3 * i + a] = tf_cloud_to_index(cloud, a, cloud->xyz[3 * i + a]);
        }
    }
    if (tf_nbr_build(&sh->nbr, sh->xi, cloud->n, unit) != 0) {
        tf_shape_free(sh);
        return -1;
    }
    return 0;
}

void tf_shape_free(tf_shape *sh)
{
    tf_nbr_free(&sh->nbr);
    tf_cells_free(&sh->cells);
    free(sh->mls_radius);
    free(sh->cell_radius);
    free(sh->cell_spacing);
    free(sh->xi);
    sh->mls_radius = sh->cell_radius = sh->cell_spacing = sh->xi = NULL;
    tf_cut_set_free(&sh->cuts);
    free(sh->cut_node);
    sh->cut_node = NULL;
}

int tf_shape_use_tets(tf_ctx *ctx, tf_shape *sh, const size_t *tet, size_t ntet, unsigned degree)
{
    if (sh->mls_radius != NULL || sh->cloud->n < TF_LOCAL_K) {
        return tf_fail(ctx, sh->mls_radius ? "EFG shape functions on tetrahedral cells are not "
                                             "supported"
                                           : "fewer nodes than a support needs");
    }
    /* The neighbour grid in mm, as HEAD's organ path and EFG have it: a
     * mesh has no grid lines, and its supports are balls of a radius per
     * cell (query) rather than a ball of alpha_s in index space. */
    tf_nbr_free(&sh->nbr);
    free(sh->xi);
    sh->xi = NULL;
    if (tf_nbr_build(&sh->nbr, sh->cloud->xyz, sh->cloud->n, sh->radius) != 0) {
        return tf_fail(ctx, "out of memory for the neighbour grid of %zu nodes", sh->cloud->n);
    }
    sh->cell_radius = malloc((ntet + 1) * sizeof *sh->cell_radius);
    sh->cell_spacing = malloc((ntet + 1) * sizeof *sh->cell_spacing);
    if (sh->cell_radius == NULL || sh->cell_spacing == NULL ||
        tf_cells_use_tets(&sh->cells, sh->cloud->xyz, tet, ntet, degree) != 0) {
        return tf_fail(ctx, "out of memory for %zu tetrahedral cells (or tet_degree %u)", ntet,
                       degree);
    }
    for (size_t e = 0; e < ntet; ++e) {
        double centre[3], half[3];
        tf_cells_box(&sh->cells, e, centre, half);
        size_t cap = TF_SUPPORT_CAP < sh->cloud->n ? TF_SUPPORT_CAP : sh->cloud->n;
        double h = tf_nbr_kth_distance(&sh->nbr, centre, TF_LOCAL_K);
        double most = tf_nbr_kth_distance(&sh->nbr, centre, cap);
        if (h < 0 || most < 0) {
            return tf_fail(ctx, "out of memory for the local spacing");
        }
        sh->cell_radius[e] = fmin(sh->support * h, most);
        sh->cell_spacing[e] = h;
    }
    return 0;
}

/* EFG: the nodes whose domain of influence meets a panel (the seed's
 * "distance less than the expansion parameter"; the ellipsoid is bounded
 * by the ball of its largest semi-axis, so a few more nodes may be
 * enriched than strictly needed, never fewer). */
static int mark_cut_nodes(tf_ctx *ctx, tf_shape *sh)
{
    const tf_cloud *c = sh->cloud;
    free(sh->cut_node);
    sh->cut_node = NULL;
    if (sh->mls_radius == NULL || sh->cuts.n == 0) {
        return 0;
    }
    sh->cut_node = calloc(c->n, 1);
    if (sh->cut_node == NULL) {
        return tf_fail(ctx, "out of memory for the enriched nodes");
    }
    for (size_t i = 0; i < c->n; ++i) {
        const double *r = sh->mls_radius + 3 * i;
        double reach = fmax(r[0], fmax(r[1], r[2]));
        sh->cut_node[i] = tf_cut_set_distance(&sh->cuts, c->xyz + 3 * i) < reach;
    }
    return 0;
}

int tf_shape_set_cuts(tf_ctx *ctx, tf_shape *sh, const tf_cut *cuts, size_t n)
{
    if (n > 0 && sh->cell_radius != NULL) {
        return tf_fail(ctx, "cuts on an organ's tetrahedral cells are not supported");
    }
    tf_cut_set_free(&sh->cuts);
    if (tf_cut_set_build(ctx, &sh->cuts, cuts, n) != 0) {
        return -1;
    }
    return mark_cut_nodes(ctx, sh);
}

size_t tf_shape_cut_nodes(const tf_shape *sh)
{
    size_t m = 0;
    for (size_t i = 0; sh->cut_node && i < sh->cloud->n; ++i) {
        m += sh->cut_node[i];
    }
    return m;
}

int tf_shape_use_efg(tf_ctx *ctx, tf_shape *sh)
{
    if (sh->cell_radius != NULL) {
        return tf_fail(ctx, "EFG shape functions on tetrahedral cells are not supported");
    }
    const tf_cloud *c = sh->cloud;
    double *rad = malloc(3 * c->n * sizeof *rad), reach[3] = {0, 0, 0}, t = 0;
    if (rad == NULL) {
        return tf_fail(ctx, "out of memory for the radii of influence");
    }
    if (tf_mls_radii(ctx, c->xyz, c->n, c->spacing, sh->support, rad) != 0) {
        free(rad);
        return -1;
    }
    for (size_t i = 0; i < c->n; ++i) {
        for (int a = 0; a < 3; ++a) {
            reach[a] = fmax(reach[a], rad[3 * i + a]);
        }
    }
    /* A node reaching a point of a cell lies within the ellipsoid reach
     * (1 + t) of the cell's centre, t the half-diagonal in reach units. */
    for (int a = 0; sh->centre == TF_SUPPORT_CELL && a < 3; ++a) {
        t += (0.5 * sh->cells.size[a] / reach[a]) * (0.5 * sh->cells.size[a] / reach[a]);
    }
    sh->scale = 0;
    for (int a = 0; a < 3; ++a) {
        sh->scale = fmax(sh->scale, reach[a]);
        reach[a] *= 1 + sqrt(t);
    }
    tf_nbr_free(&sh->nbr);
    free(sh->mls_radius);
    free(sh->xi);
    sh->xi = NULL; /* the EFG neighbour grid is in mm */
    sh->mls_radius = rad;
    if (tf_nbr_build(&sh->nbr, c->xyz, c->n, reach) != 0) {
        return tf_fail(ctx, "out of memory for the EFG neighbour grid");
    }
    return mark_cut_nodes(ctx, sh);
}

void tf_shape_stats_reset(tf_shape_stats *st)
{
    st->systems = st->ill = 0;
    st->min_rcond = INFINITY;
    st->worst_at[0] = st->worst_at[1] = st->worst_at[2] = 0;
    st->min_nodes = SIZE_MAX;
    st->max_nodes = 0;
    st->points = st->cut_points = 0;
}

void tf_shape_work_init(tf_shape_work *w)
{
    w->rw.cap = w->rw.rhs_cap = 0;
    w->rw.xs = w->rw.g = w->rw.rhs = w->rw.work = w->rw.qp = w->rw.pp = w->rw.qwork = NULL;
    w->rw.ipiv = w->rw.iwork = NULL;
    w->mw.cap = 0;
    w->mw.w = w->mw.dw = w->mw.p = NULL;
    w->idx = w->sub = w->pos = NULL;
    w->tmp = NULL;
    w->cut = 0;
    w->phi = w->dphi = NULL;
    w->n = w->cap = w->pcap = 0;
    w->cell = SIZE_MAX;
    w->err[0] = '\0';
    tf_shape_stats_reset(&w->st);
}

void tf_shape_work_free(tf_shape_work *w)
{
    tf_rpim_work_free(&w->rw);
    tf_mls_work_free(&w->mw);
    free(w->idx);
    free(w->sub);
    free(w->pos);
    free(w->tmp);
    free(w->phi);
    free(w->dphi);
    tf_shape_work_init(w);
}

/* Room for supports of need nodes and np points. */
static int grow(tf_shape_work *w, size_t need, size_t np)
{
    size_t cap = need > w->cap ? need + need / 2 + 16 : w->cap;
    size_t pcap = np > w->pcap ? np : w->pcap;
    if (cap != w->cap) {
        tf_rpim_work_free(&w->rw);
        tf_mls_work_free(&w->mw);
        free(w->idx);
        free(w->sub);
        free(w->pos);
        free(w->tmp);
        w->idx = malloc(cap * sizeof *w->idx);
        w->sub = malloc(cap * sizeof *w->sub);
        w->pos = malloc(cap * sizeof *w->pos);
        w->tmp = malloc(4 * cap * sizeof *w->tmp);
        w->cell = SIZE_MAX;
        if (w->idx == NULL || w->sub == NULL || w->pos == NULL || w->tmp == NULL || tf_rpim_work_init(&w->rw, cap) != 0 ||
            tf_mls_work_init(&w->mw, cap) != 0) {
            w->cap = w->pcap = 0;
            snprintf(w->err, sizeof w->err, "out of memory for a support of %zu nodes", need);
            return -1;
        }
    }
    if (cap != w->cap || pcap != w->pcap) {
        free(w->phi);
        free(w->dphi);
        w->phi = malloc(cap * pcap * sizeof *w->phi);
        w->dphi = malloc(3 * cap * pcap * sizeof *w->dphi);
        if (w->phi == NULL || w->dphi == NULL) {
            w->cap = w->pcap = 0;
            snprintf(w->err, sizeof w->err, "out of memory for shape functions");
            return -1;
        }
    }
    w->cap = cap;
    w->pcap = pcap;
    return 0;
}

size_t tf_shape_cell(const tf_shape *sh, const double x[3])
{
    const tf_cells *c = &sh->cells;
    if (c->tet) {
        return tf_cells_locate(c, x);
    }
    size_t ijk[3];
    for (int a = 0; a < 3; ++a) {
        ijk[a] = tf_cells_slab(c, a, x[a]);
    }
    return ijk[0] + c->n[0] * (ijk[1] + (size_t)c->n[1] * ijk[2]);
}

/* Support centre for x: x itself, or the centre of its cell. */
static void support_centre(const tf_shape *sh, const double x[3], size_t cell, double at[3])
{
    if (sh->centre == TF_SUPPORT_CELL) {
        double half[3];
        tf_cells_box(&sh->cells, cell, at, half);
    } else {
        at[0] = x[0];
        at[1] = x[1];
        at[2] = x[2];
    }
}

/* The nodes in the support domain around at: the ellipsoid of the grid's
 * radii, or on tetrahedral cells the ball of the cell's radius. */
static size_t query(const tf_shape *sh, const double at[3], size_t cell, uint32_t *out, size_t cap)
{
    if (sh->cell_radius != NULL) {
        return tf_nbr_query_ball(&sh->nbr, at, sh->cell_radius[cell], out, cap);
    }
    return tf_nbr_query(&sh->nbr, at, out, cap);
}

int tf_shape_support(const tf_shape *sh, tf_shape_work *w, const double x[3], size_t cell)
{
    double at[3], q[3];
    support_centre(sh, x, cell, at);
    for (int a = 0; a < 3; ++a) { /* RPIM on a box queries in index space; EFG and tets in mm */
        q[a] = sh->xi ? tf_cloud_to_index(sh->cloud, a, at[a]) : at[a];
    }
    size_t n = query(sh, q, cell, w->idx, w->cap);
    if (n > w->cap) {
        if (grow(w, n, w->pcap ? w->pcap : 1) != 0) {
            return -1;
        }
        n = query(sh, q, cell, w->idx, w->cap);
    }
    if (sh->mls_radius) { /* EFG: the nodes whose domain reaches x, or the cell */
        double lo[3] = {x[0], x[1], x[2]}, hi[3] = {x[0], x[1], x[2]}, half[3];
        if (sh->centre == TF_SUPPORT_CELL) {
            tf_cells_box(&sh->cells, cell, at, half);
            for (int a = 0; a < 3; ++a) {
                lo[a] = at[a] - half[a];
                hi[a] = at[a] + half[a];
            }
        }
        n = tf_mls_reach(sh->cloud->xyz, sh->mls_radius, w->idx, n, lo, hi);
    }
    w->n = n;
    if (n == 0) {
        snprintf(w->err, sizeof w->err,
                 "no node within the support around (%g, %g, %g) mm: raise solver.support", at[0],
                 at[1], at[2]);
        return -1;
    }
    return 0;
}

static void record(const tf_shape *sh, tf_shape_stats *st, size_t systems, double rcond,
                   const double at[3], size_t n)
{
    st->systems += systems;
    st->ill += rcond < sh->rcond_warn;
    if (rcond < st->min_rcond) {
        st->min_rcond = rcond;
        st->worst_at[0] = at[0];
        st->worst_at[1] = at[1];
        st->worst_at[2] = at[2];
    }
    st->min_nodes = n < st->min_nodes ? n : st->min_nodes;
    st->max_nodes = n > st->max_nodes ? n : st->max_nodes;
}

/* EFG: does a node of the prepared support carry the enrichment? */
static int efg_support_cut(const tf_shape *sh, const tf_shape_work *w)
{
    if (sh->cut_all) {
        return 1;
    }
    for (size_t i = 0; sh->cut_node && i < w->n; ++i) {
        if (sh->cut_node[w->idx[i]]) {
            return 1;
        }
    }
    return 0;
}

/* RPIM: can a segment from a point of the support's domain (x, or the cell)
 * to one of its nodes cross a cut?  Every such segment lies in the box
 * around the support's nodes and the domain, so no panel meeting that box
 * means none crosses. */
static int rpim_support_cut(const tf_shape *sh, const double x[3], size_t cell)
{
    if (sh->cut_all) {
        return 1;
    }
    if (sh->cuts.n == 0) {
        return 0;
    }
    double at[3], half[3] = {0, 0, 0}, lo[3], hi[3];
    support_centre(sh, x, cell, at);
    if (sh->centre == TF_SUPPORT_CELL) {
        tf_cells_box(&sh->cells, cell, at, half);
    }
    for (int a = 0; a < 3; ++a) {
        double r = fmax(half[a], sh->radius[a]);
        lo[a] = at[a] - r;
        hi[a] = at[a] + r;
    }
    return tf_cut_meets_box(&sh->cuts, lo, hi);
}

/* The support's scale s (its largest semi-axis, mm) and the multiquadric's
 * length alpha_c d_c at support centre at: from the local nodal spacing on a
 * graded cloud or with a relative d_c, else the fixed values (the seed's
 * absolute d_c on a uniform grid keeps its bits); on tetrahedral cells the
 * cell's ball and its local spacing (TF_LOCAL_K-th nearest node). */
static void local_scale(const tf_shape *sh, const double at[3], size_t cell, double *s,
                        double *shape)
{
    *s = sh->scale;
    *shape = sh->rpim.shape;
    if (sh->cell_radius != NULL) { /* tetrahedral cells: the cell's ball and local spacing */
        *s = sh->cell_radius[cell];
        if (sh->d_c_spacings > 0) {
            *shape = sh->alpha_c * sh->d_c_spacings * sh->cell_spacing[cell];
        }
        return;
    }
    if (!sh->cloud->graded && !(sh->d_c_spacings > 0)) {
        return;
    }
    double h[3];
    tf_cloud_local_spacing(sh->cloud, at, h);
    *s = 0;
    for (int a = 0; a < 3; ++a) {
        *s = fmax(*s, sh->support * h[a]);
    }
    if (sh->d_c_spacings > 0) {
        *shape = sh->alpha_c * sh->d_c_spacings * cbrt(h[0] * h[1] * h[2]);
    }
}

/* Factorises the support around x (cell mode: of the cell) unless the
 * cell's system is already factorised. */
static int prepare(const tf_shape *sh, tf_shape_work *w, const double x[3], size_t cell)
{
    if (sh->centre == TF_SUPPORT_CELL && w->cell == cell) {
        return 0;
    }
    if (sh->mls_radius) { /* EFG: A(x) belongs to each point (evaluate) */
        w->cell = SIZE_MAX;
        if (tf_shape_support(sh, w, x, cell) != 0) {
            return -1;
        }
        w->cut = efg_support_cut(sh, w);
        w->cell = sh->centre == TF_SUPPORT_CELL ? cell : SIZE_MAX;
        return 0;
    }
    double at[3], rcond, s;
    tf_rpim rp = sh->rpim;
    support_centre(sh, x, cell, at);
    if (tf_shape_support(sh, w, x, cell) != 0) {
        return -1;
    }
    w->cut = rpim_support_cut(sh, x, cell);
    if (w->cut) { /* one system per point (evaluate_cut) */
        w->cell = sh->centre == TF_SUPPORT_CELL ? cell : SIZE_MAX;
        return 0;
    }
    local_scale(sh, at, cell, &s, &rp.shape);
    if (tf_rpim_factor(&rp, &w->rw, sh->cloud->xyz, w->idx, w->n, at, s, &rcond) != 0) {
        snprintf(w->err, sizeof w->err,
                 "the RPIM system of the %zu nodes around (%g, %g, %g) mm is singular to "
                 "machine precision: too few nodes or all in one plane (raise "
                 "solver.support), or a multiquadric too flat for the spacing (lower "
                 "solver.rbf.spacings or d_c)",
                 w->n, at[0], at[1], at[2]);
        w->cell = SIZE_MAX;
        return -1;
    }
    record(sh, &w->st, 1, rcond, at, w->n);
    w->cell = sh->centre == TF_SUPPORT_CELL ? cell : SIZE_MAX;
    return 0;
}

/* A local system singular at x whose support a cut clips: the message
 * names the cut that hides the most of the support's nodes from x (its
 * scene entry) rather than the support.  Returns 1 when it wrote w->err, 0
 * when no cut hides a node of the support. */
static int cut_singular(const tf_shape *sh, tf_shape_work *w, const double x[3],
                        const char *what)
{
    size_t hidden = 0;
    size_t c = tf_cut_hiding(&sh->cuts, sh->cloud->xyz, w->idx, w->n, x, &hidden);
    if (c == SIZE_MAX) {
        return 0;
    }
    const char *where = sh->cuts.where[c];
    char name[TF_CUT_WHERE_MAX + 16];
    if (where[0]) {
        snprintf(name, sizeof name, "%s", where);
    } else {
        snprintf(name, sizeof name, "cut %zu", c + 1);
    }
    snprintf(w->err, sizeof w->err,
             "%s: %s at (%g, %g, %g) mm is singular: this cut hides %zu of the %zu nodes "
             "around the point, and the rest are too few or lie in one plane (a cut closer "
             "to a face or another cut than a node spacing leaves a sliver without nodes: "
             "move or shorten the cut)",
             name, what, x[0], x[1], x[2], hidden, w->n);
    return 1;
}

/* EFG: MLS at the np points of the prepared support. */
static int evaluate_mls(const tf_shape *sh, tf_shape_work *w, const double *x, size_t np,
                        int deriv)
{
    double rcond;
    size_t at;
    if (tf_mls_eval(&w->mw, sh->cloud->xyz, sh->mls_radius, w->idx, w->n, sh->scale, x, np,
                    w->phi, deriv ? w->dphi : NULL, &rcond, &at) != 0) {
        const double *p = x + 3 * at;
        if (!cut_singular(sh, w, p, "the MLS moment matrix")) {
            snprintf(w->err, sizeof w->err,
                     "the MLS moment matrix at (%g, %g, %g) mm is singular to machine "
                     "precision: fewer than four of the %zu nodes around it weigh there, or "
                     "all of them lie in one plane (raise solver.support)",
                     p[0], p[1], p[2], w->n);
        }
        w->cell = SIZE_MAX;
        return -1;
    }
    record(sh, &w->st, np, rcond, x + 3 * at, w->n);
    return 0;
}

/* The enrichment hook of mls.h: ctx is the tf_shape. */
static int enrich_node(const void *ctx, uint32_t node, const double x[3], double *e,
                       double de[3])
{
    const tf_shape *sh = ctx;
    if (sh->cut_node == NULL || !sh->cut_node[node]) {
        return 0;
    }
    *e = tf_cut_enrich(&sh->cuts, sh->cloud->xyz + 3 * (size_t)node, x, de);
    return 1;
}

/* RPIM with a cut: at each point, the system of the support nodes visible
 * from it (the visibility criterion), scattered into the support's layout
 * with phi = 0 for the hidden ones. */
static int evaluate_cut(const tf_shape *sh, tf_shape_work *w, const double *x, size_t np,
                        int deriv)
{
    size_t n = w->n;
    for (size_t p = 0; p < np; ++p) {
        const double *xp = x + 3 * p;
        size_t m = 0;
        double rcond, *phi = w->phi + p * n, *dphi = w->dphi + 3 * p * n;
        for (size_t i = 0; i < n; ++i) {
            if (tf_cut_visible(&sh->cuts, sh->cloud->xyz + 3 * (size_t)w->idx[i], xp)) {
                w->sub[m] = w->idx[i];
                w->pos[m++] = (uint32_t)i;
            }
        }
        double sc;
        tf_rpim rp = sh->rpim;
        local_scale(sh, xp, w->cell, &sc, &rp.shape); /* (grid cells only: set_cuts) */
        if (tf_rpim_factor(&rp, &w->rw, sh->cloud->xyz, w->sub, m, xp, sc, &rcond) != 0) {
            if (!cut_singular(sh, w, xp, "the RPIM system")) {
                snprintf(w->err, sizeof w->err,
                         "the RPIM system of the %zu nodes visible across the cut from (%g, "
                         "%g, %g) mm is singular: too few nodes on that side (raise "
                         "solver.support)",
                         m, xp[0], xp[1], xp[2]);
            }
            return -1;
        }
        record(sh, &w->st, 1, rcond, xp, m);
        if (tf_rpim_eval(&w->rw, xp, 1, w->tmp, deriv ? w->tmp + m : NULL) != 0) {
            snprintf(w->err, sizeof w->err, "out of memory for shape functions");
            return -1;
        }
        for (size_t i = 0; i < n; ++i) {
            phi[i] = 0;
            for (int a = 0; deriv && a < 3; ++a) {
                dphi[a * n + i] = 0;
            }
        }
        for (size_t k = 0; k < m; ++k) {
            phi[w->pos[k]] = w->tmp[k];
            for (int a = 0; deriv && a < 3; ++a) {
                dphi[a * n + w->pos[k]] = w->tmp[(1 + (size_t)a) * m + k];
            }
        }
    }
    return 0;
}

static int evaluate(const tf_shape *sh, tf_shape_work *w, const double *x, size_t np, int deriv)
{
    if (np > w->pcap && grow(w, w->n, np) != 0) {
        return -1;
    }
    w->st.points += np;
    w->st.cut_points += w->cut ? np : 0;
    if (sh->mls_radius) {
        w->mw.enrich = w->cut && sh->cut_node ? enrich_node : NULL;
        w->mw.enrich_ctx = sh;
        return evaluate_mls(sh, w, x, np, deriv);
    }
    if (w->cut) {
        return evaluate_cut(sh, w, x, np, deriv);
    }
    if (tf_rpim_eval(&w->rw, x, np, w->phi, deriv ? w->dphi : NULL) != 0) {
        snprintf(w->err, sizeof w->err, "out of memory for shape functions");
        return -1;
    }
    return 0;
}

int tf_shape_at(const tf_shape *sh, tf_shape_work *w, const double x[3], size_t cell, int deriv)
{
    if (prepare(sh, w, x, cell) != 0) {
        return -1;
    }
    return evaluate(sh, w, x, 1, deriv);
}

int tf_shape_cell_points(const tf_shape *sh, tf_shape_work *w, size_t cell, const double *x,
                         size_t np, int deriv)
{
    if (sh->centre != TF_SUPPORT_CELL || prepare(sh, w, x, cell) != 0) {
        return -1;
    }
    return evaluate(sh, w, x, np, deriv);
}

void tf_shape_stats_merge(tf_shape_stats *into, const tf_shape_stats *from)
{
    into->systems += from->systems;
    into->ill += from->ill;
    int worse = from->min_rcond < into->min_rcond;
    if (from->min_rcond == into->min_rcond) {
        /* Ties go to the lexicographically smallest place: the report does
         * not depend on which thread met it first. */
        for (int a = 0; a < 3; ++a) {
            if (from->worst_at[a] != into->worst_at[a]) {
                worse = from->worst_at[a] < into->worst_at[a];
                break;
            }
        }
    }
    if (worse) {
        into->min_rcond = from->min_rcond;
        for (int a = 0; a < 3; ++a) {
            into->worst_at[a] = from->worst_at[a];
        }
    }
    into->min_nodes = from->min_nodes < into->min_nodes ? from->min_nodes : into->min_nodes;
    into->max_nodes = from->max_nodes > into->max_nodes ? from->max_nodes : into->max_nodes;
    into->points += from->points;
    into->cut_points += from->cut_points;
}
