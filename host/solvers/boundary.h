/*
 * boundary.h — essential boundary conditions in weak form, for shape
 * functions that do not interpolate (EFG's MLS) or whose interior nodes do
 * not vanish on the boundary (RPIM): the quadrature points of the prescribed
 * part of the boundary Gamma_u and the terms they add to a Galerkin system.
 *
 *   penalty (seed 001 eqs 19, 23):  + alpha int_Gu v.S(u - ubar)
 *   Nitsche (Nitsche 1971; Griebel & Schweitzer 2003 for meshfree methods):
 *       - int_Gu v.S(sigma(u) n) - int_Gu (sigma(v) n).S(u - ubar)
 *       + beta int_Gu v.S(u - ubar)
 *
 * S is the diagonal mask of the prescribed components (a roller prescribes
 * one).  Nitsche's first two terms make the weak form consistent: the exact
 * solution satisfies it whatever beta, so the error does not depend on a
 * large factor the way the penalty's O(1/alpha) does; beta only has to be
 * large enough for coercivity.  Both factors are given relative to the
 * material: alpha = penalty (lambda + 2 mu) / h and beta = nitsche
 * (lambda + 2 mu) / h, h the smallest nodal spacing (docs/solver.md).
 *
 * Gamma_u is the union of the faces the fixed regions name (a face, or a
 * plane that is a face of the box); a fixed region inside the body (a box,
 * an interior plane) has no surface to integrate over and is refused.
 */
#ifndef TF_BOUNDARY_H
#define TF_BOUNDARY_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "materials/elasticity.h"
#include "meshfree/shape.h"
#include "numerics/csc.h"
#include "problem/problem.h"

/* One quadrature point of Gamma_u. */
typedef struct tf_bpoint {
    double x[3], w;   /* point (mm) and area weight (mm^2) */
    double n[3];      /* outward unit normal */
    double ubar[3];   /* prescribed displacement, mm */
    unsigned mask;    /* TF_COMP_* prescribed components */
    uint32_t region;  /* fixed region it comes from */
    size_t cell;      /* background cell holding it */
} tf_bpoint;

typedef struct tf_boundary {
    tf_bpoint *pt;
    size_t n;
    size_t *cell_ptr; /* points of cell c: pt[cell_ptr[c] .. cell_ptr[c+1]) (sorted by cell) */
    size_t n_cells;
} tf_boundary;

/* The points of every fixed region's face (the same rule as a load patch
 * covering the face, quadrature.h), sorted by cell.  Returns 0, or -1 with
 * a message (a region that is not a face of the box, out of memory). */
int tf_boundary_build(tf_ctx *ctx, tf_boundary *b, const tf_problem *p, const tf_shape *sh);
void tf_boundary_free(tf_boundary *b);

/* The factor's scale (lambda + 2 mu) / h of the problem's small-strain
 * moduli l and node cloud. */
double tf_boundary_scale(const tf_lame *l, const tf_cloud *c);

/* Adds the linear-elastic weak terms of method (TF_BC_PENALTY: factor is
 * alpha; TF_BC_NITSCHE: beta; both in MPa/mm, already scaled) to K (lower
 * triangle; its pattern must hold every pair of nodes that support one
 * boundary point) and to rhs (3N).  Returns 0, or -1 with a message. */
int tf_boundary_add_linear(tf_ctx *ctx, const tf_boundary *b, const tf_shape *sh,
                           tf_bc_method method, double factor, const tf_lame *l, tf_csc *k,
                           double *rhs);

#endif /* TF_BOUNDARY_H */
