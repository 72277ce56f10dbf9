/*
 * nist_strd.c — NIST StRD file reader (see nist_strd.h).
 *
 * The files are fixed in layout but written by hand: the header's
 * "File Format" block gives the line ranges of the starting values, the
 * certified values and the data, and the free text around them varies
 * (capitalisation, "Predictor" or "Predictor Variable", spacing).  The
 * reader trusts the line ranges and checks every count it can against the
 * others, so that a damaged file fails with the line at fault.
 */
#include "numerics/nist_strd.h"

#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

typedef struct reader {
    const char *path;
    char *text;    /* the file, NUL-terminated lines in place */
    char **line;   /* line[1..n] */
    size_t n;
    tf_ctx *ctx; /* where a failure's message goes */
} reader;

static int fail(reader *rd, size_t line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static int fail(reader *rd, size_t line, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (line > 0) {
        tf_fail(rd->ctx, "%s:%zu: %s", rd->path, line, msg);
    } else {
        tf_fail(rd->ctx, "%s: %s", rd->path, msg);
    }
    return -1;
}

static const char *skip_blank(const char *s)
{
    while (*s == ' ' || *s == '\t') {
        ++s;
    }
    return s;
}

static int is_blank(const char *s)
{
    return *skip_blank(s) == '\0';
}

/* Reads the whole file and splits it into lines, dropping "\r\n" / "\n". */
static int load_lines(reader *rd)
{
    FILE *fp = fopen(rd->path, "rb");
    if (fp == NULL) {
        return fail(rd, 0, "cannot open: %s", strerror(errno));
    }
    size_t cap = 1 << 16, len = 0;
    rd->text = malloc(cap + 1);
    for (size_t got; rd->text != NULL && (got = fread(rd->text + len, 1, cap - len, fp)) > 0;) {
        len += got;
        if (len == cap) {
            char *t = realloc(rd->text, 2 * cap + 1);
            if (t == NULL) {
                free(rd->text);
            }
            rd->text = t;
            cap *= 2;
        }
    }
    int bad = ferror(fp);
    fclose(fp);
    if (rd->text == NULL || bad) {
        return fail(rd, 0, bad ? "read error" : "out of memory");
    }
    rd->text[len] = '\0';
    if (memchr(rd->text, '\0', len) != NULL) {
        return fail(rd, 0, "not a text file (contains NUL bytes)");
    }
    size_t lines = 1;
    for (size_t i = 0; i < len; ++i) {
        lines += rd->text[i] == '\n';
    }
    rd->line = malloc((lines + 1) * sizeof *rd->line);
    if (rd->line == NULL) {
        return fail(rd, 0, "out of memory");
    }
    for (char *s = rd->text; s != NULL;) {
        char *nl = strchr(s, '\n');
        if (nl != NULL) {
            *nl = '\0';
        }
        size_t l = strlen(s);
        if (l > 0 && s[l - 1] == '\r') {
            s[l - 1] = '\0';
        }
        rd->line[++rd->n] = s;
        s = nl != NULL ? nl + 1 : NULL;
    }
    while (rd->n > 0 && is_blank(rd->line[rd->n])) {
        --rd->n; /* a final newline or trailing blank lines */
    }
    return 0;
}

/* First line (from `from`) whose text, after leading blanks, starts with
 * prefix (case-insensitive) and contains `also` (if not NULL); 0 if none. */
static size_t find(const reader *rd, size_t from, const char *prefix, const char *also)
{
    for (size_t i = from; i <= rd->n; ++i) {
        const char *s = skip_blank(rd->line[i]);
        if (strncasecmp(s, prefix, strlen(prefix)) == 0 &&
            (also == NULL || strstr(s, also) != NULL)) {
            return i;
        }
    }
    return 0;
}

/* Whole-token number. */
static int number(const char *tok, double *v)
{
    char *end;
    errno = 0;
    *v = strtod(tok, &end);
    return end != tok && *end == '\0' && errno != ERANGE;
}

/* Splits line i into at most max whitespace-separated tokens (copied to
 * buf); returns the count, or max + 1 when there are more or the line does
 * not fit in buf (a cut line must not parse as a shorter number). */
static size_t tokens(const reader *rd, size_t i, char *buf, size_t buflen, char **tok, size_t max)
{
    if ((size_t)snprintf(buf, buflen, "%s", rd->line[i]) >= buflen) {
        return max + 1;
    }
    size_t n = 0;
    for (char *save = NULL, *t = strtok_r(buf, " \t", &save); t != NULL;
         t = strtok_r(NULL, " \t", &save)) {
        if (n == max) {
            return max + 1;
        }
        tok[n++] = t;
    }
    return n;
}

/* "(lines A to B)" on the File Format line that starts with label. */
static int range(reader *rd, const char *label, size_t *a, size_t *b)
{
    size_t i = find(rd, 1, label, "(lines");
    if (i == 0) {
        return fail(rd, 0, "the File Format block gives no line range for '%s'", label);
    }
    const char *s = strstr(rd->line[i], "(lines");
    if (sscanf(s, "(lines %zu to %zu)", a, b) != 2 || *a == 0 || *b < *a || *b > rd->n) {
        return fail(rd, i, "bad line range for '%s' (the file has %zu lines)", label, rd->n);
    }
    return 0;
}

/* Count in front of a word on a header line: "  128 Observations". */
static int leading_count(reader *rd, size_t i, const char *what, size_t *v)
{
    const char *s = skip_blank(rd->line[i]);
    char *end;
    unsigned long c = strtoul(s, &end, 10);
    if (end == s || c == 0) {
        return fail(rd, i, "expected the number of %s", what);
    }
    *v = c;
    return 0;
}

/* ------------------------------------------------------------------------ */

static int read_name(reader *rd, tf_nist *d)
{
    if (rd->n == 0 || strncmp(rd->line[1], "NIST/ITL StRD", 13) != 0) {
        return fail(rd, 1, "not a NIST StRD file (expected 'NIST/ITL StRD')");
    }
    size_t i = find(rd, 1, "Dataset Name:", NULL);
    if (i == 0 || sscanf(strchr(rd->line[i], ':') + 1, "%63s", d->name) != 1) {
        return fail(rd, i, "no dataset name");
    }
    return 0;
}

/* Model text: the lines between "N Parameters" and "Starting values",
 * without blanks, with [] as () and without the trailing "+ e". */
static int read_model(reader *rd, tf_nist *d, size_t *n_par)
{
    size_t i = find(rd, 1, "Model:", NULL);
    if (i == 0) {
        return fail(rd, 0, "no 'Model:' block");
    }
    size_t p = i + 1;
    while (p <= rd->n && is_blank(rd->line[p])) {
        ++p;
    }
    if (p > rd->n || strstr(rd->line[p], "Parameter") == NULL ||
        leading_count(rd, p, "parameters", n_par) != 0) {
        return fail(rd, p, "expected 'N Parameters' under 'Model:'");
    }
    size_t end = find(rd, p + 1, "Starting", NULL);
    if (end == 0) {
        return fail(rd, 0, "no 'Starting values' heading after the model");
    }
    size_t len = 0;
    d->model_line = 0;
    for (size_t l = p + 1; l < end; ++l) {
        for (const char *s = rd->line[l]; *s != '\0'; ++s) {
            if (isspace((unsigned char)*s)) {
                continue;
            }
            if (len + 2 >= sizeof d->model) {
                return fail(rd, l, "model text too long");
            }
            d->model_line = d->model_line ? d->model_line : l;
            d->model[len++] = *s == '[' ? '(' : *s == ']' ? ')' : *s;
        }
    }
    d->model[len] = '\0';
    if (len > 2 && strcmp(d->model + len - 2, "+e") == 0) {
        d->model[len - 2] = '\0';
    }
    if (d->model[0] == '\0') {
        return fail(rd, p, "empty model");
    }
    return 0;
}

/* "  b3 =  start1  start2  certified  sd" on each line of the range. */
static int read_parameters(reader *rd, tf_nist *d, size_t n_par)
{
    size_t a, b;
    if (range(rd, "Starting Values", &a, &b) != 0) {
        return -1;
    }
    d->n_par = b - a + 1;
    if (d->n_par != n_par || n_par > TF_NIST_MAX_PAR) {
        return fail(rd, a, "%zu parameter lines for a model of %zu parameters (at most %d)",
                    d->n_par, n_par, TF_NIST_MAX_PAR);
    }
    for (size_t j = 0; j < n_par; ++j) {
        char buf[512], *t[8], want[32];
        size_t nt = tokens(rd, a + j, buf, sizeof buf, t, 7);
        snprintf(want, sizeof want, "b%zu", j + 1);
        double v[4];
        if (nt != 6 || strcmp(t[0], want) != 0 || strcmp(t[1], "=") != 0 ||
            !number(t[2], &v[0]) || !number(t[3], &v[1]) || !number(t[4], &v[2]) ||
            !number(t[5], &v[3])) {
            return fail(rd, a + j, "expected '%s = start1 start2 certified sd'", want);
        }
        d->start[0][j] = v[0];
        d->start[1][j] = v[1];
        d->certified[j] = v[2];
        d->certified_sd[j] = v[3];
    }
    return 0;
}

/* The certified block: parameter lines, then RSS ... observations. */
static int read_certified(reader *rd, tf_nist *d, size_t *n_obs)
{
    size_t a, b;
    if (range(rd, "Certified Values", &a, &b) != 0) {
        return -1;
    }
    size_t rss = find(rd, a, "Residual Sum of Squares:", NULL);
    size_t obs = find(rd, a, "Number of Observations:", NULL);
    if (rss == 0 || rss > b) {
        return fail(rd, a, "no 'Residual Sum of Squares:' in lines %zu to %zu", a, b);
    }
    if (obs == 0 || obs > b) {
        return fail(rd, a, "no 'Number of Observations:' in lines %zu to %zu", a, b);
    }
    char buf[512], *t[8];
    if (tokens(rd, rss, buf, sizeof buf, t, 7) != 5 || !number(t[4], &d->certified_rss)) {
        return fail(rd, rss, "expected 'Residual Sum of Squares: VALUE'");
    }
    double v;
    if (tokens(rd, obs, buf, sizeof buf, t, 7) != 4 || !number(t[3], &v) || v < 1 ||
        v != (double)(size_t)v) {
        return fail(rd, obs, "expected 'Number of Observations: N'");
    }
    *n_obs = (size_t)v;
    return 0;
}

/* The data summary under "Data:" in the header: predictors, observations. */
static int read_summary(reader *rd, size_t *n_x, size_t *n_obs)
{
    size_t i = find(rd, 1, "Data:", "Response");
    if (i == 0 || i + 2 > rd->n) {
        return fail(rd, 0, "no 'Data: 1 Response' summary");
    }
    if (strstr(rd->line[i + 1], "Predictor") == NULL ||
        leading_count(rd, i + 1, "predictors", n_x) != 0) {
        return fail(rd, i + 1, "expected 'N Predictor(s)'");
    }
    if (strstr(rd->line[i + 2], "Observations") == NULL ||
        leading_count(rd, i + 2, "observations", n_obs) != 0) {
        return fail(rd, i + 2, "expected 'N Observations'");
    }
    if (*n_x > TF_NIST_MAX_X) {
        return fail(rd, i + 1, "%zu predictors (at most %d)", *n_x, TF_NIST_MAX_X);
    }
    return 0;
}

static int read_data(reader *rd, tf_nist *d)
{
    size_t a, b;
    if (range(rd, "Data", &a, &b) != 0) {
        return -1;
    }
    if (b - a + 1 != d->n_obs) {
        return fail(rd, a, "the data range holds %zu lines for %zu observations", b - a + 1,
                    d->n_obs);
    }
    if (b < rd->n) {
        return fail(rd, b + 1, "text after the data range (lines %zu to %zu)", a, b);
    }
    d->y = malloc(d->n_obs * sizeof *d->y);
    d->x = malloc(d->n_obs * d->n_x * sizeof *d->x);
    if (d->y == NULL || d->x == NULL) {
        return fail(rd, 0, "out of memory");
    }
    for (size_t i = 0; i < d->n_obs; ++i) {
        char buf[512], *t[TF_NIST_MAX_X + 2];
        size_t nt = tokens(rd, a + i, buf, sizeof buf, t, TF_NIST_MAX_X + 1);
        int ok = nt == 1 + d->n_x && number(t[0], &d->y[i]);
        for (size_t k = 0; ok && k < d->n_x; ++k) {
            ok = number(t[1 + k], &d->x[i * d->n_x + k]);
        }
        if (!ok) {
            return fail(rd, a + i, "expected %zu numbers (y and %zu predictor%s)", 1 + d->n_x,
                        d->n_x, d->n_x == 1 ? "" : "s");
        }
    }
    return 0;
}

void tf_nist_free(tf_nist *d)
{
    free(d->y);
    free(d->x);
    d->y = d->x = NULL;
}

int tf_nist_read(tf_ctx *ctx, const char *path, tf_nist *d)
{
    memset(d, 0, sizeof *d);
    reader rd = {.path = path, .ctx = ctx};
    size_t n_par = 0, n_obs_header = 0, n_obs_cert = 0;
    int rc = load_lines(&rd);
    rc = rc != 0 ? rc : read_name(&rd, d);
    rc = rc != 0 ? rc : read_summary(&rd, &d->n_x, &n_obs_header);
    rc = rc != 0 ? rc : read_model(&rd, d, &n_par);
    rc = rc != 0 ? rc : read_parameters(&rd, d, n_par);
    rc = rc != 0 ? rc : read_certified(&rd, d, &n_obs_cert);
    if (rc == 0 && n_obs_header != n_obs_cert) {
        rc = fail(&rd, 0, "%zu observations in the header but %zu in the certified values",
                  n_obs_header, n_obs_cert);
    }
    d->n_obs = n_obs_header;
    rc = rc != 0 ? rc : read_data(&rd, d);
    free(rd.line);
    free(rd.text);
    if (rc != 0) {
        tf_nist_free(d);
    }
    return rc;
}
