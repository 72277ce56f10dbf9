/*
 * sparsity.h — which entries of the stiffness matrix exist: node pairs that
 * share a background cell's node set, as 3 x 3 blocks, laid out in
 * compressed columns (csc.h) with 3 DOFs per node.
 */
#ifndef TF_SPARSITY_H
#define TF_SPARSITY_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "numerics/csc.h"

/* Lists of nodes in compressed rows: list k is nodes[ptr[k] .. ptr[k+1]). */
typedef struct tf_nodesets {
    size_t count;
    size_t *ptr;
    uint32_t *nodes;
} tf_nodesets;

void tf_nodesets_free(tf_nodesets *s);

/* Packs count separately allocated lists (freed here, NULL allowed when
 * empty) into s.  Returns 0, or -1 when out of memory. */
int tf_nodesets_pack(tf_nodesets *s, uint32_t **lists, const size_t *len, size_t count);

/* From the cells' node sets (ascending), the block pattern (for each node
 * b the nodes a >= b sharing a cell with it, ascending, b first) and the
 * scalar pattern of K with zero values: column 3b + j holds rows
 * 3b + j .. 3b + 2, then 3a .. 3a + 2 for each node a > b, on `threads`
 * OpenMP threads (the same result for any count).  Returns 0, or -1 with a
 * message. */
int tf_sparsity(tf_ctx *ctx, const tf_nodesets *cells, size_t n_nodes, int threads,
                tf_nodesets *blocks, tf_csc *k);

/* Position of entry (3a + i, 3b + j), a >= b and i >= j when a == b, in
 * K's values; pos is the index of a in b's block list (0 for b itself). */
static inline size_t tf_sparsity_entry(const tf_csc *k, size_t a, size_t b, size_t pos, size_t i,
                                       size_t j)
{
    return (size_t)k->p[3 * b + j] + (a == b ? i - j : (3 - j) + 3 * (pos - 1) + i);
}

/* Position of entry (row, col), row >= col, in K's values, searching the
 * column's rows from position `from` on; -1 when the pattern lacks it. */
long tf_sparsity_find(const tf_csc *k, size_t row, size_t col, size_t from);

/* Adds the lower triangle of a dense matrix over the nodes idx[0 .. n)
 * (ascending; 3n x 3n, column major, DOF 3 i + a of local node i) to K.
 * Returns 0, or -1 (nothing further added) when the pattern lacks a pair. */
int tf_sparsity_add_dense(tf_csc *k, const uint32_t *idx, size_t n, const double *dense);

#endif /* TF_SPARSITY_H */
