/*
 * emit_header.h — writes models as one generated C header (NAME.h) and their
 * golden vectors (NAME_golden.h), both atomically, in the format of
 * docs/header-format.md.
 */
#ifndef TF_EMIT_HEADER_H
#define TF_EMIT_HEADER_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "model/model.h"

/* An organ's outputs (docs/header-format.md §10): for each output point, in
 * the forward model's order, the vertex of the mesh file it is (its index
 * as tissuefit reads the file) and its rest position in the scene's frame
 * (mm) and in the file's frame (file units), so that a renderer can match
 * its own vertices by index or by position. */
typedef struct tf_emit_map {
    const char *mesh_file;   /* as the scene names it */
    uint32_t mesh_crc32;     /* of its bytes */
    const char *reader;      /* how vertex indices count (reader and its options) */
    size_t n;
    const uint32_t *vertex;  /* n */
    const double *rest_mm;   /* 3 n */
    const double *rest_file; /* 3 n */
    uint32_t contact_vertex; /* the contact node's vertex */
} tf_emit_map;

typedef struct tf_emit_info {
    const char *source;     /* scene file path, or a description of a built-in model */
    int has_source_crc;     /* source_crc32 is the CRC-32 of the scene file's bytes */
    uint32_t source_crc32;
    const char *notes;      /* extra banner text, '\n'-separated lines, or NULL */
    uint64_t golden_seed;   /* seed of the golden input design */
    const tf_emit_map *map; /* an organ's output map, or NULL */
    unsigned servo_hz;      /* the haptic loop's rate: the header states the budget (0: none) */
    /* Where the outputs are when they are points between nodes (NULL: nodes,
     * named by node_ids): n_points points, 3 coordinates each, mm; output j
     * of a forward model (node_ids[j] = j + 1) is point j. */
    const double *points;
    size_t n_points;
    const double *contact_point; /* NULL, or the contact point by position, mm */
} tf_emit_info;

/* Validates every model, then writes path and its _golden.h sibling.  The
 * file's base name (without .h) must be a C identifier in lower case; it
 * names the include guard and the IMPLEMENTATION macro.  Both files are
 * synced before either is renamed; the header carries the golden file's
 * CRC and the golden file refuses to compile beside another header
 * (header-format.md section 1).  Returns 0, or -1 with a message in ctx->err and
 * nothing written. */
int tf_emit_header(tf_ctx *ctx, const char *path, tf_model *const *models, size_t n_models,
                   const tf_emit_info *info);

/* Checks, before any work, that path names a header tf_emit_header can
 * write: a lower-case C identifier + ".h" that leaves room for a model name
 * suffix of model_suffix characters (strlen("_forward")), and writable
 * destinations for it and its golden file (atomic_file.h).  Returns 0, or
 * -1 with a message. */
int tf_emit_check_path(tf_ctx *ctx, const char *path, size_t model_suffix);

/* The golden path for a header path: "dir/name.h" -> "dir/name_golden.h". */
int tf_golden_path(const char *header_path, char *out, size_t outlen);

#endif /* TF_EMIT_HEADER_H */
