/*
 * scene.h — a scene file read into what the layers below use: a problem
 * (problem/problem.h: geometry, nodes, material, supports, loads, contact
 * sites, envelope, outputs, solver options, analytic solution) and the plan
 * of `tissuefit fit` (fitting/plan.h, the fit: section).  This folder is the
 * only one that reads YAML; nothing below it includes a scene header.
 *
 * A scene is read from a YAML file (docs/scene-format.md) with `--set
 * key=value` overrides applied before validation; every value has been
 * checked (finite, in range, regions that hold nodes).  Units: mm, N, MPa.
 */
#ifndef TF_SCENE_H
#define TF_SCENE_H

#include <stddef.h>

#include "base/context.h"
#include "fitting/plan.h"
#include "problem/problem.h"

typedef struct tf_scene {
    tf_problem problem;
    tf_fit_plan fit;    /* the fit: section (contact -1 when there is no contact site) */
    /* Warnings for the user, one per line ("" when none): a node number
     * from the file when --set changed the grid that numbered it. */
    char warnings[2048];
    /* Repairs the tool made to the scene's inputs, one per line ("" when
     * none): an organ mesh's triangles reversed because they wound inward,
     * vertices no triangle used dropped, specks of a mesh dropped.  Shown as
     * progress (tissuefit -q drops them) and recorded with the warnings. */
    char notes[1024];
} tf_scene;

/* A scene file is a regular file of at most this many bytes. */
#define TF_SCENE_MAX_BYTES (16 << 20)

/* Reads a scene file, applies the overrides ("key=value", e.g.
 * "geometry.grid=41,41,9") in order, validates and resolves it.  Returns
 * NULL with a message naming file, line and field (or the --set argument)
 * in ctx->err. */
tf_scene *tf_scene_load(tf_ctx *ctx, const char *path, const char *const *sets, size_t n_sets);

/* The same from YAML text in memory; `name` stands for the file in messages. */
tf_scene *tf_scene_load_text(tf_ctx *ctx, const char *text, size_t len, const char *name,
                             const char *const *sets, size_t n_sets);

void tf_scene_free(tf_scene *s);

/* "full, modified, ...": the values a key of named values accepts (path as
 * for --set, e.g. "solver.newton.tangent"), or "" when the key is not
 * one. */
void tf_scene_key_values(const char *path, char *out, size_t outlen);

#endif /* TF_SCENE_H */
