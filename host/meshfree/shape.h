/*
 * shape.h — the trial functions of the Galerkin method at a point: which
 * nodes support it and their RPIM shape functions (seed §2.2-2.3).
 *
 * Two kinds of shape function: RPIM (rpim.h, the default) and, after
 * tf_shape_use_efg, the element-free Galerkin method's MLS (mls.h, seed
 * 001), with the same output per point (nodes, phi, dphi).
 *
 * Two choices of support domain, both an ellipsoid of semi-axes
 * alpha_s x the local nodal spacing per axis, i.e. a ball of radius alpha_s
 * in the cloud's index space (nodes.h), so that a graded cloud's supports
 * hold as many nodes as a uniform one's (on an organ's tetrahedra: a ball of
 * radius alpha_s x the local spacing, tf_shape_use_tets) (EFG: every node's own domain of
 * influence, alpha_s x its local spacing; a support is then the set of
 * nodes whose domain reaches the point, or the cell):
 *   point: centred at the evaluation point itself (the seed: "a support
 *          domain of a certain size is centered there"); one local system
 *          per point;
 *   cell:  centred at the centre of the background cell holding the point;
 *          every point of a cell shares one node set and one factorised
 *          local system, which makes assembly several times faster.
 *
 * The multiquadric's length alpha_c d_c (rpim.h) is fixed (an absolute d_c,
 * the seed's) or d_c = d_c_spacings x h, h the local nodal spacing of the
 * support: the geometric mean of the grid intervals around its centre
 * (tf_cloud_local_spacing; on an organ's tetrahedra the distance to the
 * TF_LOCAL_K-th nearest node of the cell's centroid), so that the basis
 * keeps its shape relative to the nodes when the grid is refined or graded.
 *
 * Cuts (tf_shape_set_cuts, cut.h): the shape functions at a point whose
 * support meets a cut are recomputed — EFG with the weights of the
 * enriched nodes multiplied by the enrichment of seed 001 §4, RPIM on the
 * support nodes visible from the point (one local system per point
 * there).  Everywhere else they are the uncut ones, bit for bit.  The
 * support list (w->idx) stays the uncut one; a node cut off gets phi = 0.
 */
#ifndef TF_SHAPE_H
#define TF_SHAPE_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "meshfree/cut.h"
#include "meshfree/mls.h"
#include "meshfree/neighbours.h"
#include "meshfree/quadrature.h"
#include "meshfree/rpim.h"
#include "problem/problem.h"

typedef struct tf_shape {
    const tf_cloud *cloud;
    tf_rpim rpim;      /* shape: alpha_c d_c for an absolute d_c */
    double alpha_c, d_c_spacings; /* d_c_spacings > 0: d_c = d_c_spacings x local spacing */
    tf_nbr nbr;        /* RPIM on a box: over the nodes' index coordinates xi; EFG, tets: mm */
    double *xi;        /* RPIM: 3 n index coordinates (nodes.h), NULL after tf_shape_use_efg/_tets */
    double radius[3];  /* support semi-axes, mm (nominal spacing) */
    double scale;      /* largest semi-axis: distances are divided by it */
    tf_cells cells;
    tf_support_centre centre;
    double rcond_warn;
    double support;      /* alpha_s */
    double *mls_radius;  /* EFG: 3 n radii of influence, mm; NULL for RPIM */
    tf_cut_set cuts;     /* no panel: uncut */
    unsigned char *cut_node; /* EFG: 1 for a node whose domain meets a cut */
    int cut_all;         /* treat every support as cut (tests, bench) */
    double *cell_radius; /* tetrahedral cells: each one's support radius, mm; NULL otherwise */
    double *cell_spacing; /* tetrahedral cells: each one's local spacing h, mm (d_c = spacings x h) */
} tf_shape;

/* Conditioning and size of the local systems met by one worker. */
typedef struct tf_shape_stats {
    size_t systems;     /* local systems factorised */
    size_t ill;         /* of which with rcond < rcond_warn */
    double min_rcond;
    double worst_at[3]; /* where min_rcond occurred */
    size_t min_nodes, max_nodes;
    size_t points, cut_points; /* shape functions evaluated, of which recomputed for a cut */
} tf_shape_stats;

typedef struct tf_shape_work {
    tf_rpim_work rw;
    tf_mls_work mw;  /* EFG */
    uint32_t *idx;   /* support nodes, ascending */
    size_t n, cap;   /* support size, node capacity */
    size_t pcap;     /* point capacity of phi, dphi */
    double *phi;     /* phi[p n + i] at point p */
    double *dphi;    /* dphi[(3 p + a) n + i] */
    size_t cell;     /* cell whose system is factorised (cell mode), or SIZE_MAX */
    int cut;         /* the prepared support meets a cut */
    uint32_t *sub;   /* RPIM cut: the visible nodes (cap) */
    uint32_t *pos;   /* and their places in idx (cap) */
    double *tmp;     /* 4 cap: their phi, dphi at one point */
    tf_shape_stats st;
    char err[512];
} tf_shape_work;

/* From a node cloud (which must outlive sh), the box the background cells
 * cover and the solver options.  Returns 0, or -1 (out of memory, bad
 * cells). */
int tf_shape_init(tf_shape *sh, const tf_cloud *cloud, const double lo[3], const double hi[3],
                  const tf_solver_opts *o);
void tf_shape_free(tf_shape *sh);

/* Local nodal spacing at a point of an organ's cloud: the distance to its
 * TF_LOCAL_K-th nearest node.  On a regular grid of spacing h, at a cell
 * centre, that is the corners' distance 0.87 h; near an organ's skin,
 * whose vertices are denser than the interior nodes, it follows the skin. */
#define TF_LOCAL_K 6

/* On tetrahedral cells a support ball holds at most about this many nodes:
 * its radius is capped at the distance to the TF_SUPPORT_CAP-th nearest
 * node.  Where a coarse interior meets an organ's dense skin, a ball sized
 * by the interior's spacing would otherwise take in hundreds of skin
 * vertices (376 measured on the liver at 10 mm, against a median of 36). */
#define TF_SUPPORT_CAP 60

/* Integrates over the ntet tetrahedra tet[] of the cloud's nodes (an
 * organ's mesh; the array must outlive sh) with the Gauss rule of the
 * given degree, and sizes supports from the local spacing: every Gauss
 * point of a tetrahedron has the ball of radius alpha_s x the local
 * spacing at the tetrahedron's centroid (capped, TF_SUPPORT_CAP), centred
 * at the point or at the centroid (o->centre); a relative d_c
 * (solver.rbf.spacings) is that many times the same local spacing.  The
 * neighbour grid is rebuilt in mm.  RPIM only (EFG is refused).  Returns 0,
 * or -1 with a message. */
int tf_shape_use_tets(tf_ctx *ctx, tf_shape *sh, const size_t *tet, size_t ntet, unsigned degree);

/* Switches sh from RPIM to EFG: MLS shape functions whose nodes have the
 * radii of influence alpha_s x their local spacing (tf_mls_radii).
 * Returns 0, or -1 with a message in ctx->err. */
int tf_shape_use_efg(tf_ctx *ctx, tf_shape *sh);

/* Cuts n cuts into sh (after tf_shape_use_efg for EFG).  Returns 0, or -1
 * with a message (a bad cut, out of memory). */
int tf_shape_set_cuts(tf_ctx *ctx, tf_shape *sh, const tf_cut *cuts, size_t n);

/* How many nodes are enriched (EFG), for reports. */
size_t tf_shape_cut_nodes(const tf_shape *sh);

void tf_shape_work_init(tf_shape_work *w);
void tf_shape_work_free(tf_shape_work *w);

/* Shape functions (and gradients when deriv) at x, which lies in background
 * cell `cell` (tf_shape_cell).  Fills w->idx, w->n, w->phi, w->dphi (point
 * 0).  Returns 0, or -1 with a message in w->err (singular or empty
 * support, out of memory). */
int tf_shape_at(const tf_shape *sh, tf_shape_work *w, const double x[3], size_t cell, int deriv);

/* Cell-centred supports only: the np points x[3p ..] of one cell share its
 * support; one solve gives all their shape functions (points 0 .. np-1 in
 * w->phi, w->dphi). */
int tf_shape_cell_points(const tf_shape *sh, tf_shape_work *w, size_t cell, const double *x,
                         size_t np, int deriv);

/* The nodes of the support used at x in cell (no shape functions). */
int tf_shape_support(const tf_shape *sh, tf_shape_work *w, const double x[3], size_t cell);

/* Background cell holding x (clamped to the box). */
size_t tf_shape_cell(const tf_shape *sh, const double x[3]);

/* Merges worker statistics (order-independent: sums, min, max). */
void tf_shape_stats_merge(tf_shape_stats *into, const tf_shape_stats *from);
void tf_shape_stats_reset(tf_shape_stats *st);

#endif /* TF_SHAPE_H */
