/*
 * scene_locate.c — lines of values in scene files, and libcyaml's errors in
 * plain words (scene_locate.h).
 */
#include "scene/scene_locate.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Schema copies made along a path; freed together. */
typedef struct arena {
    void *blocks[2 * SD_PATH_MAX + 2];
    int n;
} arena;

static void *arena_alloc(arena *a, size_t size)
{
    if (a->n == (int)(sizeof a->blocks / sizeof a->blocks[0])) {
        return NULL;
    }
    void *p = calloc(1, size);
    if (p != NULL) {
        a->blocks[a->n++] = p;
    }
    return p;
}

static void arena_free(arena *a)
{
    while (a->n > 0) {
        free(a->blocks[--a->n]);
    }
}

static const cyaml_schema_field_t no_fields[] = {CYAML_FIELD_END};

/* A value schema that no YAML value of the original kind satisfies:
 * scalars must suddenly be mappings, collections must be numbers. */
static cyaml_schema_value_t poisoned(const cyaml_schema_value_t *v)
{
    cyaml_schema_value_t p = *v;
    switch (v->type) {
    case CYAML_MAPPING:
    case CYAML_SEQUENCE:
    case CYAML_SEQUENCE_FIXED:
    case CYAML_FLAGS:
        p.type = CYAML_FLOAT;
        p.data_size = sizeof(double);
        break;
    default:
        p.type = CYAML_MAPPING;
        p.mapping.fields = no_fields;
        break;
    }
    return p;
}

/* Copies the schema v along comp[0..n) with the last value poisoned.  A key
 * the schema lacks is added (to find an unknown key).  In a sequence of
 * mappings, entry_only limits the sequence to comp[0] entries, so the load
 * stops at that entry; otherwise the path continues into every entry and
 * the first entry holding the key stops it. */
static int poison_path(arena *a, const cyaml_schema_value_t *v, char **comp, int n,
                       int entry_only, cyaml_schema_value_t *out)
{
    if (n == 0) {
        *out = poisoned(v);
        return 0;
    }
    *out = *v;
    if (v->type == CYAML_SEQUENCE) {
        char *end;
        unsigned long k = strtoul(comp[0], &end, 10);
        if (*end != '\0') {
            return -1;
        }
        if (entry_only || n == 1) {
            out->sequence.min = 0;
            out->sequence.max = (uint32_t)k;
            return 0;
        }
        cyaml_schema_value_t *entry = arena_alloc(a, sizeof *entry);
        out->sequence.entry = entry;
        return entry ? poison_path(a, v->sequence.entry, comp + 1, n - 1, entry_only, entry) : -1;
    }
    if (v->type == CYAML_SEQUENCE_FIXED) {
        *out = poisoned(v); /* the whole fixed-length list */
        return 0;
    }
    if (v->type != CYAML_MAPPING) {
        return -1;
    }
    size_t nf = 0;
    while (v->mapping.fields[nf].key != NULL) {
        nf++;
    }
    cyaml_schema_field_t *f = arena_alloc(a, (nf + 2) * sizeof *f);
    if (f == NULL) {
        return -1;
    }
    memcpy(f, v->mapping.fields, nf * sizeof *f);
    out->mapping.fields = f;
    for (size_t k = 0; k < nf; ++k) {
        if (strcmp(f[k].key, comp[0]) == 0) {
            return poison_path(a, &v->mapping.fields[k].value, comp + 1, n - 1, entry_only,
                               &f[k].value);
        }
    }
    if (n != 1) {
        return -1;
    }
    static const cyaml_schema_value_t anything = {CYAML_VALUE_FLOAT(CYAML_FLAG_OPTIONAL, double)};
    f[nf].key = comp[0];
    f[nf].value = poisoned(&anything);
    return 0;
}

/* Innermost line of a libcyaml backtrace, or 0. */
static int backtrace_line(const char *log)
{
    const char *bt = strstr(log, "Backtrace:");
    const char *l = bt ? strstr(bt, "(line: ") : NULL;
    return l ? atoi(l + 7) : 0;
}

static int locate_mode(const cyaml_schema_value_t *root, const char *text, size_t len,
                       const char *path, int entry_only)
{
    char buf[256], *comp[SD_PATH_MAX];
    snprintf(buf, sizeof buf, "%s", path);
    int n = sd_path_split(buf, comp), line = 0;
    arena a = {.n = 0};
    cyaml_schema_value_t top;
    if (n > 0 && poison_path(&a, root, comp, n, entry_only, &top) == 0) {
        sd_log log = {.len = 0};
        cyaml_config_t cfg = sd_config(&log);
        void *data = NULL;
        if (cyaml_load_data((const uint8_t *)text, len, &cfg, &top, &data, NULL) == CYAML_OK) {
            cyaml_free(&cfg, root, data, 0); /* the path is not in the text */
        } else {
            line = backtrace_line(log.text);
        }
    }
    arena_free(&a);
    return line;
}

int sd_locate(const cyaml_schema_value_t *root, const char *text, size_t len, const char *path)
{
    return locate_mode(root, text, len, path, 1);
}

/* Path of the value a backtrace points at: its lines run innermost first,
 * "  in mapping field 'KEY' (line: ...)" or "  in sequence entry 'N' ...";
 * a bare "  in mapping (...)" has no name.  libcyaml counts an entry once
 * it has started reading it, so N is one more than the entry's index (a
 * surplus entry, reported before it is counted, is dropped from the path
 * by the caller). */
static void backtrace_path(const char *log, char *path, size_t pathlen)
{
    char comps[SD_PATH_MAX][64];
    int n = 0;
    const char *p = strstr(log, "Backtrace:");
    while (p != NULL && (p = strchr(p, '\n')) != NULL && strncmp(++p, "  in ", 5) == 0 &&
           n < SD_PATH_MAX) {
        const char *eol = p + strcspn(p, "\n"), *f = strstr(p, "field '"), *e = strstr(p, "entry '");
        int is_field = f != NULL && f < eol; /* no arithmetic on a NULL f (UB) */
        const char *q = is_field ? f + 7 : e != NULL && e < eol ? e + 7 : NULL;
        const char *end = q ? strchr(q, '\'') : NULL;
        if (end != NULL && end < eol && is_field) {
            snprintf(comps[n++], sizeof comps[0], "%.*s", (int)(end - q), q);
        } else if (end != NULL && end < eol) {
            snprintf(comps[n++], sizeof comps[0], "%ld", strtol(q, NULL, 10) - 1);
        }
    }
    size_t used = 0;
    path[0] = '\0';
    for (int k = n - 1; k >= 0 && used < pathlen; --k) {
        used += (size_t)snprintf(path + used, pathlen - used, "%s%s", used ? "." : "", comps[k]);
    }
}

/* Drops the last component of a path. */
static void path_parent(char *path)
{
    char *dot = strrchr(path, '.');
    if (dot != NULL) {
        *dot = '\0';
    } else {
        path[0] = '\0';
    }
}

/* Text after the first occurrence of prefix in s, up to the line end. */
static int after(const char *s, const char *prefix, char *out, size_t outlen)
{
    const char *p = strstr(s, prefix);
    if (p == NULL) {
        return 0;
    }
    p += strlen(prefix);
    size_t k = strcspn(p, "\n");
    while (k > 0 && (p[k - 1] == '.' || p[k - 1] == ' ')) {
        k--;
    }
    snprintf(out, outlen, "%.*s", (int)k, p);
    return 1;
}

static const char *event_name(const char *ev)
{
    if (strncmp(ev, "SEQUENCE", 8) == 0) {
        return "a list";
    }
    if (strncmp(ev, "MAPPING", 7) == 0) {
        return "a mapping";
    }
    return "a single value";
}

static const char *type_name(const char *t)
{
    if (strcmp(t, "FLOAT") == 0) {
        return "a number";
    }
    if (strcmp(t, "INT") == 0 || strcmp(t, "UINT") == 0) {
        return "a whole number";
    }
    if (strcmp(t, "SEQUENCE") == 0 || strcmp(t, "SEQUENCE_FIXED") == 0 || strcmp(t, "FLAGS") == 0) {
        return "a list";
    }
    if (strcmp(t, "MAPPING") == 0) {
        return "a mapping";
    }
    return "a single value";
}

/* "Invalid FLOAT value: abc", "Invalid ENUM value: w+", "Invalid uint64_t
 * value: 'x'": the offending text, unquoted. */
static int invalid_value(const char *log, char *arg, size_t len)
{
    const char *p = strstr(log, "Invalid ");
    const char *v = p ? strstr(p, " value: ") : NULL;
    const char *nl = p ? strchr(p, '\n') : NULL;
    if (v == NULL || (nl != NULL && nl < v)) {
        return 0;
    }
    v += 8;
    size_t k = strcspn(v, "\n");
    if (k >= 2 && v[0] == '\'' && v[k - 1] == '\'') {
        v++;
        k -= 2;
    }
    snprintf(arg, len, "%.*s", (int)k, v);
    return 1;
}

void sd_explain(const cyaml_schema_value_t *root, const char *text, size_t len,
                const sd_log *log, const char *base, int *line, char *path, size_t pathlen,
                char *msg, size_t msglen)
{
    const char *t = log->text;
    char arg[160], names[256], rel[128];
    *line = backtrace_line(t);
    backtrace_path(t, rel, sizeof rel);
    snprintf(path, pathlen, "%s%s%s", base, base[0] && rel[0] ? "." : "", rel);
    if (after(t, "Unexpected key: ", arg, sizeof arg)) {
        const cyaml_schema_value_t *v = path[0] ? sd_schema_at(root, path) : root;
        names[0] = '\0';
        if (v != NULL) {
            sd_names(v, names, sizeof names);
        }
        size_t used = strlen(path);
        snprintf(path + used, pathlen - used, "%s%s", used ? "." : "", arg);
        int exact = locate_mode(root, text, len, path, 0);
        *line = exact ? exact : *line;
        snprintf(msg, msglen, "unknown key '%s' (known keys here: %s)", arg, names);
    } else if (after(t, "Missing required mapping field: ", arg, sizeof arg)) {
        path_parent(path);
        snprintf(msg, msglen, "required key '%s' is missing", arg);
    } else if (after(t, "Mapping field already seen: ", arg, sizeof arg)) {
        snprintf(msg, msglen, "key given twice");
    } else if (invalid_value(t, arg, sizeof arg) || after(t, "Unknown flag: ", arg, sizeof arg)) {
        const cyaml_schema_value_t *v = sd_schema_at(root, path);
        names[0] = '\0';
        if (v != NULL) {
            sd_names(v, names, sizeof names);
        }
        if (names[0] != '\0') {
            snprintf(msg, msglen, "'%s' is not one of: %s", arg, names);
        } else {
            snprintf(msg, msglen, "'%s' is not %s", arg,
                     v == NULL                  ? "valid here"
                     : v->type == CYAML_FLOAT   ? "a number"
                     : v->type == CYAML_BOOL    ? "true or false"
                     : v->type == CYAML_STRING  ? "a valid string"
                                                : "a non-negative whole number");
        }
    } else if (after(t, "Insufficient entries ", arg, sizeof arg)) {
        path_parent(path);
        snprintf(msg, msglen, "too few entries %s", arg);
    } else if (after(t, "Excessive entries ", arg, sizeof arg)) {
        path_parent(path);
        snprintf(msg, msglen, "too many entries %s", arg);
    } else if (after(t, "Expecting ", arg, sizeof arg)) {
        char want[32] = "", *got = strstr(arg, "got event: ");
        sscanf(arg, "%31[A-Z_]", want);
        snprintf(msg, msglen, "expected %s, got %s", type_name(want),
                 got ? event_name(got + 11) : "something else");
    } else if (after(t, "STRING length > ", arg, sizeof arg)) {
        snprintf(msg, msglen, "at most %ld characters", strtol(arg, NULL, 10));
    } else if (after(t, "STRING length < ", arg, sizeof arg)) {
        snprintf(msg, msglen, "at least %ld characters", strtol(arg, NULL, 10));
    } else if (after(t, "libyaml: ", arg, sizeof arg)) {
        snprintf(msg, msglen, "YAML syntax error: %s", arg);
    } else if (after(t, "Load: ", arg, sizeof arg) && arg[0] != '\0' &&
               strncmp(arg, "Backtrace", 9) != 0) {
        snprintf(msg, msglen, "%s", arg);
    } else {
        snprintf(msg, msglen, "not a valid scene");
    }
}
