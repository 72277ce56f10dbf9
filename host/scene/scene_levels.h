/*
 * scene_levels.h — the levels of a convergence study of a scene file
 * (`tissuefit verify`), each a scene read with extra overrides.
 *
 * Grid series: level k halves the nodal spacing k times on every axis
 * with more than two nodes, and scales the background cells and the RBF
 * length d_c with it, so every level is the same discretisation at a finer
 * scale.  An axis with two nodes is the thickness of a plane problem: it
 * keeps its two nodes and its extent shrinks with the spacing.
 *
 * Gauss series: level k uses k + 1 Gauss points per axis, nothing else
 * changes.
 */
#ifndef TF_SCENE_LEVELS_H
#define TF_SCENE_LEVELS_H

#include <stddef.h>

#include "base/context.h"
#include "scene/scene.h"

typedef enum tf_vary { TF_VARY_GRID, TF_VARY_GAUSS } tf_vary;

/* Level k of the study of a scene file, with the user's overrides applied
 * first; *label is the level's name in a table (grid: k; gauss: the Gauss
 * order).  Returns NULL with a message (a bad scene) in ctx->err. */
tf_scene *tf_scene_level(tf_ctx *ctx, const char *path, const char *const *sets, size_t n_sets,
                         tf_vary vary, unsigned k, unsigned *label);

/* The scene file with the user's overrides, its nodal spacing times f (a
 * box: every axis of more than two nodes, its grid rounded to whole
 * intervals, and its background cells; an organ: the interior spacing and a
 * local refinement's, its surface vertices stay the file's) and an absolute
 * d_c with it.  Returns NULL with a message in ctx->err. */
tf_scene *tf_scene_scaled(tf_ctx *ctx, const char *path, const char *const *sets, size_t n_sets,
                          double f);

#endif /* TF_SCENE_LEVELS_H */
