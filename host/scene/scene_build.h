/*
 * scene_build.h — from a loaded scene document to a checked tf_scene:
 * defaults, ranges, the node cloud, and regions resolved to nodes.
 */
#ifndef TF_SCENE_BUILD_H
#define TF_SCENE_BUILD_H

#include <stddef.h>

#include "scene/scene.h"
#include "scene/scene_schema.h"

/* What is wrong and where: the path of the offending value (scene_schema.h
 * syntax) and a message. */
typedef struct sd_issue {
    char path[128];
    char msg[256];
} sd_issue;

/* Fills s (zeroed by the caller) from doc.  Returns 0, or -1 with the
 * issue; s may then hold partial allocations for tf_scene_free. */
int sd_build(const sd_scene *doc, tf_scene *s, sd_issue *is);

/* Solver defaults (docs/scene-format.md) for a grid of nodes. */
tf_solver_opts sd_solver_defaults(const unsigned grid[3]);

#endif /* TF_SCENE_BUILD_H */
