/*
 * sparsity.c — the stiffness matrix's pattern from the cells' node sets
 * (sparsity.h).
 */
#include "solvers/sparsity.h"

#include <limits.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void tf_nodesets_free(tf_nodesets *s)
{
    free(s->ptr);
    free(s->nodes);
    s->ptr = NULL;
    s->nodes = NULL;
    s->count = 0;
}

int tf_nodesets_pack(tf_nodesets *s, uint32_t **lists, const size_t *len, size_t count)
{
    s->count = count;
    s->ptr = malloc((count + 1) * sizeof *s->ptr);
    if (s->ptr != NULL) {
        s->ptr[0] = 0;
        for (size_t k = 0; k < count; ++k) {
            s->ptr[k + 1] = s->ptr[k] + len[k];
        }
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

/* Inverse of the cell sets: the cells touching each node, ascending. */
static int invert(const tf_nodesets *cs, size_t n_nodes, tf_nodesets *nc)
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

/* The nodes a >= b that share a cell with b, ascending, into list; mark
 * is this thread's node -> stamp array. */
static size_t neighbours_of(size_t b, const tf_nodesets *cs, const tf_nodesets *nc,
                            uint32_t *mark, uint32_t *list)
{
    size_t m = 0;
    for (size_t q = nc->ptr[b]; q < nc->ptr[b + 1]; ++q) {
        size_t c = nc->nodes[q];
        for (size_t r = cs->ptr[c]; r < cs->ptr[c + 1]; ++r) {
            uint32_t a = cs->nodes[r];
            if (a >= b && mark[a] != (uint32_t)b + 1) {
                mark[a] = (uint32_t)b + 1;
                list[m++] = a;
            }
        }
    }
    qsort(list, m, sizeof *list, cmp_u32);
    return m;
}

/* Block pattern, one node per iteration in parallel (each writes its own
 * list: no order dependence). */
static int block_pattern(const tf_nodesets *cs, const tf_nodesets *nc, tf_nodesets *bp,
                         int threads)
{
    size_t n = nc->count;
    uint32_t **lists = calloc(n, sizeof *lists);
    size_t *len = calloc(n, sizeof *len);
    int oom = 0;
    if (!lists || !len) {
        free(lists);
        free(len);
        return -1;
    }
#pragma omp parallel num_threads(threads) reduction(| : oom)
    {
        uint32_t *mark = calloc(n, sizeof *mark), *list = malloc((n + 1) * sizeof *list);
        oom |= !mark || !list;
#pragma omp for schedule(dynamic, 64)
        for (size_t b = 0; b < n; ++b) {
            if (!oom) {
                size_t m = neighbours_of(b, cs, nc, mark, list);
                lists[b] = malloc(m * sizeof *lists[b]);
                if (lists[b] != NULL) {
                    memcpy(lists[b], list, m * sizeof *lists[b]);
                    len[b] = m;
                }
                oom |= lists[b] == NULL;
            }
        }
        free(mark);
        free(list);
    }
    int rc = tf_nodesets_pack(bp, lists, len, n);
    free(lists);
    free(len);
    return oom ? -1 : rc;
}

static int scalar_pattern(tf_ctx *ctx, const tf_nodesets *bp, tf_csc *k)
{
    size_t nn = bp->count, nnz = 0;
    for (size_t b = 0; b < nn; ++b) {
        /* a node in no cell has an empty list (not even itself): nothing
         * integrates its row, and 9 (len - 1) would wrap */
        if (bp->ptr[b + 1] == bp->ptr[b]) {
            return tf_fail(ctx,
                           "node %zu lies in no integration cell's support: nothing integrates its "
                           "stiffness (a cut or the background cells leave it uncovered)",
                           b + 1);
        }
        nnz += 6 + 9 * (bp->ptr[b + 1] - bp->ptr[b] - 1);
    }
    if (nnz > INT_MAX) {
        return tf_fail(ctx, "the stiffness matrix has %zu entries, more than this build handles",
                       nnz);
    }
    k->n = 3 * nn;
    k->nnz = nnz;
    k->p = malloc((k->n + 1) * sizeof *k->p);
    k->i = malloc(nnz * sizeof *k->i);
    k->x = calloc(nnz, sizeof *k->x);
    if (!k->p || !k->i || !k->x) {
        return tf_fail(ctx, "out of memory for a stiffness matrix of %zu entries", nnz);
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

int tf_sparsity(tf_ctx *ctx, const tf_nodesets *cells, size_t n_nodes, int threads,
                tf_nodesets *blocks, tf_csc *k)
{
    tf_nodesets nc = {0};
    memset(k, 0, sizeof *k);
    if (invert(cells, n_nodes, &nc) != 0 || block_pattern(cells, &nc, blocks, threads) != 0) {
        tf_nodesets_free(&nc);
        return tf_fail(ctx, "out of memory for the sparsity pattern");
    }
    tf_nodesets_free(&nc);
    return scalar_pattern(ctx, blocks, k);
}

long tf_sparsity_find(const tf_csc *k, size_t row, size_t col, size_t from)
{
    size_t lo = from > (size_t)k->p[col] ? from : (size_t)k->p[col], hi = (size_t)k->p[col + 1];
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if ((size_t)k->i[mid] < row) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return lo < (size_t)k->p[col + 1] && (size_t)k->i[lo] == row ? (long)lo : -1;
}

int tf_sparsity_add_dense(tf_csc *k, const uint32_t *idx, size_t n, const double *dense)
{
    size_t dim = 3 * n;
    for (size_t j = 0; j < n; ++j) {
        for (size_t b = 0; b < 3; ++b) {
            size_t col = 3 * (size_t)idx[j] + b, from = 0;
            const double *src = dense + dim * (3 * j + b);
            for (size_t i = j; i < n; ++i) {
                size_t a0 = i == j ? b : 0, row = 3 * (size_t)idx[i] + a0;
                long q = tf_sparsity_find(k, row, col, from);
                if (q < 0) {
                    return -1;
                }
                /* the rows of a node's block follow one another */
                for (size_t a = a0; a < 3; ++a) {
                    k->x[(size_t)q + a - a0] += src[3 * i + a];
                }
                from = (size_t)q;
            }
        }
    }
    return 0;
}
