/*
 * scene.c — reading scenes: load (libcyaml), overrides, build (scene_build.c,
 * which calls nothing here), and error messages that name file, line and
 * field (scene.h).
 */
#include "scene/scene.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/input_file.h"
#include "scene/scene_build.h"
#include "scene/scene_locate.h"
#include "scene/scene_schema.h"
#include "scene/scene_set.h"
#include "scene/scene_strict.h"

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

/* An override as messages show it: a value of 2,000 characters would push
 * the reason out of any message buffer. */
static const char *shown_set(const char *set, char *buf, size_t len)
{
    size_t n = strlen(set);
    if (n <= 80) {
        return set;
    }
    snprintf(buf, len, "%.60s... (%zu characters)", set, n);
    return buf;
}

/* One path covers another when either is a prefix of the other at a dot. */
static int covers(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b), m = la < lb ? la : lb;
    return strncmp(a, b, m) == 0 && (la == lb || (la < lb ? b[la] : a[lb]) == '.');
}

static void report(tf_ctx *ctx, const cyaml_schema_value_t *root, const char *text, size_t len,
                   const char *name, const char *const *sets, const char (*set_paths)[128],
                   size_t n_sets, const sd_issue *is)
{
    const char *sep = is->path[0] ? ": " : "";
    char buf[128];
    for (size_t k = n_sets; k-- > 0;) {
        if (is->path[0] && covers(set_paths[k], is->path)) {
            tf_fail(ctx, "--set %s: %s%s%s", shown_set(sets[k], buf, sizeof buf), is->path, sep,
                    is->msg);
            return;
        }
    }
    int line = is->path[0] ? sd_locate(root, text, len, is->path) : 0;
    if (line > 0) {
        tf_fail(ctx, "%s:%d: %s%s%s", name, line, is->path, sep, is->msg);
    } else {
        tf_fail(ctx, "%s: %s%s%s", name, is->path, sep, is->msg);
    }
}

/* Each cut's entry for the messages of a solve that fails at it
 * (tf_cut.where): the file and line of cuts.K, or the --set that gave it. */
static void label_cuts(const cyaml_schema_value_t *root, const char *text, size_t len,
                       const char *name, const char *const *sets,
                       const char (*set_paths)[128], size_t n_sets, tf_problem *p)
{
    char path[32], buf[128];
    for (size_t k = 0; k < p->n_cuts; ++k) {
        tf_cut *c = &p->cuts[k];
        snprintf(path, sizeof path, "cuts.%zu", k);
        size_t s = n_sets;
        while (s > 0 && !covers(set_paths[s - 1], path)) {
            s--;
        }
        int line = s > 0 ? 0 : sd_locate(root, text, len, path);
        char label[1024];
        if (s > 0) {
            snprintf(label, sizeof label, "--set %s: %s", shown_set(sets[s - 1], buf, sizeof buf),
                     path);
        } else if (line > 0) {
            snprintf(label, sizeof label, "%s:%d: %s", name, line, path);
        } else {
            snprintf(label, sizeof label, "%s: %s", name, path);
        }
        snprintf(c->where, sizeof c->where, "%.*s", (int)sizeof c->where - 1, label);
    }
}

/* The --set paths override the value at path (or a mapping above it). */
static int overridden(const char (*set_paths)[128], size_t n_sets, const char *path)
{
    for (size_t k = 0; k < n_sets; ++k) {
        if (covers(set_paths[k], path)) {
            return 1;
        }
    }
    return 0;
}

static void warn_node(tf_scene *s, const char *name, const char *path, uint32_t number,
                      const char *what)
{
    const tf_problem *p = &s->problem;
    const double *x = p->cloud.xyz + 3 * (size_t)(number - 1);
    size_t used = strlen(s->warnings);
    snprintf(s->warnings + used, sizeof s->warnings - used,
             "%s: %s: node %u was numbered on the file's grid; with the grid overridden it is "
             "the node at (%g, %g, %g) mm: give %s by position to follow the grid\n",
             name, path, number, x[0], x[1], x[2], what);
}

/* Node numbers in the file name other places once --set changes the grid
 * (the numbering follows the grid): say so for each one not overridden too. */
static void node_number_warnings(const sd_scene *doc, const char (*set_paths)[128],
                                 size_t n_sets, const char *name, tf_scene *s)
{
    char path[128];
    if (!overridden(set_paths, n_sets, "geometry.grid")) {
        return;
    }
    for (unsigned k = 0; k < doc->contact_count; ++k) {
        snprintf(path, sizeof path, "contact.%u.node", k);
        if (doc->contact[k].node && !overridden(set_paths, n_sets, path)) {
            warn_node(s, name, path, *doc->contact[k].node,
                      "the contact point (at: [x, y, z], or its patch alone: the centre)");
        }
    }
    for (unsigned k = 0; k < doc->loads_count; ++k) {
        snprintf(path, sizeof path, "loads.%u.node", k);
        if (doc->loads[k].node && !overridden(set_paths, n_sets, path)) {
            warn_node(s, name, path, *doc->loads[k].node, "the point force (at: [x, y, z])");
        }
    }
    if (doc->outputs.nodes_count > 0 && !overridden(set_paths, n_sets, "outputs.nodes")) {
        warn_node(s, name, "outputs.nodes", doc->outputs.nodes[0],
                  "the outputs (select: points)");
    }
}

/* A warning line into s->warnings. */
static void warn(tf_scene *s, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void warn(tf_scene *s, const char *fmt, ...)
{
    size_t used = strlen(s->warnings);
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(s->warnings + used, sizeof s->warnings - used, fmt, ap);
    va_end(ap);
    if (n >= 0 && used + (size_t)n + 1 < sizeof s->warnings) {
        strcat(s->warnings, "\n");
    }
}

/* The repairs made to an organ's mesh (tf_mesh_geometry.notes) as the
 * scene's notes: "scene: geometry.surface: mesh: what was done". */
static void mesh_notes(const char *name, tf_scene *s)
{
    const tf_mesh_geometry *g = tf_problem_mesh(&s->problem);
    if (g == NULL) {
        return;
    }
    for (const char *line = g->notes; *line != '\0'; line += strcspn(line, "\n")) {
        line += *line == '\n';
        int len = (int)strcspn(line, "\n");
        size_t used = strlen(s->notes);
        if (len > 0) {
            snprintf(s->notes + used, sizeof s->notes - used, "%s: geometry.surface: %s: %.*s\n",
                     name, g->path, len, line);
        }
    }
}

/* Legal values a tissue model hardly ever has, said rather than refused: a
 * modulus stiffer than 1 GPa (bone is 10 to 20 GPa; soft tissue 10^-3 to 1
 * MPa: E in Pa rather than MPa?), an organ under 1 cm or over 1 m across
 * (a mesh in other units than its scale says?), a contact point farther
 * from the organ than its site's radius (it acts at the nearest vertex). */
static void plausibility_warnings(const sd_scene *doc, const char *name, tf_scene *s)
{
    const tf_problem *p = &s->problem;
    double young = NAN, nu;
    if (p->material.law != NULL && p->material.law->moduli != NULL) {
        p->material.law->moduli(p->material.p, &young, &nu);
    }
    if (young > 1000) {
        warn(s, "%s: material: Young's modulus %g MPa, stiffer than 1 GPa (soft tissue: 0.001 to 1 "
                "MPa): the unit is MPa, not Pa",
             name, young);
    }
    if (tf_problem_mesh(p) == NULL) {
        return;
    }
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < p->cloud.n; ++i) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = fmin(lo[a], p->cloud.xyz[3 * i + a]);
            hi[a] = fmax(hi[a], p->cloud.xyz[3 * i + a]);
        }
    }
    double span = hypot(hypot(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
    if (span < 10 || span > 1000) {
        warn(s, "%s: geometry.surface: the organ is %.4g mm across (its box's diagonal), %s than any "
                "organ (%s): is "
                "geometry.surface.scale right (mm per file unit)?",
             name, span, span < 10 ? "smaller" : "larger",
             span < 10 ? "1 cm" : "1 m");
    }
    for (unsigned k = 0; k < doc->contact_count && k < p->n_contacts; ++k) {
        const sd_site *site = doc->contact[k].site;
        if (site == NULL) {
            continue;
        }
        const double *x = p->cloud.xyz + 3 * (size_t)p->contacts[k].node;
        double d = hypot(hypot(x[0] - site->point[0], x[1] - site->point[1]),
                         x[2] - site->point[2]);
        if (d > site->radius) {
            warn(s, "%s: contact.%u.site.point: %.4g mm from the organ's surface, more than the "
                    "site's radius %g mm: the contact acts at the nearest vertex (%g, %g, %g) mm",
                 name, k, d, site->radius, x[0], x[1], x[2]);
        }
    }
}

tf_scene *tf_scene_load_text(tf_ctx *ctx, const char *text, size_t len, const char *name,
                             const char *const *sets, size_t n_sets)
{
    sd_schema schema;
    if (sd_schema_init(&schema) != 0) {
        tf_fail(ctx,
                "%s: the material laws have more parameter keys than a scene holds "
                "(SD_MATERIAL_KEYS)",
                name);
        return NULL;
    }
    const cyaml_schema_value_t *root = &schema.root;
    sd_strict_issue si;
    if (sd_strict_check(text, len, root, "", &si) != 0) {
        tf_fail(ctx, "%s:%d: %s%s%s", name, si.line, si.path, si.path[0] ? ": " : "", si.msg);
        return NULL;
    }
    sd_log log = {.len = 0};
    cyaml_config_t cfg = sd_config(&log);
    sd_scene *doc = NULL;
    if (cyaml_load_data((const uint8_t *)text, len, &cfg, root, (void **)&doc, NULL) != CYAML_OK) {
        int line;
        char path[128], msg[256];
        sd_explain(root, text, len, &log, "", &line, path, sizeof path, msg, sizeof msg);
        tf_fail(ctx, "%s:%d: %s%s%s", name, line, path, path[0] ? ": " : "", msg);
        return NULL;
    }
    if (doc == NULL) {
        tf_fail(ctx, "%s: empty scene file", name);
        return NULL;
    }
    char (*set_paths)[128] = calloc(n_sets + 1, sizeof *set_paths);
    tf_scene *s = calloc(1, sizeof *s);
    int ok = set_paths && s;
    for (size_t k = 0; ok && k < n_sets; ++k) {
        char buf[128];
        if (sd_set(ctx, root, doc, sets[k], set_paths[k], sizeof set_paths[k]) != 0) {
            tf_fail(ctx, "--set %s: %s: %s", shown_set(sets[k], buf, sizeof buf), set_paths[k],
                    ctx->err);
            ok = 0;
        }
    }
    if (ok) {
        sd_issue is;
        tf_problem *p = &s->problem;
        snprintf(p->source, sizeof p->source, "%s", name);
        stem(name, p->name, sizeof p->name);
        if (sd_build(doc, p, &s->fit, &is) != 0) {
            report(ctx, root, text, len, name, sets, (const char(*)[128])set_paths, n_sets, &is);
            ok = 0;
        } else {
            label_cuts(root, text, len, name, sets, (const char(*)[128])set_paths, n_sets, p);
            node_number_warnings(doc, (const char(*)[128])set_paths, n_sets, name, s);
            plausibility_warnings(doc, name, s);
            mesh_notes(name, s);
        }
    } else if (!set_paths || !s) {
        tf_fail(ctx, "out of memory");
    }
    free(set_paths);
    sd_scene_free(root, doc);
    if (!ok) {
        tf_scene_free(s);
        return NULL;
    }
    return s;
}

void tf_scene_key_values(const char *path, char *out, size_t outlen)
{
    sd_schema schema;
    out[0] = '\0';
    const cyaml_schema_value_t *v =
        sd_schema_init(&schema) == 0 ? sd_schema_at(&schema.root, path) : NULL;
    if (v != NULL && (v->type == CYAML_ENUM || v->type == CYAML_FLAGS)) {
        sd_names(v, out, outlen);
    }
}

/* The bytes of a scene file (base/input_file.h: a regular file of at most
 * TF_SCENE_MAX_BYTES).  Returns the text (NUL-terminated, *len bytes), or
 * NULL with a message. */
static char *read_scene(tf_ctx *ctx, const char *path, size_t *len)
{
    return tf_input_file_read(ctx, path, "scene", TF_SCENE_MAX_BYTES, len);
}

tf_scene *tf_scene_load(tf_ctx *ctx, const char *path, const char *const *sets, size_t n_sets)
{
    size_t len = 0;
    char *text = read_scene(ctx, path, &len);
    if (text == NULL) {
        return NULL;
    }
    tf_scene *s = tf_scene_load_text(ctx, text, len, path, sets, n_sets);
    free(text);
    return s;
}
