/*
 * solver.h — the meshless elasticity solver of a scene (seed 000 §2): built
 * once (nodes, supports, RPIM shape functions, Galerkin assembly, essential
 * boundary conditions, one Cholesky factorisation), then solved for as many
 * load cases as needed through that one factorisation.
 *
 * Loads: every solve applies the scene's `loads` plus, at one contact site,
 * a force per load case, spread as the site's patch says (a uniform
 * traction over a rectangle or disc of a face, or a point force at the
 * node).  The response is affine in the force; with no scene loads and
 * zero prescribed displacements, linear.
 *
 * Displacements are returned per node index (scene.h numbering: index =
 * scene node number - 1), DOF 3 i + a = component a of node i, in mm.
 *
 * Deterministic: the same scene gives the same bits whatever the number of
 * OpenMP threads.
 */
#ifndef TF_SOLVER_H
#define TF_SOLVER_H

#include <stddef.h>
#include <stdint.h>

#include "scene/scene.h"
#include "meshfree/shape.h"

typedef struct tf_solver tf_solver;

typedef struct tf_solver_info {
    size_t nodes, dofs, free_dofs;
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
    double t_solve;       /* all solves so far */
    size_t solves;        /* right-hand sides solved so far */
    tf_shape_stats st;    /* local systems: count, conditioning, sizes */
} tf_solver_info;

/* Builds the solver for a scene, which must outlive it.  Progress goes to
 * tf_info().  Returns NULL with a message in err on failure (singular local
 * system, stiffness not positive definite, out of memory). */
tf_solver *tf_solver_new(const tf_scene *scene, char *err, size_t errlen);
void tf_solver_free(tf_solver *s);

const tf_solver_info *tf_solver_info_of(const tf_solver *s);

size_t tf_solver_node_count(const tf_solver *s);
/* Node coordinates, 3 per node, mm. */
const double *tf_solver_coords(const tf_solver *s);
/* Scene node number (1-based) of a node index. */
uint32_t tf_solver_node_number(const tf_solver *s, size_t index);

/* Solves n load cases: case k applies the scene loads plus the force
 * forces[3k .. 3k+2] (N) at contact site `contact` (0 .. n_contacts - 1),
 * or only the scene loads when contact is -1 (then forces may be NULL).
 * Writes u[k 3N + dof] (3N x n, column major), one CHOLMOD solve with n
 * right-hand sides.  Returns 0, or -1 with a message. */
int tf_solver_solve(tf_solver *s, int contact, const double *forces, size_t n, double *u,
                    char *err, size_t errlen);

/* r = K u - f for a displacement u (3N) solved with (contact, force): at
 * fixed DOFs the reaction, the force the supports exert on the body (N);
 * at free DOFs the solve's residual (about zero).  Returns 0, or -1 for a
 * bad contact index. */
int tf_solver_reactions(const tf_solver *s, int contact, const double force[3], const double *u,
                        double *r);

/* 1 when DOF 3 i + a is prescribed by a fixed region. */
int tf_solver_dof_fixed(const tf_solver *s, size_t dof);

/* The shape functions the solver built (for post-processing). */
const tf_shape *tf_solver_shape(const tf_solver *s);

#endif /* TF_SOLVER_H */
