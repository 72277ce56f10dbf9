/*
 * galerkin.h — the RPIM Galerkin solver of linear elasticity (seed 000 §2),
 * registered as "rpim-galerkin": built once (nodes, supports, RPIM shape
 * functions, Galerkin assembly, essential boundary conditions, one
 * Cholesky factorisation), then solved for as many load cases as needed
 * through that one factorisation.
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

extern const tf_solver_ops tf_galerkin_ops;

/* The build, in detail. */
typedef struct tf_galerkin_info {
    size_t points;        /* volume Gauss points */
    size_t nnz_k;         /* stored entries of K (lower triangle) */
    double nnz_l, flops;  /* factor entries, factorisation flops */
    const char *ordering;
    /* wall-clock seconds */
    double t_pattern;     /* supports of every cell, sparsity pattern */
    double t_shape;       /* RPIM shape functions (share of the value pass) */
    double t_assemble;    /* stiffness values (the rest of the value pass) */
    double t_loads;       /* load vectors, boundary conditions */
    double t_factor;      /* CHOLMOD analysis + factorisation */
    tf_shape_stats st;    /* local systems: count, conditioning, sizes */
} tf_galerkin_info;

/* The details of a Galerkin solver, or NULL for another kind. */
const tf_galerkin_info *tf_galerkin_info_of(const tf_solver *s);

/* The shape functions it built, or NULL for another kind of solver. */
const tf_shape *tf_galerkin_shape(const tf_solver *s);

#endif /* TF_GALERKIN_H */
