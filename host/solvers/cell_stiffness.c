/*
 * cell_stiffness.c — one background cell's stiffness (cell_stiffness.h;
 * seed eq 19).
 */
#include "solvers/cell_stiffness.h"

#include <cblas.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int tf_cell_work_init(tf_cell_work *w, const tf_shape *sh, size_t n_nodes, size_t cap, int vci)
{
    size_t np = tf_cells_points(&sh->cells);
    memset(w, 0, sizeof *w);
    tf_shape_work_init(&w->sw);
    w->cap = cap;
    w->vci = vci;
    w->loc = malloc((cap + 1) * sizeof *w->loc);
    if (w->loc == NULL || (vci && (tf_grad_work_init(&w->gw, sh, n_nodes) != 0 ||
                                   (w->g = malloc(3 * np * cap * sizeof *w->g)) == NULL))) {
        tf_cell_work_free(w);
        return -1;
    }
    w->map = malloc(n_nodes * sizeof *w->map);
    w->x = malloc(3 * np * sizeof *w->x);
    w->w = malloc(np * sizeof *w->w);
    w->y = malloc(3 * (np + 1) * cap * sizeof *w->y);
    w->c = malloc(9 * cap * cap * sizeof *w->c);
    w->pl = malloc(np * sizeof *w->pl);
    w->wm = malloc(np * sizeof *w->wm);
    if (!w->map || !w->x || !w->w || !w->y || !w->c || !w->pl || !w->wm) {
        tf_cell_work_free(w);
        return -1;
    }
    for (size_t i = 0; i < n_nodes; ++i) {
        w->map[i] = -1;
    }
    return 0;
}

void tf_cell_work_free(tf_cell_work *w)
{
    tf_shape_work_free(&w->sw);
    if (w->vci) {
        tf_grad_work_free(&w->gw);
    }
    free(w->g);
    free(w->loc);
    w->g = NULL;
    w->loc = NULL;
    free(w->map);
    free(w->x);
    free(w->w);
    free(w->y);
    free(w->c);
    free(w->pl);
    free(w->wm);
    w->map = NULL;
    w->pl = NULL;
    w->x = w->w = w->y = w->c = w->wm = NULL;
}

/* Adds w B^T D B of one point (gradients d[a n + i] of the support nodes
 * idx[0..n), local indices through map) to the cell matrix (seed eq 19). */
static void add_point(const tf_lame *l, double w, const double *d, const uint32_t *idx, size_t n,
                      const int *map, size_t dim, double *kc)
{
    for (size_t ib = 0; ib < n; ++ib) {
        size_t lb = (size_t)map[idx[ib]];
        const double gb[3] = {d[ib], d[n + ib], d[2 * n + ib]};
        for (size_t ia = ib; ia < n; ++ia) {
            size_t la = (size_t)map[idx[ia]];
            const double ga[3] = {d[ia], d[n + ia], d[2 * n + ia]};
            double k9[9] = {0};
            tf_stiffness_block(l, w, ga, gb, k9);
            for (int j = 0; j < 3; ++j) {
                double *col = kc + dim * (3 * lb + (size_t)j) + 3 * la;
                col[0] += k9[j];
                col[1] += k9[3 + j];
                col[2] += k9[6 + j];
            }
        }
    }
}

/* B-bar (Hughes 1980): the volumetric part lambda (div u)(div v) with div
 * averaged over the cell, lambda / V s s^T with s_(a,i) = sum_g w_g
 * d phi_i / d x_a over the cell's m nodes (s[a m + i], local order). */
static void add_volumetric(double lambda, double vol, const double *sv, size_t m, double *kc)
{
    size_t dim = 3 * m;
    for (size_t lb = 0; lb < m; ++lb) {
        for (size_t la = lb; la < m; ++la) {
            for (size_t b = 0; b < 3; ++b) {
                double f = lambda / vol * sv[b * m + lb];
                double *col = kc + dim * (3 * lb + b) + 3 * la;
                for (size_t a = 0; a < 3; ++a) {
                    col[a] += f * sv[a * m + la];
                }
            }
        }
    }
}

/* Whether a field gives the points of a cell (x, np of them) materials
 * other than the first's: their materials into pl either way. */
static int mixed(const tf_lame_field *field, const double *x, size_t np, tf_lame *pl)
{
    int varies = 0;
    for (size_t p = 0; p < np; ++p) {
        pl[p] = field->at(field->data, x + 3 * p);
        varies |= pl[p].lambda != pl[0].lambda || pl[p].mu != pl[0].mu;
    }
    return varies;
}

/* Point-centred supports (the seed): one local system per Gauss point.
 * With a field, each point's material; the B-bar term then takes the
 * weighted mean of lambda over the cell's points when they differ. */
static int cell_matrix_points(const tf_shape *sh, const tf_lame *l, const tf_lame_field *field,
                              int bbar, tf_cell_work *wk, size_t cell, size_t m, double *kc)
{
    const size_t np = tf_cells_points(&sh->cells);
    tf_lame cl = *l;
    int varies = 0;
    if (field != NULL) {
        for (size_t p = 0; p < np; ++p) {
            tf_cells_point(&sh->cells, cell, p, wk->x + 3 * p, wk->w + p);
        }
        varies = mixed(field, wk->x, np, wk->pl);
        cl = wk->pl[0];
    }
    tf_lame shear = {bbar ? 0 : cl.lambda, cl.mu};
    double vol = 0, lam_w = 0, *sv = wk->y; /* 3 m sums, when bbar */
    memset(sv, 0, 3 * m * sizeof *sv);
    for (size_t p = 0; p < np; ++p) {
        double x[3], w, t0 = omp_get_wtime();
        tf_cells_point(&sh->cells, cell, p, x, &w);
        int rc = tf_shape_at(sh, &wk->sw, x, cell, 1);
        wk->t_shape += omp_get_wtime() - t0;
        if (rc != 0) {
            return -1;
        }
        if (varies) {
            shear = (tf_lame){bbar ? 0 : wk->pl[p].lambda, wk->pl[p].mu};
            lam_w += w * wk->pl[p].lambda;
        }
        add_point(&shear, w, wk->sw.dphi, wk->sw.idx, wk->sw.n, wk->map, 3 * m, kc);
        vol += w;
        for (size_t i = 0; i < wk->sw.n; ++i) {
            size_t li = (size_t)wk->map[wk->sw.idx[i]];
            for (size_t a = 0; a < 3; ++a) {
                sv[a * m + li] += w * wk->sw.dphi[a * wk->sw.n + i];
            }
        }
    }
    if (bbar) {
        add_volumetric(varies ? lam_w / vol : cl.lambda, vol, sv, m, kc);
    }
    return 0;
}

/* The cell matrix from gradients shared by all np points of a cell:
 * dphi[(3 p + a) n + k] of n nodes at local indices loc[k], weights w.
 * With Y[g, a n + i] = sqrt(w_g) d phi_i / d x_a at point g, all sums
 * M^ab_ij = sum_g w_g d_a phi_i d_b phi_j come from one C = Y^T Y (BLAS
 * dsyrk), and the Lame form gives
 * K_(3i+a)(3j+b) = lambda M^ab_ij + mu M^ba_ij + mu delta_ab sum_c M^cc_ij.
 * The B-bar sums go in local order, which is the nodes' order here. */
static void cell_matrix_shared(const tf_lame *l, int bbar, tf_cell_work *wk, const double *dphi,
                               size_t n, const size_t *loc, const double *wts, size_t np,
                               size_t dim, double *kc)
{
    size_t n3 = 3 * n;
    double *y = wk->y, *c = wk->c;
    for (size_t p = 0; p < np; ++p) {
        double sw = sqrt(wts[p]);
        const double *d = dphi + 3 * p * n;
        for (size_t q = 0; q < n3; ++q) {
            y[p + np * q] = sw * d[q];
        }
    }
    cblas_dsyrk(CblasColMajor, CblasLower, CblasTrans, (int)n3, (int)np, 1.0, y, (int)np, 0.0, c,
                (int)n3);
    double lambda = bbar ? 0 : l->lambda, vol = 0, *sv = y; /* y is free again */
    if (bbar) {
        memset(sv, 0, n3 * sizeof *sv);
        for (size_t p = 0; p < np; ++p) {
            vol += wts[p];
            for (size_t q = 0; q < n3; ++q) {
                sv[q] += wts[p] * dphi[3 * p * n + q];
            }
        }
    }
#define M(a, i, b, j) c[((a) * n + (i)) >= ((b) * n + (j)) ? ((a) * n + (i)) + n3 * ((b) * n + (j)) \
                                                           : ((b) * n + (j)) + n3 * ((a) * n + (i))]
    for (size_t j = 0; j < n; ++j) {
        size_t lj = loc[j];
        for (size_t i = j; i < n; ++i) {
            size_t li = loc[i];
            double tr = l->mu * (M(0, i, 0, j) + M(1, i, 1, j) + M(2, i, 2, j));
            for (size_t b = 0; b < 3; ++b) {
                double *col = kc + dim * (3 * lj + b) + 3 * li;
                for (size_t a = 0; a < 3; ++a) {
                    col[a] += lambda * M(a, i, b, j) + l->mu * M(b, i, a, j) + (a == b ? tr : 0);
                }
            }
        }
    }
#undef M
    if (bbar) {
        add_volumetric(l->lambda, vol, sv, n, kc); /* local order = the nodes' order */
    }
}

/* Cell-centred supports: every Gauss point of the cell has the same n
 * nodes (the cell's set, in its order). */
static int cell_matrix_cell(const tf_shape *sh, const tf_lame *l, const tf_lame_field *field,
                            int bbar, tf_cell_work *wk, size_t cell, size_t dim, double *kc)
{
    size_t np = tf_cells_points(&sh->cells);
    double t0 = omp_get_wtime();
    for (size_t p = 0; p < np; ++p) {
        tf_cells_point(&sh->cells, cell, p, wk->x + 3 * p, wk->w + p);
    }
    int rc = tf_shape_cell_points(sh, &wk->sw, cell, wk->x, np, 1);
    wk->t_shape += omp_get_wtime() - t0;
    if (rc != 0) {
        return -1;
    }
    size_t n = wk->sw.n;
    for (size_t k = 0; k < n; ++k) {
        wk->loc[k] = (size_t)wk->map[wk->sw.idx[k]];
    }
    if (field == NULL || !mixed(field, wk->x, np, wk->pl)) {
        cell_matrix_shared(field ? &wk->pl[0] : l, bbar, wk, wk->sw.dphi, n, wk->loc, wk->w, np,
                           dim, kc);
        return 0;
    }
    /* an inclusion cuts the cell: each material's points with their own
     * parameters (the other points' weights zero) */
    for (size_t first = 0; first < np; ++first) {
        int seen = 0;
        for (size_t p = 0; p < first && !seen; ++p) {
            seen = wk->pl[p].lambda == wk->pl[first].lambda && wk->pl[p].mu == wk->pl[first].mu;
        }
        if (seen) {
            continue;
        }
        for (size_t p = 0; p < np; ++p) {
            const int same =
                wk->pl[p].lambda == wk->pl[first].lambda && wk->pl[p].mu == wk->pl[first].mu;
            wk->wm[p] = same ? wk->w[p] : 0;
        }
        cell_matrix_shared(&wk->pl[first], bbar, wk, wk->sw.dphi, n, wk->loc, wk->wm, np, dim,
                           kc);
    }
    return 0;
}

/* VCI: corrected gradients over the cell's set (cell_gradients.h). */
static int cell_matrix_vci(const tf_shape *sh, const tf_lame *l, int bbar, tf_cell_work *wk,
                           size_t cell, const uint32_t *set, size_t m, double *kc)
{
    double t0 = wk->gw.t_shape;
    int rc = tf_cell_gradients(sh, 1, &wk->gw, cell, set, m, wk->g);
    wk->t_shape += wk->gw.t_shape - t0;
    if (rc != 0) {
        snprintf(wk->sw.err, sizeof wk->sw.err, "%s", wk->gw.sw.err);
        return -1;
    }
    for (size_t r = 0; r < m; ++r) {
        wk->loc[r] = r;
    }
    /* the gradients are dense over the set at every point (zeros where a
     * node does not support a point), whatever the supports' centre */
    cell_matrix_shared(l, bbar, wk, wk->g, m, wk->loc, wk->gw.w, tf_cells_points(&sh->cells),
                       3 * m, kc);
    return 0;
}

int tf_cell_stiffness(const tf_shape *sh, const tf_lame *l, const tf_lame_field *field, int bbar,
                      tf_cell_work *wk, size_t cell, const uint32_t *set, size_t m, double *kc)
{
    size_t dim = 3 * m;
    memset(kc, 0, dim * dim * sizeof *kc);
    if (wk->vci) {
        if (field != NULL) {
            snprintf(wk->sw.err, sizeof wk->sw.err,
                     "material regions are not integrated with VCI's corrected gradients");
            return -1;
        }
        return cell_matrix_vci(sh, l, bbar, wk, cell, set, m, kc);
    }
    for (size_t r = 0; r < m; ++r) {
        wk->map[set[r]] = (int)r;
    }
    int rc = sh->centre == TF_SUPPORT_CELL
                 ? cell_matrix_cell(sh, l, field, bbar, wk, cell, dim, kc)
                 : cell_matrix_points(sh, l, field, bbar, wk, cell, m, kc);
    for (size_t r = 0; r < m; ++r) {
        wk->map[set[r]] = -1;
    }
    return rc;
}

