/*
 * scene_run.h — a scene loaded with overrides, a solver of it and load
 * cases solved, for the solver tests: one call, failing the current cmocka
 * test with the message when anything fails.
 */
#ifndef TF_SCENE_RUN_H
#define TF_SCENE_RUN_H

#include <stddef.h>

#include "base/context.h"
#include "scene/scene.h"
#include "solvers/solver.h"

typedef struct tf_scene_run {
    tf_ctx ctx;
    tf_scene *scene;
    const tf_problem *p;
    tf_solver *solver;
    size_t n3; /* 3 N */
    double *u; /* 3N x cases */
} tf_scene_run;

/* Scene file with overrides sets[0..n_sets), a solver of type (NULL: the
 * problem's solver.method) with a quiet context of the given thread count
 * (0: OpenMP's), and n cases forces[n] at contact site 0 (forces NULL:
 * the problem's loads only). */
tf_scene_run *tf_scene_run_solve(const char *scene, const tf_solver_ops *type,
                                 const char *const *sets, size_t n_sets, int threads,
                                 const double (*forces)[3], size_t n);
void tf_scene_run_free(tf_scene_run *r);

/* The reactions of a solution u of load case (contact 0, force) summed
 * per axis over the fixed DOFs (sum, which balances the force when the
 * solver is in equilibrium), and the largest residual at a free DOF.
 * Returns tf_solver_reactions' result (-1: no reactions). */
int tf_scene_run_balance(const tf_scene_run *r, const double force[3], const double *u,
                         double sum[3], double *resid);

/* max |v_i| */
double tf_max_abs(const double *v, size_t n);

#endif /* TF_SCENE_RUN_H */
