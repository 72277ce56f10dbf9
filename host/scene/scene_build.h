/*
 * scene_build.h — from a loaded scene document to a checked problem and fit
 * plan: defaults, ranges, the node cloud, and regions resolved to nodes.
 */
#ifndef TF_SCENE_BUILD_H
#define TF_SCENE_BUILD_H

#include <stddef.h>

#include "fitting/plan.h"
#include "problem/problem.h"
#include "scene/scene_issue.h"
#include "scene/scene_schema.h"

/* Fills p (zeroed by the caller, its name and source set) and the plan
 * from doc.  Returns 0, or -1 with the issue; p may then hold partial
 * allocations for tf_problem_release. */
int sd_build(const sd_scene *doc, tf_problem *p, tf_fit_plan *plan, sd_issue *is);

/* Solver defaults (docs/scene-format.md) for a grid of nodes. */
tf_solver_opts sd_solver_defaults(const unsigned grid[3]);

#endif /* TF_SCENE_BUILD_H */
