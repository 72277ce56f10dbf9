/*
 * case_graph.h — the continuation graph of a case list (case_runner.h),
 * made from the list's forces alone so that every schedule, on any number
 * of ranks, starts each case from the same place.
 *
 * Anchored: the first n_anchor cases start from rest; every later case
 * starts from the anchor whose force is nearest its own (Euclidean, the
 * lower index on a tie), unless the zero force is at least as near, when it
 * starts from rest too.  The graph is two levels deep: after the anchors,
 * every case can be solved at once, which is what a cluster of ranks needs
 * (a chain "from the previous case" would serialise them).
 */
#ifndef TF_FIT_CASE_GRAPH_H
#define TF_FIT_CASE_GRAPH_H

#include <stddef.h>

/* Anchors for a list of n cases: ceil(sqrt(n)), at most n. */
size_t tf_case_graph_anchors(size_t n);

/* from[n] (case_runner.h) for forces[n]. */
void tf_case_graph_anchored(const double (*forces)[3], size_t n, size_t n_anchor, long *from);

#endif /* TF_FIT_CASE_GRAPH_H */
