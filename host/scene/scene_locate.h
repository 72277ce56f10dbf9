/*
 * scene_locate.h — where in a scene file a value is, and libcyaml's errors
 * reworded as "line, field, what is wrong".
 *
 * libcyaml reports line numbers only for its own load errors.  To place an
 * error found after loading (E negative, a region holding no node, ...),
 * the document is loaded again with a copy of the schema in which the value
 * at that path is given an impossible type: libcyaml then stops exactly
 * there and its backtrace names the line.  Inside a sequence of mappings
 * the line is that of the entry.
 */
#ifndef TF_SCENE_LOCATE_H
#define TF_SCENE_LOCATE_H

#include <stddef.h>

#include "scene/scene_schema.h"

/* Line (1-based) of the value at path in the YAML text of a scene (schema
 * root), or 0 when the text has no such value (an absent optional key, for
 * instance). */
int sd_locate(const cyaml_schema_value_t *root, const char *text, size_t len, const char *path);

/* Rewords a failed load: writes the innermost line to *line, the path of
 * the offending value to path ("" at the top), and a message to msg.  The
 * text holds the value at path base ("" for a whole scene) of a scene of
 * schema root. */
void sd_explain(const cyaml_schema_value_t *root, const char *text, size_t len,
                const sd_log *log, const char *base, int *line, char *path, size_t pathlen,
                char *msg, size_t msglen);

#endif /* TF_SCENE_LOCATE_H */
