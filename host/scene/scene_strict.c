/*
 * scene_strict.c — strict values, one document, no aliases, syntax errors
 * with lines (scene_strict.h).  A walk over libyaml's events that keeps,
 * for each open mapping or sequence, the schema of its values and the path
 * that leads to it.
 */
#include "scene/scene_strict.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <yaml.h>

#include "scene/scene_ranges.h"
#include "scene/scene_schema.h"

/* Scene schemas nest about six deep; deeper text is not a scene. */
#define DEPTH 32

typedef struct frame {
    int is_map;
    const cyaml_schema_value_t *v;     /* this collection's schema, NULL when unknown */
    const cyaml_schema_value_t *value; /* mapping: schema of the value after the key read */
    int have_key;
    unsigned index;                    /* sequence: the next entry's index */
    size_t mark;                       /* path length before the current value */
} frame;

typedef struct walk {
    const cyaml_schema_value_t *root;
    frame f[DEPTH];
    int depth;
    char path[sizeof ((sd_strict_issue *)0)->path];
    sd_strict_issue *is;
} walk;

static int fail(walk *w, size_t line0, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int fail(walk *w, size_t line0, const char *fmt, ...)
{
    va_list ap;
    w->is->line = (int)line0 + 1;
    snprintf(w->is->path, sizeof w->is->path, "%s", w->path);
    va_start(ap, fmt);
    vsnprintf(w->is->msg, sizeof w->is->msg, fmt, ap);
    va_end(ap);
    return -1;
}

static void append(walk *w, const char *comp)
{
    size_t used = strlen(w->path);
    snprintf(w->path + used, sizeof w->path - used, "%s%s", used ? "." : "", comp);
}

/* The schema of the value that starts now (NULL when unknown); its path
 * component is appended (a mapping's key was appended with the key). */
static const cyaml_schema_value_t *enter(walk *w)
{
    if (w->depth == 0) {
        return w->root;
    }
    frame *f = &w->f[w->depth - 1];
    if (f->is_map) {
        return f->value;
    }
    char idx[16];
    f->mark = strlen(w->path);
    snprintf(idx, sizeof idx, "%u", f->index);
    append(w, idx);
    if (f->v == NULL || f->v->type == CYAML_FLAGS) {
        return NULL;
    }
    return f->v->sequence.entry;
}

/* After a value: its path component goes, the next entry or key follows. */
static void leave(walk *w)
{
    if (w->depth == 0) {
        return;
    }
    frame *f = &w->f[w->depth - 1];
    w->path[f->mark] = '\0';
    if (f->is_map) {
        f->have_key = 0;
    } else {
        f->index++;
    }
}

/* The text of a scalar for a message: at most 40 bytes, printable. */
static void shown(const unsigned char *s, size_t len, char *out, size_t outlen)
{
    size_t k = 0;
    for (size_t i = 0; i < len && i < 40 && k + 4 < outlen; ++i) {
        out[k++] = isprint(s[i]) ? (char)s[i] : '?';
    }
    if (len > 40 && k + 4 < outlen) {
        memcpy(out + k, "...", 3);
        k += 3;
    }
    out[k] = '\0';
}

static size_t digits(const char *s, size_t len, size_t i)
{
    size_t n = 0;
    while (i + n < len && isdigit((unsigned char)s[i + n])) {
        n++;
    }
    return n;
}

/* [-+]digits[.digits][(e|E)[-+]digits], at least one digit before the exponent. */
static int is_number(const char *s, size_t len)
{
    size_t i = len > 0 && (s[0] == '-' || s[0] == '+');
    size_t whole = digits(s, len, i), frac = 0;
    i += whole;
    if (i < len && s[i] == '.') {
        frac = digits(s, len, i + 1);
        i += 1 + frac;
    }
    if (whole + frac == 0) {
        return 0;
    }
    if (i < len && (s[i] == 'e' || s[i] == 'E')) {
        i += 1 + (i + 1 < len && (s[i + 1] == '-' || s[i + 1] == '+'));
        size_t e = digits(s, len, i);
        if (e == 0) {
            return 0;
        }
        i += e;
    }
    return i == len;
}

static int check_number(walk *w, size_t line0, const char *s, size_t len, const char *text)
{
    if (!is_number(s, len)) {
        return fail(w, line0, "'%s' is not a number (write it like 0.45, -3 or 3.2e-1, with "
                    "nothing after it)", text);
    }
    char buf[64], msg[200];
    if (len >= sizeof buf) {
        return fail(w, line0, "'%s' has more digits than a double holds", text);
    }
    memcpy(buf, s, len);
    buf[len] = '\0';
    if (sd_range_check(w->path, strtod(buf, NULL), msg, sizeof msg) != 0) {
        return fail(w, line0, "%s", msg);
    }
    return 0;
}

static int check_whole(walk *w, size_t line0, const char *s, size_t len, const char *text,
                       int is_signed)
{
    size_t sign = is_signed && len > 0 && s[0] == '-';
    size_t n = digits(s, len, sign);
    if (n == 0 || sign + n != len) {
        return fail(w, line0, "'%s' is not a %swhole number (digits only)", text,
                    is_signed ? "" : "non-negative ");
    }
    if (n > 1 && s[sign] == '0') {
        return fail(w, line0, "'%s' has a leading zero (which YAML 1.1 reads as octal): write "
                    "the number without it", text);
    }
    return 0;
}

static int check_bool(walk *w, size_t line0, const char *s, size_t len, const char *text)
{
    static const char *const words[] = {"true", "false", "yes", "no", "on", "off"};
    for (size_t k = 0; k < sizeof words / sizeof words[0]; ++k) {
        if (strlen(words[k]) == len && strncasecmp(words[k], s, len) == 0) {
            return 0;
        }
    }
    return fail(w, line0, "'%s' is not true or false", text);
}

static int scalar(walk *w, const yaml_event_t *ev)
{
    const char *s = (const char *)ev->data.scalar.value;
    size_t len = ev->data.scalar.length, line0 = ev->start_mark.line;
    frame *f = w->depth > 0 ? &w->f[w->depth - 1] : NULL;
    char text[64];
    shown(ev->data.scalar.value, len, text, sizeof text);
    if (f != NULL && f->is_map && !f->have_key) {
        const cyaml_schema_field_t *field =
            f->v != NULL && memchr(s, '\0', len) == NULL ? sd_field(f->v, s) : NULL;
        f->mark = strlen(w->path);
        append(w, text);
        f->value = field ? &field->value : NULL;
        f->have_key = 1;
        return 0;
    }
    const cyaml_schema_value_t *v = enter(w);
    int rc = 0;
    if (v != NULL && v->type == CYAML_FLOAT) {
        rc = check_number(w, line0, s, len, text);
    } else if (v != NULL && (v->type == CYAML_UINT || v->type == CYAML_INT)) {
        rc = check_whole(w, line0, s, len, text, v->type == CYAML_INT);
    } else if (v != NULL && v->type == CYAML_BOOL) {
        rc = check_bool(w, line0, s, len, text);
    }
    leave(w);
    return rc;
}

static const char *kind_of(const yaml_event_t *ev)
{
    return ev->type == YAML_MAPPING_START_EVENT    ? "a mapping"
           : ev->type == YAML_SEQUENCE_START_EVENT ? "a list"
                                                   : "a single value";
}

/* The document's own value and the keys of mappings, which libcyaml's
 * messages cannot place (they have no enclosing line). */
static int check_shape(walk *w, const yaml_event_t *ev)
{
    const frame *f = w->depth > 0 ? &w->f[w->depth - 1] : NULL;
    if (f != NULL && f->is_map && !f->have_key && ev->type != YAML_SCALAR_EVENT) {
        return fail(w, ev->start_mark.line, "a key must be a plain word, not %s", kind_of(ev));
    }
    if (f == NULL && w->root->type == CYAML_MAPPING && ev->type != YAML_MAPPING_START_EVENT) {
        return fail(w, ev->start_mark.line, "expected a mapping of keys (%s), got %s",
                    w->path[0] ? "key: value" : "name:, geometry:, ...", kind_of(ev));
    }
    return 0;
}

static int open_collection(walk *w, const yaml_event_t *ev, int is_map)
{
    if (w->depth == DEPTH) {
        return fail(w, ev->start_mark.line, "nested more than %d levels deep: not a scene", DEPTH);
    }
    if (check_shape(w, ev) != 0) {
        return -1;
    }
    const cyaml_schema_value_t *v = enter(w);
    int fits = v != NULL && (is_map ? v->type == CYAML_MAPPING
                                    : v->type == CYAML_SEQUENCE ||
                                          v->type == CYAML_SEQUENCE_FIXED ||
                                          v->type == CYAML_FLAGS);
    w->f[w->depth++] = (frame){.is_map = is_map, .v = fits ? v : NULL};
    return 0;
}

/* The line (0-based) of a byte offset. */
static size_t line_of(const char *text, size_t len, size_t offset)
{
    size_t line = 0;
    for (size_t i = 0; i < offset && i < len; ++i) {
        line += text[i] == '\n';
    }
    return line;
}

static int syntax_error(walk *w, const yaml_parser_t *p, const char *text, size_t len)
{
    size_t line0 = p->error == YAML_READER_ERROR ? line_of(text, len, p->problem_offset)
                                                 : p->problem_mark.line;
    w->path[0] = '\0';
    return fail(w, line0, "YAML syntax error: %s%s%s", p->problem ? p->problem : "unreadable",
                p->context ? " " : "", p->context ? p->context : "");
}

static int event(walk *w, const yaml_event_t *ev, int *documents)
{
    switch (ev->type) {
    case YAML_DOCUMENT_START_EVENT:
        if (++*documents > 1) {
            return fail(w, ev->start_mark.line,
                        "a second YAML document starts here: a scene file holds one");
        }
        return 0;
    case YAML_ALIAS_EVENT:
        enter(w);
        return fail(w, ev->start_mark.line,
                    "aliases (*%s) are not supported in scenes: write the value out",
                    (const char *)ev->data.alias.anchor);
    case YAML_SCALAR_EVENT:
        return check_shape(w, ev) != 0 ? -1 : scalar(w, ev);
    case YAML_SEQUENCE_START_EVENT:
    case YAML_MAPPING_START_EVENT:
        return open_collection(w, ev, ev->type == YAML_MAPPING_START_EVENT);
    case YAML_SEQUENCE_END_EVENT:
    case YAML_MAPPING_END_EVENT:
        if (w->depth > 0) {
            w->depth--;
            leave(w);
        }
        return 0;
    default:
        return 0;
    }
}

int sd_strict_check(const char *text, size_t len, const cyaml_schema_value_t *root,
                    const char *base, sd_strict_issue *is)
{
    walk w = {.root = root, .depth = 0, .is = is};
    snprintf(w.path, sizeof w.path, "%s", base);
    yaml_parser_t p;
    if (!yaml_parser_initialize(&p)) {
        snprintf(is->msg, sizeof is->msg, "out of memory");
        is->line = 0;
        is->path[0] = '\0';
        return -1;
    }
    yaml_parser_set_input_string(&p, (const unsigned char *)text, len);
    int rc = 0, documents = 0, done = 0;
    while (rc == 0 && !done) {
        yaml_event_t ev;
        if (!yaml_parser_parse(&p, &ev)) {
            rc = syntax_error(&w, &p, text, len);
            break;
        }
        done = ev.type == YAML_STREAM_END_EVENT;
        rc = event(&w, &ev, &documents);
        yaml_event_delete(&ev);
    }
    yaml_parser_delete(&p);
    return rc;
}
