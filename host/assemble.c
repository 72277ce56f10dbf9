/*
 * assemble.c — sparse stiffness assembly (assemble.h; seed eqs 19-22).
 */
#include "assemble.h"

#include <cblas.h>
#include <limits.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Cells computed in parallel before they are added to K in cell order.  A
 * constant, so the result does not depend on the thread count. */
#define BATCH 32

void tf_csc_free(tf_csc *a)
{
    free(a->p);
    free(a->i);
    free(a->x);
    a->p = a->i = NULL;
    a->x = NULL;
    a->n = a->nnz = 0;
}

void tf_csc_symv(const tf_csc *a, const double *x, double *y, size_t ncol)
{
    for (size_t c = 0; c < ncol; ++c) {
        const double *xc = x + c * a->n;
        double *yc = y + c * a->n;
        memset(yc, 0, a->n * sizeof *yc);
        for (size_t j = 0; j < a->n; ++j) {
            for (int q = a->p[j]; q < a->p[j + 1]; ++q) {
                size_t i = (size_t)a->i[q];
                yc[i] += a->x[q] * xc[j];
                if (i != j) {
                    yc[j] += a->x[q] * xc[i];
                }
            }
        }
    }
}

/* Node sets in compressed rows: set k is nodes[ptr[k] .. ptr[k+1]). */
typedef struct sets {
    size_t count;
    size_t *ptr;
    uint32_t *nodes;
} sets;

static void sets_free(sets *s)
{
    free(s->ptr);
    free(s->nodes);
    s->ptr = NULL;
    s->nodes = NULL;
}

/* Packs count separately allocated lists (freed here) into s. */
static int sets_pack(sets *s, uint32_t **lists, const size_t *len, size_t count)
{
    s->count = count;
    s->ptr = malloc((count + 1) * sizeof *s->ptr);
    s->ptr[0] = 0;
    for (size_t k = 0; s->ptr && k < count; ++k) {
        s->ptr[k + 1] = s->ptr[k] + len[k];
    }
    s->nodes = s->ptr ? malloc((s->ptr[count] + 1) * sizeof *s->nodes) : NULL;
    for (size_t k = 0; k < count; ++k) {
        if (s->nodes && lists[k]) {
            memcpy(s->nodes + s->ptr[k], lists[k], len[k] * sizeof *s->nodes);
        }
        free(lists[k]);
    }
    return s->ptr && s->nodes ? 0 : -1;
}

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* Per-thread scratch. */
typedef struct worker {
    tf_shape_work sw;
    uint32_t *mark; /* node -> stamp */
    int *map;       /* node -> local index in the current cell, or -1 */
    uint32_t *list;
    double *x, *w;  /* Gauss points of a cell and their weights */
    double *y, *c;  /* cell-centred assembly: scaled gradients and Y^T Y */
    double t_shape, t_all;
} worker;

static void workers_free(worker *w, int nt, tf_shape_stats *st);

static worker *workers_new(size_t n_nodes, int nt)
{
    worker *w = calloc((size_t)nt, sizeof *w);
    int ok = w != NULL;
    for (int t = 0; ok && t < nt; ++t) {
        tf_shape_work_init(&w[t].sw);
    }
    for (int t = 0; ok && t < nt; ++t) {
        w[t].mark = calloc(n_nodes, sizeof *w[t].mark);
        w[t].map = malloc(n_nodes * sizeof *w[t].map);
        w[t].list = malloc(n_nodes * sizeof *w[t].list);
        ok = w[t].mark && w[t].map && w[t].list;
        for (size_t i = 0; ok && i < n_nodes; ++i) {
            w[t].map[i] = -1;
        }
    }
    if (!ok) {
        workers_free(w, nt, NULL);
        return NULL;
    }
    return w;
}

/* Stamps restart for a new pass over the nodes. */
static void workers_unmark(worker *w, int nt, size_t n_nodes)
{
    for (int t = 0; t < nt; ++t) {
        memset(w[t].mark, 0, n_nodes * sizeof *w[t].mark);
    }
}

static void workers_free(worker *w, int nt, tf_shape_stats *st)
{
    for (int t = 0; w && t < nt; ++t) {
        if (st) {
            tf_shape_stats_merge(st, &w[t].sw.st);
        }
        tf_shape_work_free(&w[t].sw);
        free(w[t].mark);
        free(w[t].map);
        free(w[t].list);
        free(w[t].x);
        free(w[t].w);
        free(w[t].y);
        free(w[t].c);
    }
    free(w);
}

/* The nodes any support of the cell touches, ascending. */
static int cell_set(const tf_shape *sh, worker *wk, size_t cell, uint32_t **out, size_t *len)
{
    size_t n = 0, np = sh->centre == TF_SUPPORT_CELL ? 1 : tf_cells_points(&sh->cells);
    uint32_t stamp = (uint32_t)cell + 1;
    for (size_t p = 0; p < np; ++p) {
        double x[3], w;
        tf_cells_point(&sh->cells, cell, p, x, &w);
        if (tf_shape_support(sh, &wk->sw, x, cell) != 0) {
            return -1;
        }
        for (size_t k = 0; k < wk->sw.n; ++k) {
            uint32_t a = wk->sw.idx[k];
            if (wk->mark[a] != stamp) {
                wk->mark[a] = stamp;
                wk->list[n++] = a;
            }
        }
    }
    qsort(wk->list, n, sizeof *wk->list, cmp_u32);
    *out = malloc(n * sizeof **out);
    if (*out == NULL) {
        snprintf(wk->sw.err, sizeof wk->sw.err, "out of memory");
        return -1;
    }
    memcpy(*out, wk->list, n * sizeof **out);
    *len = n;
    return 0;
}

static int build_cell_sets(const tf_shape *sh, worker *wks, sets *cs, char *err, size_t errlen)
{
    size_t ncell = tf_cells_count(&sh->cells), failed = SIZE_MAX;
    uint32_t **lists = calloc(ncell, sizeof *lists);
    size_t *len = calloc(ncell, sizeof *len);
    char msg[256] = "";
    if (!lists || !len) {
        free(lists);
        free(len);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
#pragma omp parallel for schedule(dynamic, 4)
    for (size_t c = 0; c < ncell; ++c) {
        worker *wk = &wks[omp_get_thread_num()];
        if (cell_set(sh, wk, c, &lists[c], &len[c]) != 0) {
#pragma omp critical(tf_assemble_fail)
            if (c < failed) {
                failed = c; /* the lowest failing cell, whatever the schedule */
                snprintf(msg, sizeof msg, "%s", wk->sw.err);
            }
        }
    }
    int rc = sets_pack(cs, lists, len, ncell);
    free(lists);
    free(len);
    if (failed != SIZE_MAX || rc != 0) {
        snprintf(err, errlen, "%s", failed != SIZE_MAX ? msg : "out of memory");
        return -1;
    }
    return 0;
}

/* Inverse of the cell sets: the cells touching each node, ascending. */
static int invert(const sets *cs, size_t n_nodes, sets *nc)
{
    nc->count = n_nodes;
    nc->ptr = calloc(n_nodes + 1, sizeof *nc->ptr);
    nc->nodes = malloc((cs->ptr[cs->count] + 1) * sizeof *nc->nodes);
    size_t *fill = malloc((n_nodes + 1) * sizeof *fill);
    if (!nc->ptr || !nc->nodes || !fill) {
        free(fill);
        return -1;
    }
    for (size_t q = 0; q < cs->ptr[cs->count]; ++q) {
        nc->ptr[cs->nodes[q] + 1]++;
    }
    for (size_t i = 0; i < n_nodes; ++i) {
        nc->ptr[i + 1] += nc->ptr[i];
    }
    memcpy(fill, nc->ptr, (n_nodes + 1) * sizeof *fill);
    for (size_t c = 0; c < cs->count; ++c) {
        for (size_t q = cs->ptr[c]; q < cs->ptr[c + 1]; ++q) {
            nc->nodes[fill[cs->nodes[q]]++] = (uint32_t)c;
        }
    }
    free(fill);
    return 0;
}

/* Block pattern: for each node b, the nodes a >= b sharing a cell with it. */
static int block_pattern(const sets *cs, const sets *nc, worker *wks, sets *bp)
{
    size_t n = nc->count;
    uint32_t **lists = calloc(n, sizeof *lists);
    size_t *len = calloc(n, sizeof *len);
    int oom = !lists || !len;
#pragma omp parallel for schedule(dynamic, 64)
    for (size_t b = 0; b < n; ++b) {
        worker *wk = &wks[omp_get_thread_num()];
        size_t m = 0;
        if (oom) {
            continue;
        }
        for (size_t q = nc->ptr[b]; q < nc->ptr[b + 1]; ++q) {
            size_t c = nc->nodes[q];
            for (size_t r = cs->ptr[c]; r < cs->ptr[c + 1]; ++r) {
                uint32_t a = cs->nodes[r];
                if (a >= b && wk->mark[a] != (uint32_t)b + 1) {
                    wk->mark[a] = (uint32_t)b + 1;
                    wk->list[m++] = a;
                }
            }
        }
        qsort(wk->list, m, sizeof *wk->list, cmp_u32);
        lists[b] = malloc(m * sizeof *lists[b]);
        if (lists[b] == NULL) {
            oom = 1;
            continue;
        }
        memcpy(lists[b], wk->list, m * sizeof *lists[b]);
        len[b] = m;
    }
    int rc = oom ? -1 : sets_pack(bp, lists, len, n);
    free(lists);
    free(len);
    return rc;
}

/* Scalar compressed columns from the block pattern: column 3b + j holds
 * rows 3b + j .. 3b + 2, then 3a .. 3a + 2 for each node a > b. */
static int scalar_pattern(const sets *bp, tf_csc *k, char *err, size_t errlen)
{
    size_t nn = bp->count, nnz = 0;
    for (size_t b = 0; b < nn; ++b) {
        nnz += 6 + 9 * (bp->ptr[b + 1] - bp->ptr[b] - 1);
    }
    if (nnz > INT_MAX) {
        snprintf(err, errlen, "the stiffness matrix has %zu entries, more than this build handles",
                 nnz);
        return -1;
    }
    k->n = 3 * nn;
    k->nnz = nnz;
    k->p = malloc((k->n + 1) * sizeof *k->p);
    k->i = malloc(nnz * sizeof *k->i);
    k->x = calloc(nnz, sizeof *k->x);
    if (!k->p || !k->i || !k->x) {
        snprintf(err, errlen, "out of memory for a stiffness matrix of %zu entries", nnz);
        return -1;
    }
    size_t q = 0;
    for (size_t b = 0; b < nn; ++b) {
        for (int j = 0; j < 3; ++j) {
            k->p[3 * b + (size_t)j] = (int)q;
            for (int i = j; i < 3; ++i) {
                k->i[q++] = (int)(3 * b) + i;
            }
            for (size_t r = bp->ptr[b] + 1; r < bp->ptr[b + 1]; ++r) {
                for (int i = 0; i < 3; ++i) {
                    k->i[q++] = (int)(3 * bp->nodes[r]) + i;
                }
            }
        }
    }
    k->p[k->n] = (int)q;
    return 0;
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

/* Point-centred supports (the seed): one local system per Gauss point. */
static int cell_matrix_points(const tf_shape *sh, const tf_lame *l, int bbar, worker *wk,
                              size_t cell, size_t m, double *kc)
{
    tf_lame shear = {bbar ? 0 : l->lambda, l->mu};
    double vol = 0, *sv = wk->y; /* 3 m sums, when bbar */
    memset(sv, 0, 3 * m * sizeof *sv);
    for (size_t p = 0; p < tf_cells_points(&sh->cells); ++p) {
        double x[3], w, t0 = omp_get_wtime();
        tf_cells_point(&sh->cells, cell, p, x, &w);
        int rc = tf_shape_at(sh, &wk->sw, x, cell, 1);
        wk->t_shape += omp_get_wtime() - t0;
        if (rc != 0) {
            return -1;
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
        add_volumetric(l->lambda, vol, sv, m, kc);
    }
    return 0;
}

/* Cell-centred supports: every Gauss point of the cell has the same n
 * nodes, so with Y[g, a n + i] = sqrt(w_g) d phi_i / d x_a at point g, all
 * sums M^ab_ij = sum_g w_g d_a phi_i d_b phi_j come from one C = Y^T Y
 * (BLAS dsyrk), and the Lame form gives
 * K_(3i+a)(3j+b) = lambda M^ab_ij + mu M^ba_ij + mu delta_ab sum_c M^cc_ij. */
static int cell_matrix_cell(const tf_shape *sh, const tf_lame *l, int bbar, worker *wk,
                            size_t cell, size_t dim, double *kc)
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
    size_t n = wk->sw.n, n3 = 3 * n;
    double *y = wk->y, *c = wk->c;
    for (size_t p = 0; p < np; ++p) {
        double sw = sqrt(wk->w[p]);
        const double *d = wk->sw.dphi + 3 * p * n;
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
            vol += wk->w[p];
            for (size_t q = 0; q < n3; ++q) {
                sv[q] += wk->w[p] * wk->sw.dphi[3 * p * n + q];
            }
        }
    }
#define M(a, i, b, j) c[((a) * n + (i)) >= ((b) * n + (j)) ? ((a) * n + (i)) + n3 * ((b) * n + (j)) \
                                                           : ((b) * n + (j)) + n3 * ((a) * n + (i))]
    for (size_t j = 0; j < n; ++j) {
        size_t lj = (size_t)wk->map[wk->sw.idx[j]];
        for (size_t i = j; i < n; ++i) {
            size_t li = (size_t)wk->map[wk->sw.idx[i]];
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
        add_volumetric(l->lambda, vol, sv, n, kc); /* cell mode: local order = support order */
    }
    return 0;
}

/* Dense stiffness of one cell over its node set (column major, 3m x 3m,
 * lower block triangle filled): the sum over its Gauss points of
 * w B^T D B (seed eq 19). */
static int cell_matrix(const tf_shape *sh, const tf_lame *l, int bbar, worker *wk, size_t cell,
                       const uint32_t *set, size_t m, double *kc)
{
    size_t dim = 3 * m;
    memset(kc, 0, dim * dim * sizeof *kc);
    for (size_t r = 0; r < m; ++r) {
        wk->map[set[r]] = (int)r;
    }
    int rc = sh->centre == TF_SUPPORT_CELL ? cell_matrix_cell(sh, l, bbar, wk, cell, dim, kc)
                                           : cell_matrix_points(sh, l, bbar, wk, cell, m, kc);
    for (size_t r = 0; r < m; ++r) {
        wk->map[set[r]] = -1;
    }
    return rc;
}

/* Adds a cell's dense matrix into K. */
static void scatter(tf_csc *k, const sets *bp, const uint32_t *set, size_t m, const double *kc)
{
    size_t dim = 3 * m;
    for (size_t lb = 0; lb < m; ++lb) {
        size_t b = set[lb], q = bp->ptr[b];
        for (size_t la = lb; la < m; ++la) {
            uint32_t a = set[la];
            while (bp->nodes[q] != a) {
                q++;
            }
            size_t pos = q - bp->ptr[b];
            for (size_t j = 0; j < 3; ++j) {
                double *dst = k->x + k->p[3 * b + j];
                const double *src = kc + dim * (3 * lb + j) + 3 * la;
                if (a == b) {
                    for (size_t i = j; i < 3; ++i) {
                        dst[i - j] += src[i];
                    }
                } else {
                    dst += (3 - j) + 3 * (pos - 1);
                    dst[0] += src[0];
                    dst[1] += src[1];
                    dst[2] += src[2];
                }
            }
        }
    }
}

static int assemble_values(const tf_shape *sh, const tf_lame *l, int bbar, worker *wks,
                           const sets *cs, const sets *bp, tf_csc *k, char *err, size_t errlen)
{
    size_t ncell = cs->count, maxm = 0;
    for (size_t c = 0; c < ncell; ++c) {
        size_t m = cs->ptr[c + 1] - cs->ptr[c];
        maxm = m > maxm ? m : maxm;
    }
    double *buf = malloc((size_t)BATCH * 9 * maxm * maxm * sizeof *buf);
    size_t np = tf_cells_points(&sh->cells);
    for (int t = 0; buf != NULL && t < omp_get_max_threads(); ++t) {
        wks[t].x = malloc(3 * np * sizeof *wks[t].x);
        wks[t].w = malloc(np * sizeof *wks[t].w);
        wks[t].y = malloc(3 * np * maxm * sizeof *wks[t].y);
        wks[t].c = malloc(9 * maxm * maxm * sizeof *wks[t].c);
        if (!wks[t].x || !wks[t].w || !wks[t].y || !wks[t].c) {
            free(buf);
            buf = NULL;
        }
    }
    if (buf == NULL) {
        snprintf(err, errlen, "out of memory for %d cell matrices of %zu nodes", BATCH, maxm);
        return -1;
    }
    char msg[256] = "";
    size_t failed = SIZE_MAX;
    for (size_t start = 0; start < ncell && failed == SIZE_MAX; start += BATCH) {
        size_t end = start + BATCH < ncell ? start + BATCH : ncell;
#pragma omp parallel for schedule(dynamic, 1)
        for (size_t c = start; c < end; ++c) {
            worker *wk = &wks[omp_get_thread_num()];
            double t0 = omp_get_wtime();
            int rc = cell_matrix(sh, l, bbar, wk, c, cs->nodes + cs->ptr[c],
                                 cs->ptr[c + 1] - cs->ptr[c],
                                 buf + (c - start) * 9 * maxm * maxm);
            wk->t_all += omp_get_wtime() - t0;
            if (rc != 0) {
#pragma omp critical(tf_assemble_fail)
                if (c < failed) {
                    failed = c;
                    snprintf(msg, sizeof msg, "%s", wk->sw.err);
                }
            }
        }
        for (size_t c = start; c < end && failed == SIZE_MAX; ++c) {
            scatter(k, bp, cs->nodes + cs->ptr[c], cs->ptr[c + 1] - cs->ptr[c],
                    buf + (c - start) * 9 * maxm * maxm);
        }
    }
    free(buf);
    if (failed != SIZE_MAX) {
        snprintf(err, errlen, "%s", msg);
        return -1;
    }
    return 0;
}

int tf_assemble_stiffness(const tf_shape *sh, const tf_lame *l, int bbar, tf_csc *k,
                          tf_assembly_info *info, char *err, size_t errlen)
{
    int nt = omp_get_max_threads();
    size_t nn = sh->cloud->n;
    sets cs = {0}, nc = {0}, bp = {0};
    memset(k, 0, sizeof *k);
    tf_shape_stats_reset(&info->st);
    info->points = tf_cells_count(&sh->cells) * tf_cells_points(&sh->cells);
    /* The threads here are OpenMP's: BLAS and LAPACK calls inside them run
     * on one thread each instead of spawning and spinning more. */
    openblas_set_num_threads(1);
    worker *wks = workers_new(nn, nt);
    if (wks == NULL) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    double t0 = omp_get_wtime();
    int rc = build_cell_sets(sh, wks, &cs, err, errlen);
    if (rc == 0) {
        workers_unmark(wks, nt, nn);
    }
    if (rc == 0 && (invert(&cs, nn, &nc) != 0 || block_pattern(&cs, &nc, wks, &bp) != 0)) {
        snprintf(err, errlen, "out of memory for the sparsity pattern");
        rc = -1;
    }
    if (rc == 0) {
        rc = scalar_pattern(&bp, k, err, errlen);
    }
    double t1 = omp_get_wtime();
    info->t_pattern = t1 - t0;
    if (rc == 0) {
        for (int t = 0; t < nt; ++t) {
            wks[t].t_shape = wks[t].t_all = 0;
            tf_shape_stats_reset(&wks[t].sw.st); /* count the value pass only */
        }
        rc = assemble_values(sh, l, bbar, wks, &cs, &bp, k, err, errlen);
    }
    info->t_values = omp_get_wtime() - t1;
    double ts = 0, ta = 0;
    for (int t = 0; t < nt; ++t) {
        ts += wks[t].t_shape;
        ta += wks[t].t_all;
    }
    info->shape_fraction = ta > 0 ? ts / ta : 0;
    workers_free(wks, nt, &info->st);
    sets_free(&cs);
    sets_free(&nc);
    sets_free(&bp);
    if (rc != 0) {
        tf_csc_free(k);
    }
    return rc;
}
