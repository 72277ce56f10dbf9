/*
 * discretisation.h — the solve's own error against the physics, so that a
 * header states fit + discretisation error, not only the fit against the
 * solve it was fitted to (issue 14).
 *
 * The physics is a finer reference solution of the same scene (CalculiX
 * C3D20R for block48, docs/calculix-reference.md), given as an index CSV
 *
 *     fx,fy,fz,file          header line
 *     1,0,0,block48_fx.csv   force in N at the fitted contact site; file
 *                            relative to the index, header node,x,y,z,ux,uy,uz
 *
 * The solve is evaluated at the reference's points through the solver's
 * displacement field (any cloud compares at the same points).  For a linear
 * solver with three independent reference forces the error is linear in the
 * force, e(F) = E F, and its largest component over the envelope
 * |F - c| <= R is max_i (R |E_i| + |E_i . c|); otherwise it is the largest
 * component error over the reference's cases, each of which must lie in
 * the envelope (a reference that stops early, as CalculiX NLGEOM does under
 * block48's patch, covers only part of it: reach says how far).  The
 * contact site's figure is the relative error of its
 * displacement (the compliance the contact inverse inverts), at the
 * reference point nearest the site.
 */
#ifndef TF_DISCRETISATION_H
#define TF_DISCRETISATION_H

#include <stddef.h>

#include "base/context.h"
#include "solvers/solver.h"

typedef struct tf_discretisation {
    double max_mm;    /* largest displacement component error over the envelope, mm */
    double site_rel;  /* contact-site displacement error / its magnitude, largest over cases */
    double site_gap;  /* distance from the contact node to the nearest reference point, mm */
    size_t cases, points;
    int enveloped;    /* 1: max_mm bounds the whole envelope (linear); 0: the cases only */
    double reach;     /* the cases' largest |F - centre| / radius: how far into the
                       * envelope a nonlinear solve's figure was measured */
    char source[256]; /* the index file, as given; "self-measured" */
    /* Measured by the tool itself (discretisation_self.h): */
    int self;
    double self_order;    /* the observed order of convergence (NAN: none) */
    double self_order_used; /* at most TF_SELF_ORDER_MAX */
    double self_other_mm; /* max_mm from the coarser pair of clouds */
    double self_diff[2];  /* L2 of the outputs' change, coarser -> the scene's -> finer, mm */
    double self_h[3];     /* the clouds' spacing, mm: coarser, the scene's, finer */
    size_t self_nodes[3];
    double self_seconds;  /* the two extra clouds' setup and solves */
    int self_relaxed;     /* a time-dependent solver: its fully relaxed response measured */
    int self_shifted;     /* the coarser cloud failed: the clouds are the scene's, h/r and
                           * h/r^2, and self_h, self_nodes, self_diff follow that order */
    char self_shifted_why[80]; /* why the coarser cloud failed, in short (the log has it all) */
    int self_solve_failed; /* the last attempt failed in a cloud's solve (Newton): the
                            * measurement is tried again with smaller forces */
    int self_skin_kept;   /* an organ whose skin is the file's on every cloud: the
                           * surface's part of the error is not in the figure */
} tf_discretisation;

/* Solves the reference's cases with solver s at contact site `contact` of
 * problem p and compares.  Returns 0, or -1 with a message naming the file
 * and line in ctx->err. */
int tf_discretisation_measure(tf_ctx *ctx, tf_solver *s, const tf_problem *p, int contact,
                              const char *index, tf_discretisation *out);

/* The same comparison against references held in memory: n cases, the
 * forces (N) at contact site `contact`, the displacements u[k] (3 np, mm)
 * at the points x (3 np, mm).  solved[k], when not NULL, is solver s's own
 * displacement at x under case k, already computed (a Newton solve is not
 * repeated); NULL: s solves each case.  Fills max_mm, site_rel, site_gap,
 * points, enveloped and reach of out, which the caller has cleared.
 * Returns 0, or -1 with a message. */
int tf_discretisation_compare(tf_ctx *ctx, tf_solver *s, const tf_problem *p, int contact,
                              const double (*force)[3], size_t n, const double *x, size_t np,
                              const double *const *u, const double *const *solved,
                              tf_discretisation *out);

#endif /* TF_DISCRETISATION_H */
