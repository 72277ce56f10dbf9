/*
 * cut.h — incisions in the body and the enrichment of the weight functions
 * of the nodes whose support meets one (seed 001 §4).
 *
 * A cut is a polyline on the top surface z = top swept down to a depth: a
 * chain of vertical rectangles (panels).  Panel k spans the segment
 * a_k -> b_k of the polyline (tangent t, length L, in-plane coordinate
 * f = t.(x - a) in [0, L]), the depth coordinate z in [top - depth, top],
 * and has the horizontal unit normal n = t x e_z (normal coordinate
 * s = n.(x - a), the side function: s >= 0 is the "+" side).
 *
 * Distance (seed eq 29-30, generalised from the segment to the rectangle;
 * the seed text is garbled, this is the standard distance to a segment):
 *   d_f = |f - L/2| - L/2,  d_g = |z - (top - depth/2)| - depth/2
 *   (negative inside the panel's span), d(x) = sqrt(d_f+^2 + d_g+^2 + s^2)
 * with d+ = (d + |d|)/2: the Euclidean distance from x to the panel.
 * Discontinuous function (eq 31) phi = dd/ds = s/d: +1 / -1 on either side
 * within the span, smooth around the panel's free edges (the cut front).
 * Enrichment (eq 32) h = (phi + 1)/2.  The seed multiplies "the weight
 * function of the corresponding node" by it; a node must keep its weight
 * on its own side and lose it across the cut, so (our reading, the
 * transparency idea of Organ, Fleming, Terry & Belytschko 1996) node I's
 * weight is multiplied by
 *   e_I(x) = h(x) h(x_I) + (1 - h(x)) (1 - h(x_I)),
 * which is 1 when x and x_I lie on the same side of the panel, 0 across it
 * and varies smoothly ahead of the front.  Several panels multiply.  Only
 * the nodes whose domain of influence meets a panel are enriched (the seed:
 * "only the shape functions of nodes whose distance is less than their
 * expansion parameters are recalculated"): e_I = 1 for every other node.
 *
 * RPIM shape functions interpolate and have no weight to enrich; they use
 * the visibility criterion (Belytschko, Lu & Gu 1994; Belytschko, Krongauz
 * et al. 1996): a node is dropped from the support of x when the segment
 * x_I -> x crosses a panel.
 */
#ifndef TF_CUT_H
#define TF_CUT_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "problem/problem.h" /* tf_cut: a cut as the problem gives it */

/* One rectangle of a cut. */
typedef struct tf_cut_panel {
    double a[3];      /* first top corner, mm */
    double t[3], n[3];/* unit tangent (horizontal) and normal */
    double len;       /* along t, mm */
    double zlo, zhi;  /* depth span, mm */
    size_t cut;       /* the cut it belongs to: index into tf_cut_set.where */
} tf_cut_panel;

typedef struct tf_cut_set {
    tf_cut_panel *panel;
    size_t n;
    char (*where)[TF_CUT_WHERE_MAX]; /* per cut: its tf_cut.where, for messages */
    size_t n_cuts;
} tf_cut_set;

/* The panels of n cuts.  Returns 0, or -1 with a message (a segment of
 * zero length, a non-positive depth, out of memory).  An empty set (n = 0)
 * is valid. */
int tf_cut_set_build(tf_ctx *ctx, tf_cut_set *set, const tf_cut *cuts, size_t n);
void tf_cut_set_free(tf_cut_set *set);

/* Side function: the signed normal coordinate s of x, mm. */
double tf_cut_side(const tf_cut_panel *p, const double x[3]);

/* Distance from x to the panel (eq 29), mm. */
double tf_cut_distance(const tf_cut_panel *p, const double x[3]);

/* The enrichment h(x) of eq 32 in [0, 1]; grad (may be NULL) receives dh/dx
 * (per mm; zero inside the span, undefined on the panel itself). */
double tf_cut_h(const tf_cut_panel *p, const double x[3], double grad[3]);

/* 1 when the segment a -> b crosses no panel (visibility criterion). */
int tf_cut_visible(const tf_cut_set *set, const double a[3], const double b[3]);

/* 1 when the segment a -> b crosses a panel of cut number `cut` (the index
 * of the cut in the array the set was built from). */
int tf_cut_blocks(const tf_cut_set *set, size_t cut, const double a[3], const double b[3]);

/* The cut (index, as tf_cut_blocks) whose panels hide the most of the n
 * nodes idx (coordinates xyz) from x, or SIZE_MAX when no cut hides any;
 * *hidden (may be NULL) receives how many it hides.  Names the cut a
 * singular local system at x comes from. */
size_t tf_cut_hiding(const tf_cut_set *set, const double *xyz, const uint32_t *idx, size_t n,
                     const double x[3], size_t *hidden);

/* Node weight factor e_I(x) at x for the node at xi (product over the
 * panels); grad (may be NULL) receives de_I/dx. */
double tf_cut_enrich(const tf_cut_set *set, const double xi[3], const double x[3],
                     double grad[3]);

/* 1 when x lies on a panel: within tol (mm) of its plane and inside its
 * span.  Such a point has no side (tf_cut_h and the visibility put it on
 * the + side); an integration point of a cell face lying on a cut must be
 * moved into its cell to see that cell's side. */
int tf_cut_on_panel(const tf_cut_set *set, const double x[3], double tol);

/* 1 when some panel meets the box [lo, hi]. */
int tf_cut_meets_box(const tf_cut_set *set, const double lo[3], const double hi[3]);

/* Smallest distance from x to a panel (INFINITY for an empty set). */
double tf_cut_set_distance(const tf_cut_set *set, const double x[3]);

/* The cut's progress (docs/cutting.md, "Cut progress"): the path of c
 * truncated at the fraction s of its length into out (out->n = 0 when
 * nothing is left: s <= 0, or less than 1e-9 mm of path). */
void tf_cut_truncate(const tf_cut *c, double s, tf_cut *out);

#endif /* TF_CUT_H */
