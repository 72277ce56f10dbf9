/*
 * galerkin.h — the meshless Galerkin solver of linear elasticity: RPIM shape
 * functions (seed 000 §2), registered as "rpim-galerkin", or EFG's MLS
 * shape functions (seed 001 §2), "efg-galerkin".  Built once (nodes,
 * supports, shape functions, Galerkin assembly, essential boundary
 * conditions, one Cholesky factorisation), then solved for as many load
 * cases as needed through that one factorisation.
 *
 * EFG's unknowns are nodal parameters, not displacements: essential
 * conditions go in weak form (boundary.h), and every displacement it
 * returns is the displacement at the nodes, u(x_I) = sum_J phi_J(x_I) d_J
 * (nodal_values.h).  RPIM may take Nitsche's weak form too.
 *
 * Its response is affine in the contact force (linear when the problem has
 * no loads and zero prescribed displacements); it gives reactions and the
 * displacement field between nodes (the RPIM interpolant).  The same
 * problem gives the same bits whatever the number of threads.
 *
 * Everything below is specific to this solver: callers that need only a
 * solver use solvers/solver.h.
 */
#ifndef TF_GALERKIN_H
#define TF_GALERKIN_H

#include <stddef.h>

#include "meshfree/shape.h"
#include "solvers/solver.h"

extern const tf_solver_ops tf_galerkin_ops;     /* "rpim-galerkin" */
extern const tf_solver_ops tf_efg_galerkin_ops; /* "efg-galerkin": MLS shape functions */

/* The build, in detail. */
typedef struct tf_galerkin_info {
    size_t points;        /* volume Gauss points */
    size_t nnz_k;         /* stored entries of K (lower triangle) */
    double nnz_l, flops;  /* factor entries, factorisation flops */
    double rcond;         /* CHOLMOD's rough reciprocal condition of the factorised system */
    const char *ordering;
    /* wall-clock seconds */
    double t_pattern;     /* supports of every cell, sparsity pattern */
    double t_shape;       /* RPIM shape functions (share of the value pass) */
    double t_assemble;    /* stiffness values (the rest of the value pass) */
    double t_loads;       /* load vectors, boundary conditions */
    double t_factor;      /* CHOLMOD analysis + factorisation */
    double t_analyse;     /* of which the symbolic analysis (the ordering) */
    double chol_mib;      /* CHOLMOD's peak memory, the factor included, MiB */
    tf_shape_stats st;    /* local systems: count, conditioning, sizes */
} tf_galerkin_info;

/* The details of a Galerkin solver, or NULL for another kind. */
const tf_galerkin_info *tf_galerkin_info_of(const tf_solver *s);

/* The shape functions it built, or NULL for another kind of solver. */
const tf_shape *tf_galerkin_shape(const tf_solver *s);

#endif /* TF_GALERKIN_H */
