/*
 * scene.c — reading scenes: load (libcyaml), overrides, build (scene_build.c,
 * which calls nothing here), and error messages that name file, line and
 * field (scene.h).
 */
#include "scene/scene.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/scene_build.h"
#include "scene/scene_locate.h"
#include "scene/scene_schema.h"
#include "scene/scene_set.h"

void tf_scene_free(tf_scene *s)
{
    if (s == NULL) {
        return;
    }
    tf_problem_release(&s->problem);
    free(s);
}

/* "a/b/block48.yaml" -> "block48" */
static void stem(const char *path, char *out, size_t outlen)
{
    const char *slash = strrchr(path, '/');
    snprintf(out, outlen, "%s", slash ? slash + 1 : path);
    out[strcspn(out, ".")] = '\0';
}

/* One path covers another when either is a prefix of the other at a dot. */
static int covers(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b), m = la < lb ? la : lb;
    return strncmp(a, b, m) == 0 && (la == lb || (la < lb ? b[la] : a[lb]) == '.');
}

static void report(const char *text, size_t len, const char *name, const char *const *sets,
                   const char (*set_paths)[128], size_t n_sets, const sd_issue *is, char *err,
                   size_t errlen)
{
    const char *sep = is->path[0] ? ": " : "";
    for (size_t k = n_sets; k-- > 0;) {
        if (is->path[0] && covers(set_paths[k], is->path)) {
            snprintf(err, errlen, "--set %s: %s%s%s", sets[k], is->path, sep, is->msg);
            return;
        }
    }
    int line = is->path[0] ? sd_locate(text, len, is->path) : 0;
    if (line > 0) {
        snprintf(err, errlen, "%s:%d: %s%s%s", name, line, is->path, sep, is->msg);
    } else {
        snprintf(err, errlen, "%s: %s%s%s", name, is->path, sep, is->msg);
    }
}

tf_scene *tf_scene_load_text(const char *text, size_t len, const char *name,
                             const char *const *sets, size_t n_sets, char *err, size_t errlen)
{
    sd_log log = {.len = 0};
    cyaml_config_t cfg = sd_config(&log);
    sd_scene *doc = NULL;
    if (cyaml_load_data((const uint8_t *)text, len, &cfg, &sd_scene_schema, (void **)&doc, NULL) !=
        CYAML_OK) {
        int line;
        char path[128], msg[256];
        sd_explain(text, len, &log, "", &line, path, sizeof path, msg, sizeof msg);
        snprintf(err, errlen, "%s:%d: %s%s%s", name, line, path, path[0] ? ": " : "", msg);
        return NULL;
    }
    if (doc == NULL) {
        snprintf(err, errlen, "%s: empty scene file", name);
        return NULL;
    }
    char (*set_paths)[128] = calloc(n_sets + 1, sizeof *set_paths);
    tf_scene *s = calloc(1, sizeof *s);
    int ok = set_paths && s;
    for (size_t k = 0; ok && k < n_sets; ++k) {
        char msg[256];
        if (sd_set(doc, sets[k], set_paths[k], sizeof set_paths[k], msg, sizeof msg) != 0) {
            snprintf(err, errlen, "--set %s: %s: %s", sets[k], set_paths[k], msg);
            ok = 0;
        }
    }
    if (ok) {
        sd_issue is;
        tf_problem *p = &s->problem;
        snprintf(p->source, sizeof p->source, "%s", name);
        stem(name, p->name, sizeof p->name);
        if (sd_build(doc, p, &s->fit, &is) != 0) {
            report(text, len, name, sets, (const char(*)[128])set_paths, n_sets, &is, err, errlen);
            ok = 0;
        }
    } else if (!set_paths || !s) {
        snprintf(err, errlen, "out of memory");
    }
    free(set_paths);
    sd_scene_free(doc);
    if (!ok) {
        tf_scene_free(s);
        return NULL;
    }
    return s;
}

tf_scene *tf_scene_load(const char *path, const char *const *sets, size_t n_sets, char *err,
                        size_t errlen)
{
    FILE *fp = fopen(path, "rb");
    if (fp == NULL) {
        snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return NULL;
    }
    size_t cap = 1 << 16, len = 0;
    char *text = malloc(cap);
    while (text != NULL) {
        len += fread(text + len, 1, cap - len, fp);
        if (len < cap) {
            break;
        }
        char *grown = realloc(text, cap *= 2);
        if (grown == NULL) {
            free(text);
        }
        text = grown;
    }
    int bad = text == NULL || ferror(fp);
    fclose(fp);
    if (bad) {
        free(text);
        snprintf(err, errlen, "%s: cannot read", path);
        return NULL;
    }
    tf_scene *s = tf_scene_load_text(text, len, path, sets, n_sets, err, errlen);
    free(text);
    return s;
}
