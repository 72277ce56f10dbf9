/*
 * cmd_args.h — option values and steps shared by the solver commands.
 */
#ifndef TF_CMD_ARGS_H
#define TF_CMD_ARGS_H

#include <stddef.h>

#include "base/context.h"
#include "scene/scene.h"

/* "FX,FY,FZ" -> v; 0, or -1 when not three finite numbers. */
int tf_parse_vec3(const char *s, double v[3]);

/* A growing list of --set assignments (pointers into argv). */
typedef struct tf_sets {
    const char **item;
    size_t n, cap;
} tf_sets;

/* Appends; 0, or -1 when out of memory. */
int tf_sets_add(tf_sets *s, const char *assignment);
void tf_sets_free(tf_sets *s);

/* Checks, before any work, that every output path (NULL entries are
 * skipped) can be written (base/atomic_file.h: a new or regular file, or a
 * link to one, in a writable directory).  0, or -1 after "CMD: reason". */
int tf_cmd_outputs(tf_ctx *ctx, const char *cmd, const char *const *paths, size_t n);

/* The same for a directory that files will be written into. */
int tf_cmd_output_dir(tf_ctx *ctx, const char *cmd, const char *dir);

/* The scene file with the --set overrides applied, or NULL after an error
 * message (file, line, field) through the context. */
tf_scene *tf_cmd_scene(tf_ctx *ctx, const char *path, const tf_sets *sets);

/* --cut-progress S: every cut of problem p truncated at the fraction S of
 * its path (a cut with nothing left is dropped).  0, or -1 after a message
 * when the scene (named `scene`) has no cuts. */
int tf_cmd_cut_progress(tf_ctx *ctx, const char *scene, tf_problem *p, double s);

#endif /* TF_CMD_ARGS_H */
