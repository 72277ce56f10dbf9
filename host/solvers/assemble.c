/*
 * assemble.c — sparse stiffness assembly (assemble.h; seed eqs 19-22).
 */
#include "solvers/assemble.h"

#include <cblas.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solvers/cell_stiffness.h"

/* Cells computed in parallel before they are added to K in cell order.  A
 * constant, so the result does not depend on the thread count. */
#define BATCH 32

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

static void add_support(const tf_shape_work *sw, uint32_t *mark, uint32_t stamp, uint32_t *list,
                        size_t *n)
{
    for (size_t k = 0; k < sw->n; ++k) {
        uint32_t a = sw->idx[k];
        if (mark[a] != stamp) {
            mark[a] = stamp;
            list[(*n)++] = a;
        }
    }
}

/* The supports of the cell's boundary points and, with VCI, of its face
 * integrals. */
static int extra_nodes(const tf_shape *sh, const tf_assembly_extra *ex, tf_shape_work *sw,
                       tf_grad_work *gw, uint32_t *mark, uint32_t stamp, uint32_t *list,
                       size_t cell, size_t *n)
{
    for (size_t q = ex->bnd ? ex->bnd->cell_ptr[cell] : 0;
         ex->bnd && q < ex->bnd->cell_ptr[cell + 1]; ++q) {
        if (tf_shape_support(sh, sw, ex->bnd->pt[q].x, cell) != 0) {
            return -1;
        }
        add_support(sw, mark, stamp, list, n);
    }
    if (ex->vci && tf_vci_cell_nodes(sh, gw, cell, mark, stamp, list, n) != 0) {
        snprintf(sw->err, sizeof sw->err, "%s", gw->sw.err);
        return -1;
    }
    return 0;
}

/* The nodes any support of the cell touches, ascending.  mark (node ->
 * stamp) and list are the thread's scratch. */
static int cell_set(const tf_shape *sh, const tf_assembly_extra *ex, tf_shape_work *sw,
                    tf_grad_work *gw, uint32_t *mark, uint32_t *list, size_t cell, uint32_t **out,
                    size_t *len)
{
    size_t n = 0, np = sh->centre == TF_SUPPORT_CELL ? 1 : tf_cells_points(&sh->cells);
    uint32_t stamp = (uint32_t)cell + 1;
    for (size_t p = 0; p < np; ++p) {
        double x[3], w;
        tf_cells_point(&sh->cells, cell, p, x, &w);
        if (tf_shape_support(sh, sw, x, cell) != 0) {
            return -1;
        }
        add_support(sw, mark, stamp, list, &n);
    }
    if (ex != NULL && extra_nodes(sh, ex, sw, gw, mark, stamp, list, cell, &n) != 0) {
        return -1;
    }
    qsort(list, n, sizeof *list, cmp_u32);
    *out = malloc((n + 1) * sizeof **out);
    if (*out == NULL) {
        snprintf(sw->err, sizeof sw->err, "out of memory");
        return -1;
    }
    memcpy(*out, list, n * sizeof **out);
    *len = n;
    return 0;
}

/* Records the lowest failing cell's message, whatever the schedule. */
static void note_failure(size_t c, const char *why, size_t *failed, char *msg, size_t msglen)
{
#pragma omp critical(tf_assemble_fail)
    if (c < *failed) {
        *failed = c;
        snprintf(msg, msglen, "%s", why);
    }
}

static int build_cell_sets(tf_ctx *ctx, const tf_shape *sh, const tf_assembly_extra *ex,
                           int threads, tf_nodesets *cs)
{
    size_t ncell = tf_cells_count(&sh->cells), nn = sh->cloud->n, failed = SIZE_MAX;
    uint32_t **lists = calloc(ncell, sizeof *lists);
    size_t *len = calloc(ncell, sizeof *len);
    char msg[512] = "out of memory";
    if (!lists || !len) {
        free(lists);
        free(len);
        return tf_fail(ctx, "out of memory");
    }
#pragma omp parallel num_threads(threads)
    {
        tf_shape_work sw;
        tf_grad_work gw;
        tf_shape_work_init(&sw);
        int gw_ok = ex != NULL && ex->vci ? tf_grad_work_init(&gw, sh, nn) == 0 : 1;
        uint32_t *mark = calloc(nn, sizeof *mark), *list = malloc((nn + 1) * sizeof *list);
#pragma omp for schedule(dynamic, 4)
        for (size_t c = 0; c < ncell; ++c) {
            if (!mark || !list || !gw_ok) {
                note_failure(c, "out of memory", &failed, msg, sizeof msg);
            } else if (cell_set(sh, ex, &sw, &gw, mark, list, c, &lists[c], &len[c]) != 0) {
                note_failure(c, sw.err, &failed, msg, sizeof msg);
            }
        }
        tf_shape_work_free(&sw);
        if (ex != NULL && ex->vci && gw_ok) {
            tf_grad_work_free(&gw);
        }
        free(mark);
        free(list);
    }
    int rc = tf_nodesets_pack(cs, lists, len, ncell);
    free(lists);
    free(len);
    if (failed != SIZE_MAX || rc != 0) {
        return tf_fail(ctx, "%s", msg);
    }
    return 0;
}

/* Adds a cell's dense matrix into K. */
static void scatter(tf_csc *k, const tf_nodesets *bp, const uint32_t *set, size_t m,
                    const double *kc)
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
                const double *src = kc + dim * (3 * lb + j) + 3 * la;
                for (size_t i = a == b ? j : 0; i < 3; ++i) {
                    k->x[tf_sparsity_entry(k, a, b, pos, i, j)] += src[i];
                }
            }
        }
    }
}

typedef struct value_pass {
    const tf_shape *sh;
    const tf_lame *l;
    const tf_lame_field *field;
    int bbar, vci;
    const tf_nodesets *cs, *bp;
    int threads;
    tf_csc *k;
    double t_shape, t_all;
    tf_shape_stats st;
} value_pass;

static int assemble_values(tf_ctx *ctx, value_pass *v)
{
    const tf_nodesets *cs = v->cs;
    size_t ncell = cs->count, maxm = 0, failed = SIZE_MAX;
    for (size_t c = 0; c < ncell; ++c) {
        size_t m = cs->ptr[c + 1] - cs->ptr[c];
        maxm = m > maxm ? m : maxm;
    }
    double *buf = malloc((size_t)BATCH * 9 * maxm * maxm * sizeof *buf);
    char msg[512] = "out of memory";
    int nt = v->threads;
    tf_cell_work *cw = calloc((size_t)nt, sizeof *cw);
    int ok = buf != NULL && cw != NULL;
    for (int t = 0; ok && t < nt; ++t) {
        ok = tf_cell_work_init(&cw[t], v->sh, v->sh->cloud->n, maxm, v->vci) == 0;
    }
    for (size_t start = 0; ok && start < ncell && failed == SIZE_MAX; start += BATCH) {
        size_t end = start + BATCH < ncell ? start + BATCH : ncell;
#pragma omp parallel for num_threads(nt) schedule(dynamic, 1)
        for (size_t c = start; c < end; ++c) {
            tf_cell_work *w = &cw[omp_get_thread_num()];
            double t0 = omp_get_wtime();
            if (tf_cell_stiffness(v->sh, v->l, v->field, v->bbar, w, c, cs->nodes + cs->ptr[c],
                                  cs->ptr[c + 1] - cs->ptr[c],
                                  buf + (c - start) * 9 * maxm * maxm) != 0) {
                note_failure(c, w->sw.err, &failed, msg, sizeof msg);
            }
#pragma omp atomic
            v->t_all += omp_get_wtime() - t0;
        }
        for (size_t c = start; c < end && failed == SIZE_MAX; ++c) {
            scatter(v->k, v->bp, cs->nodes + cs->ptr[c], cs->ptr[c + 1] - cs->ptr[c],
                    buf + (c - start) * 9 * maxm * maxm);
        }
    }
    for (int t = 0; cw != NULL && t < nt; ++t) {
        v->t_shape += cw[t].t_shape;
        tf_shape_stats_merge(&v->st, &cw[t].sw.st);
        if (cw[t].vci) {
            tf_shape_stats_merge(&v->st, &cw[t].gw.sw.st);
            tf_shape_stats_merge(&v->st, &cw[t].gw.fw.st);
        }
        tf_cell_work_free(&cw[t]);
    }
    free(cw);
    free(buf);
    if (!ok || failed != SIZE_MAX) {
        return tf_fail(ctx, "%s", ok ? msg : "out of memory for the cell matrices");
    }
    return 0;
}

int tf_assemble_pattern(tf_ctx *ctx, const tf_shape *sh, const tf_assembly_extra *ex, int threads,
                        tf_nodesets *cells, tf_nodesets *blocks, tf_csc *k)
{
    memset(cells, 0, sizeof *cells);
    memset(blocks, 0, sizeof *blocks);
    memset(k, 0, sizeof *k);
    int rc = build_cell_sets(ctx, sh, ex, threads, cells);
    if (rc == 0) {
        rc = tf_sparsity(ctx, cells, sh->cloud->n, threads, blocks, k);
    }
    if (rc != 0) {
        tf_nodesets_free(cells);
        tf_nodesets_free(blocks);
        tf_csc_free(k);
    }
    return rc;
}

int tf_assemble_stiffness(tf_ctx *ctx, const tf_shape *sh, const tf_lame *l, int bbar,
                          const tf_assembly_extra *ex, int threads, tf_csc *k,
                          tf_assembly_info *info)
{
    tf_nodesets cs = {0}, bp = {0};
    memset(k, 0, sizeof *k);
    info->points = tf_cells_count(&sh->cells) * tf_cells_points(&sh->cells);
    /* The threads here are OpenMP's: BLAS and LAPACK calls inside them run
     * on one thread each instead of spawning and spinning more. */
    openblas_set_num_threads(1);
    double t0 = omp_get_wtime();
    int rc = tf_assemble_pattern(ctx, sh, ex, threads, &cs, &bp, k);
    double t1 = omp_get_wtime();
    info->t_pattern = t1 - t0;
    value_pass v = {sh,  l, ex != NULL ? ex->field : NULL, bbar, ex != NULL && ex->vci,
                    &cs, &bp, threads, k, 0, 0, {0}};
    tf_shape_stats_reset(&v.st);
    if (rc == 0) {
        rc = assemble_values(ctx, &v);
    }
    info->t_values = omp_get_wtime() - t1;
    info->shape_fraction = v.t_all > 0 ? v.t_shape / v.t_all : 0;
    info->st = v.st;
    tf_nodesets_free(&cs);
    tf_nodesets_free(&bp);
    if (rc != 0) {
        tf_csc_free(k);
    }
    return rc;
}
