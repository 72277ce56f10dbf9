/*
 * scene_set.c — `--set key=value` overrides through the libcyaml schema
 * (scene_set.h).
 */
#include "scene/scene_set.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/scene_locate.h"
#include "scene/scene_strict.h"

static void *mem(size_t size)
{
    void *p = cyaml_mem(NULL, NULL, size);
    if (p != NULL) {
        memset(p, 0, size);
    }
    return p;
}

static size_t value_size(const cyaml_schema_value_t *v)
{
    if (v->flags & CYAML_FLAG_POINTER) {
        return sizeof(void *);
    }
    return v->type == CYAML_SEQUENCE_FIXED ? v->data_size * v->sequence.max : v->data_size;
}

static unsigned read_count(const uint8_t *base, const cyaml_schema_field_t *f)
{
    unsigned long long c = 0;
    memcpy(&c, base + f->count_offset, f->count_size); /* little-endian host */
    return (unsigned)c;
}

static void write_count(uint8_t *base, const cyaml_schema_field_t *f, unsigned c)
{
    unsigned long long v = c;
    memcpy(base + f->count_offset, &v, f->count_size);
}

/* Loads value text with schema v (as a top-level pointer value), after the
 * checks a scene file's values get (scene_strict.h). */
static void *load_value(tf_ctx *ctx, const cyaml_schema_value_t *root,
                        const cyaml_schema_value_t *v, char *path, size_t pathlen, const char *text,
                        unsigned *count)
{
    cyaml_schema_value_t top = *v;
    top.flags = (enum cyaml_flag)(top.flags | CYAML_FLAG_POINTER);
    top.flags = (enum cyaml_flag)(top.flags & ~CYAML_FLAG_OPTIONAL);
    int list = v->type == CYAML_SEQUENCE || v->type == CYAML_SEQUENCE_FIXED ||
               v->type == CYAML_FLAGS;
    int bracket = list && text[0] != '[';
    size_t len = strlen(text) + 2 * (size_t)bracket;
    char *buf = malloc(len + 1);
    *count = 0;
    if (buf == NULL) {
        tf_fail(ctx, "out of memory");
        return NULL;
    }
    snprintf(buf, len + 1, bracket ? "[%s]" : "%s", text);
    sd_strict_issue si;
    if (sd_strict_check(buf, len, v, path, &si) != 0) {
        if (si.path[0] != '\0') {
            snprintf(path, pathlen, "%s", si.path); /* the entry or key at fault */
        }
        tf_fail(ctx, "%s", si.msg);
        free(buf);
        return NULL;
    }
    sd_log log = {.len = 0};
    cyaml_config_t cfg = sd_config(&log);
    void *out = NULL;
    cyaml_err_t rc = cyaml_load_data((const uint8_t *)buf, len, &cfg, &top, &out,
                                     v->type == CYAML_SEQUENCE ? count : NULL);
    if (rc != CYAML_OK) {
        int line;
        char where[128], msg[256];
        sd_explain(root, buf, len, &log, path, &line, where, sizeof where, msg, sizeof msg);
        tf_fail(ctx, "%s", log.len ? msg : cyaml_strerror(rc));
    } else if (out == NULL) {
        tf_fail(ctx, "no value given");
    }
    free(buf);
    return out;
}

/* Replaces the value of field f in the mapping at base. */
static int assign(tf_ctx *ctx, const cyaml_schema_value_t *root, uint8_t *base,
                  const cyaml_schema_field_t *f, char *path, size_t pathlen, const char *text)
{
    const cyaml_schema_value_t *v = &f->value;
    unsigned count;
    void *out = load_value(ctx, root, v, path, pathlen, text, &count);
    if (out == NULL) {
        return -1;
    }
    cyaml_config_t cfg = sd_config(NULL);
    uint8_t *dst = base + f->data_offset;
    if (v->flags & CYAML_FLAG_POINTER || v->type == CYAML_SEQUENCE) {
        void *old;
        memcpy(&old, dst, sizeof old);
        cyaml_free(&cfg, v, old, v->type == CYAML_SEQUENCE ? read_count(base, f) : 0);
        memcpy(dst, &out, sizeof out);
        if (v->type == CYAML_SEQUENCE) {
            write_count(base, f, count);
        }
        return 0;
    }
    /* An embedded value: free what the old one owns (through a copy, since
     * libcyaml frees the block it is given), then move the new one in. */
    size_t size = value_size(v);
    cyaml_schema_value_t boxed = *v;
    boxed.flags = (enum cyaml_flag)(boxed.flags | CYAML_FLAG_POINTER);
    void *old = mem(size);
    if (old == NULL) {
        cyaml_free(&cfg, &boxed, out, 0);
        return tf_fail(ctx, "out of memory");
    }
    memcpy(old, dst, size);
    cyaml_free(&cfg, &boxed, old, 0);
    memcpy(dst, out, size);
    cyaml_mem(NULL, out, 0);
    return 0;
}

/* Entry k of the sequence field f of the mapping at base; k == count appends. */
static uint8_t *entry(uint8_t *base, const cyaml_schema_field_t *f, unsigned long k)
{
    unsigned n = read_count(base, f);
    uint8_t *arr;
    memcpy(&arr, base + f->data_offset, sizeof arr);
    size_t es = f->value.sequence.entry->data_size;
    if (k > n || k >= f->value.sequence.max) {
        return NULL;
    }
    if (k == n) {
        uint8_t *grown = cyaml_mem(NULL, arr, (n + 1) * es);
        if (grown == NULL) {
            return NULL;
        }
        memset(grown + n * es, 0, es);
        arr = grown;
        memcpy(base + f->data_offset, &arr, sizeof arr);
        write_count(base, f, n + 1);
    }
    return arr + k * es;
}

int sd_set(tf_ctx *ctx, const cyaml_schema_value_t *root, sd_scene *doc, const char *assignment,
           char *path, size_t pathlen)
{
    const char *eq = strchr(assignment, '=');
    char buf[256], *comp[SD_PATH_MAX];
    if (eq == NULL || eq == assignment || (size_t)(eq - assignment) >= sizeof buf) {
        snprintf(path, pathlen, "%s", assignment);
        return tf_fail(ctx, "expected key=value");
    }
    snprintf(path, pathlen, "%.*s", (int)(eq - assignment), assignment);
    snprintf(buf, sizeof buf, "%s", path);
    int n = sd_path_split(buf, comp);
    const cyaml_schema_value_t *v = root;
    uint8_t *base = (uint8_t *)doc;
    for (int k = 0; k < n; ++k) {
        const cyaml_schema_field_t *f = sd_field(v, comp[k]);
        if (f == NULL) {
            char names[256] = "";
            sd_names(v, names, sizeof names);
            return tf_fail(ctx, "no key '%s' here (known keys: %s)", comp[k], names);
        }
        if (k == n - 1) {
            return assign(ctx, root, base, f, path, pathlen, eq + 1);
        }
        if (f->value.type == CYAML_SEQUENCE) {
            char *end;
            unsigned long idx = strtoul(comp[k + 1], &end, 10);
            uint8_t *e = *end == '\0' ? entry(base, f, idx) : NULL;
            if (e == NULL) {
                return tf_fail(ctx,
                               "'%s' has %u entries: index '%s' is not one of them or the next",
                               f->key, read_count(base, f), comp[k + 1]);
            }
            if (++k == n - 1) {
                cyaml_schema_field_t whole = {.key = f->key, .data_offset = 0,
                                              .value = *f->value.sequence.entry};
                return assign(ctx, root, e, &whole, path, pathlen, eq + 1);
            }
            base = e;
            v = f->value.sequence.entry;
        } else if (f->value.type == CYAML_MAPPING) {
            uint8_t *sub = base + f->data_offset;
            if (f->value.flags & CYAML_FLAG_POINTER) {
                memcpy(&sub, base + f->data_offset, sizeof sub);
                if (sub == NULL && (sub = mem(f->value.data_size)) == NULL) {
                    return tf_fail(ctx, "out of memory");
                }
                memcpy(base + f->data_offset, &sub, sizeof sub);
            }
            base = sub;
            v = &f->value;
        } else {
            return tf_fail(ctx, "'%s' holds a value, not keys", f->key);
        }
    }
    return tf_fail(ctx, "expected key=value");
}
