/*
 * inclusions.h — the material at a point of a body with material regions
 * (problem.h, tf_inclusion): the first inclusion holding the point, else
 * the body's material.  The Galerkin solvers take it at every Gauss point
 * (solvers/cell_stiffness.h): the integration cells do not follow an
 * inclusion's surface, so a cell it cuts is integrated with each Gauss
 * point's own material (docs/solver.md, "Material regions").
 */
#ifndef TF_INCLUSIONS_H
#define TF_INCLUSIONS_H

#include "materials/elasticity.h"
#include "problem/problem.h"

/* Whether point x lies in inclusion c (boundary included). */
int tf_inclusion_holds(const tf_inclusion *c, const double x[3]);

/* The material region at x: k + 1 for the first inclusion k holding it,
 * else 0 (the body). */
size_t tf_problem_region_at(const tf_problem *p, const double x[3]);

/* The small-strain Lame parameters at x (the linear solvers). */
tf_lame tf_problem_lame_at(const tf_problem *p, const double x[3]);

#endif /* TF_INCLUSIONS_H */
