/*
 * scene_strict.h — what libcyaml lets through, refused before it reads.
 *
 * libcyaml converts numbers with strtod/strtoull and ignores what follows
 * ("nu: 0,45" is 0, "E: 0.32 MPa" is 0.32), reads integers in C syntax
 * ("011" is octal 9, "-1" wraps to 2^64 - 1, "61.9" is 61), takes any word
 * but a few as `true`, reads only the first YAML document of a file, and
 * words YAML syntax errors without a line.  This pass walks the YAML events
 * (libyaml) beside the scene schema, so every value of every key — present
 * and future — is held to the same rules:
 *
 *   numbers    [-+]digits[.digits][e[-+]digits] and nothing else, within
 *              the key's range (scene_ranges.h);
 *   whole      digits only, no sign (unless the key is signed), no leading 0;
 *   booleans   true/false (yes/no, on/off), any case;
 *   documents  exactly one; no aliases (*name);
 *   syntax     errors (bad UTF-8, control characters) with their line.
 *
 * Keys the schema lacks and values of the wrong kind are left to libcyaml,
 * whose messages name them (scene_locate.h).
 */
#ifndef TF_SCENE_STRICT_H
#define TF_SCENE_STRICT_H

#include <stddef.h>

#include <cyaml/cyaml.h>

typedef struct sd_strict_issue {
    int line;        /* 1-based; 0 when unknown */
    char path[128];  /* the value's path, "" for the document itself */
    char msg[256];
} sd_strict_issue;

/* Checks YAML text whose root value has schema root and lies at path base
 * ("" for a scene file, "material.E" for the value of --set material.E=...).
 * Returns 0, or -1 with the issue. */
int sd_strict_check(const char *text, size_t len, const cyaml_schema_value_t *root,
                    const char *base, sd_strict_issue *is);

#endif /* TF_SCENE_STRICT_H */
