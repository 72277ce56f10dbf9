/*
 * api_internal.h — what the API's files share (api.h): what a tf_api_scene
 * handle holds, and a failure message that wraps the one before it.
 */
#ifndef TF_API_INTERNAL_H
#define TF_API_INTERNAL_H

#include "api/api.h"
#include "scene/scene.h"
#include "solvers/solver.h"

/* The scene as the tool reads it, its path for messages, the solver
 * built at its first solve, and the scene's cuts whole (the problem's are
 * truncated to the cut progress of the solver's build). */
struct tf_api_scene {
    tf_scene *scene;
    tf_solver *solver; /* NULL until the first tf_api_solve */
    char *path;        /* the scene file, as messages name it */
    tf_cut *cuts;      /* a copy of the scene's n_cuts cuts */
    size_t n_cuts;
    double progress;   /* the cut progress the problem's cuts are at; NaN: whole */
};

/* ctx->err becomes the formatted prefix, ": " and its previous text (the
 * form of the tool's messages, "solve: SCENE: ..."); returns -1. */
int tf_api_fail_on(tf_ctx *ctx, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif /* TF_API_INTERNAL_H */
