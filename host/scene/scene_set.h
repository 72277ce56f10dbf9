/*
 * scene_set.h — `--set key=value` on a loaded scene document.
 *
 * The key is a path (scene_schema.h: "geometry.grid", "fixed.0.face",
 * "solver.rbf.q"); the value is YAML for that key's type, parsed by
 * libcyaml with the key's own schema, so it is checked exactly as in a
 * file.  A list may be written without brackets ("41,41,9").  A sequence
 * index equal to the current length appends an entry.  Absent optional
 * mappings on the way are created.
 */
#ifndef TF_SCENE_SET_H
#define TF_SCENE_SET_H

#include <stddef.h>

#include "base/context.h"
#include "scene/scene_schema.h"

/* Applies one "key=value" to a document of schema root and writes the
 * key's path to path.  Returns 0, or -1 with a message in ctx->err; the value is
 * then unchanged, though empty optional mappings or an appended entry on
 * the way may remain. */
int sd_set(tf_ctx *ctx, const cyaml_schema_value_t *root, sd_scene *doc, const char *assignment,
           char *path, size_t pathlen);

#endif /* TF_SCENE_SET_H */
