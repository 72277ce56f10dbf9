/*
 * cmd_eval.c — `tissuefit eval NAME.h`: a generated header's model
 * evaluated by libtfit, bit for bit what the firmware computes, on inputs
 * from a CSV file, into a CSV file (docs/header-format.md §11).  The header
 * is compiled and loaded by eval_shim.c; this file reads the inputs, calls
 * the model as the golden runner does, and writes the outputs.
 */
#include <ctype.h>
#include <errno.h>
#include <getopt.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "base/log.h"
#include "cli/cli.h"
#include "cli/cmd_args.h"
#include "cli/eval_shim.h"
#include "tfit.h"

typedef struct eval_args {
    const char *header, *model, *in, *out;
    int q31, golden;
} eval_args;

/* The model chosen: its index among the header's float or Q31 models, its
 * family and outputs, and for a region surface the index of its law. */
typedef struct chosen {
    uint32_t index, family, n_out, law;
    int q31;
    const char *name;
} chosen;

/* The input rows: n rows of `cols` words (float or int32 bits). */
typedef struct table {
    size_t n, cap, cols;
    union {
        float f;
        int32_t i;
    } *v;
} table;

static void help(FILE *out)
{
    fprintf(out,
            "usage: tissuefit eval NAME.h [--model M] [--q31] -i INPUTS.csv -o OUTPUTS.csv\n"
            "       tissuefit eval NAME.h [--model M] [--q31] --golden -o GOLDEN.csv\n\n"
            "Evaluates model M of a generated header through libtfit, bit for bit what\n"
            "the firmware computes, on the rows of INPUTS.csv, and writes OUTPUTS.csv: a\n"
            "header row naming the columns, then one row per input: the status (tfit.h:\n"
            "0 OK, 1 CLAMPED, 2 NO_CONTACT, -1 ERR_INPUT, ...) and the outputs.\n\n"
            "Inputs, by the model's family (three columns, comma-separated; a first row\n"
            "whose first cell is not a number names the columns):\n"
            "  nodal, modal, zhou2017, modal_q15   fx,fy,fz: the force (N); outputs the\n"
            "                                      displacement of every output point (mm)\n"
            "  contact                             ux,uy,uz: the contact displacement (mm);\n"
            "                                      outputs the contact force (N)\n"
            "  cut                                 fx,fy,fz,s: the force and the cut progress\n"
            "  prony, resonant                     fx,fy,fz, one row per tick from rest\n"
            "  region (NAME_law)                   x,y,z: the tool tip (mm), one row per tick\n"
            "                                      from a reset state; outputs the force (N)\n"
            "  region_surface (NAME_surface)       x,y,z as for its law: the law's status and\n"
            "                                      force, then the surface's status and the\n"
            "                                      displacement of every output point (mm)\n"
            "Values are read as float32 (round to nearest; nan and inf are accepted) and\n"
            "written with 9 significant digits, which give back every float exactly.\n\n"
            "Options:\n"
            "  --model M      a model of the header, with or without its tfit_ prefix\n"
            "                 (default: the first the header declares)\n"
            "  --q31          its Q31 form (M_q31): inputs and outputs are int32 words in\n"
            "                 the header's Q31 scalings (TFIT_M_Q31_IN_EXP, _OUT_EXP)\n"
            "  -i FILE        the inputs (CSV)\n"
            "  -o FILE        the outputs (CSV), written whole or not at all\n"
            "  --golden       write the model's golden vectors (NAME_golden.h) instead:\n"
            "                 the input columns, then the expected status and outputs\n\n"
            "The header is compiled with $CC (default cc) -std=c11 -O2 -ffp-contract=off\n"
            "against the tfit.h and position-independent libtfit installed beside the\n"
            "tool (PREFIX/include, PREFIX/lib/tfit/native-pic), with the evaluator\n"
            "PREFIX/share/tfit/tfit_shim.c that the Python module also compiles.\n");
}

static int parse(tf_ctx *ctx, int argc, char **argv, eval_args *a)
{
    static const struct option opts[] = {{"model", required_argument, NULL, 'm'},
                                         {"q31", no_argument, NULL, 'q'},
                                         {"golden", no_argument, NULL, 'g'},
                                         {0}};
    memset(a, 0, sizeof *a);
    int c;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "i:o:", opts, NULL)) != -1) {
        switch (c) {
        case 'm':
            a->model = strncmp(optarg, "tfit_", 5) == 0 ? optarg + 5 : optarg;
            break;
        case 'q':
            a->q31 = 1;
            break;
        case 'g':
            a->golden = 1;
            break;
        case 'i':
            a->in = optarg;
            break;
        case 'o':
            a->out = optarg;
            break;
        default:
            tf_error(ctx, "eval: bad option '%s' (see tissuefit eval --help)", argv[optind - 1]);
            return -1;
        }
    }
    if (optind + 1 != argc || a->out == NULL || (a->in == NULL) == !a->golden) {
        tf_error(ctx, "eval: expected NAME.h, -o FILE and one of -i FILE or --golden "
                      "(see tissuefit eval --help)");
        return -1;
    }
    a->header = argv[optind];
    return 0;
}

static const char *family_name(uint32_t f)
{
    static const char *const names[] = {"?",         "nodal", "modal",    "zhou2017",
                                        "contact",   "prony", "cut",      "resonant",
                                        "modal_q15", "region", "region_surface"};
    return f < sizeof names / sizeof names[0] ? names[f] : "?";
}

/* The index of name in names[n], or -1. */
static long find(const char (*names)[TF_EVAL_NAME_MAX], size_t n, const char *name)
{
    for (size_t i = 0; i < n; ++i) {
        if (strcmp(names[i], name) == 0) {
            return (long)i;
        }
    }
    return -1;
}

/* The header's model names, for a message. */
static void list_models(const tf_eval_decls *d, char *s, size_t size)
{
    size_t k = 0;
    s[0] = '\0';
    for (size_t i = 0; i < d->n_models + d->n_models_q31 && k < size; ++i) {
        const char *m = i < d->n_models ? d->models[i] : d->models_q31[i - d->n_models];
        k += (size_t)snprintf(s + k, size - k, "%s%s", i ? ", " : "", m);
    }
}

/* Which model --model and --q31 name (before compiling). */
static int choose_name(tf_ctx *ctx, const eval_args *a, const tf_eval_decls *d, chosen *m)
{
    char want[TF_EVAL_NAME_MAX + 8], names[2048];
    snprintf(want, sizeof want, "%s", a->model ? a->model : d->models[0]);
    size_t len = strlen(want);
    if (a->q31 && !(len > 4 && strcmp(want + len - 4, "_q31") == 0)) {
        strcat(want, "_q31");
    }
    long i = a->q31 ? find(d->models_q31, d->n_models_q31, want)
                    : find(d->models, d->n_models, want);
    if (i < 0) {
        list_models(d, names, sizeof names);
        return tf_fail(ctx, "%s: no %smodel %s (it has %s)", a->header, a->q31 ? "Q31 " : "",
                       want, names);
    }
    m->index = (uint32_t)i;
    m->q31 = a->q31;
    m->name = a->q31 ? d->models_q31[i] : d->models[i];
    return 0;
}

/* The region law beside surface model `name` (NAME_surface -> NAME_law). */
static int find_law(tf_ctx *ctx, const char *header, const tf_eval_decls *d, chosen *m)
{
    char law[TF_EVAL_NAME_MAX + 8];
    size_t len = strlen(m->name);
    const char *suffix = "_surface";
    if (len > strlen(suffix) && strcmp(m->name + len - strlen(suffix), suffix) == 0) {
        snprintf(law, sizeof law, "%.*s_law", (int)(len - strlen(suffix)), m->name);
        long i = find(d->models, d->n_models, law);
        if (i >= 0) {
            m->law = (uint32_t)i;
            return 0;
        }
    }
    return tf_fail(ctx, "%s: region surface %s has no law %s_law beside it", header, m->name,
                   m->name);
}

/* Family and outputs from the compiled model; refuses a model the library
 * refuses at boot. */
static int describe(tf_ctx *ctx, const char *header, const tf_eval_decls *d,
                    const tf_eval_shim *sh, chosen *m)
{
    uint32_t info[3];
    int32_t st = m->q31 ? sh->model_q31_info(m->index, info) : sh->model_info(m->index, info);
    m->family = info[0];
    m->n_out = info[1];
    if (st != TFIT_OK) {
        return tf_fail(ctx, "%s: model %s fails tfit_model_check (status %d)", header, m->name,
                       (int)st);
    }
    m->law = UINT32_MAX;
    if (m->family == TFIT_FAMILY_REGION_SURFACE) {
        return find_law(ctx, header, d, m);
    }
    return 0;
}

/* ---- the CSV files ------------------------------------------------------- */

static size_t input_cols(const chosen *m)
{
    return m->family == TFIT_FAMILY_CUT ? 4 : 3;
}

static void write_input_names(FILE *f, const chosen *m)
{
    const char *names = m->family == TFIT_FAMILY_CONTACT ? "ux,uy,uz"
                        : m->family == TFIT_FAMILY_REGION ||
                                m->family == TFIT_FAMILY_REGION_SURFACE
                            ? "x,y,z"
                            : "fx,fy,fz";
    fprintf(f, "%s%s,", names, m->family == TFIT_FAMILY_CUT ? ",s" : "");
}

static void write_output_names(FILE *f, const chosen *m, uint32_t n_out)
{
    if (m->family == TFIT_FAMILY_CONTACT || m->family == TFIT_FAMILY_REGION ||
        m->family == TFIT_FAMILY_REGION_SURFACE) {
        fputs("status,fx,fy,fz", f);
        if (m->family != TFIT_FAMILY_REGION_SURFACE) {
            fputc('\n', f);
            return;
        }
        fputs(",surface_status", f);
    } else {
        fputs("status", f);
    }
    for (uint32_t p = 0; p < n_out; ++p) {
        fprintf(f, ",u%u_x,u%u_y,u%u_z", p, p, p);
    }
    fputc('\n', f);
}

/* One value: a float with 9 significant digits (every float exactly), or
 * an int32 word. */
static void put(FILE *f, int q31, const void *word)
{
    if (q31) {
        int32_t i;
        memcpy(&i, word, sizeof i);
        fprintf(f, ",%d", (int)i);
    } else {
        float x;
        memcpy(&x, word, sizeof x);
        fprintf(f, ",%.9g", (double)x);
    }
}

/* A cell: a float (strtof, round to nearest) or an int32 word. */
static int cell(const char *s, int q31, float *f, int32_t *i)
{
    s += strspn(s, " \t");
    char *end;
    errno = 0;
    if (q31) {
        long v = strtol(s, &end, 10);
        if (end == s || errno != 0 || v < INT32_MIN || v > INT32_MAX) {
            return -1;
        }
        *i = (int32_t)v;
    } else {
        *f = strtof(s, &end);
        if (end == s || (errno == ERANGE && isinf(*f))) {
            return -1;
        }
    }
    end += strspn(end, " \t\r");
    return *end == '\0' ? 0 : -1;
}

/* Splits line at commas in place into at most max cells; their count. */
static size_t split(char *line, char **cells, size_t max)
{
    size_t n = 0;
    line[strcspn(line, "\n")] = '\0';
    for (char *p = line;; ++p) {
        if (n == max) {
            return max + 1;
        }
        cells[n++] = p;
        p += strcspn(p, ",");
        if (*p == '\0') {
            return n;
        }
        *p = '\0';
    }
}

static int table_add(tf_ctx *ctx, table *t)
{
    if (t->n == t->cap) {
        size_t cap = t->cap ? 2 * t->cap : 256;
        void *v = realloc(t->v, cap * t->cols * sizeof *t->v);
        if (v == NULL) {
            return tf_fail(ctx, "out of memory");
        }
        t->v = v;
        t->cap = cap;
    }
    t->n++;
    return 0;
}

/* One line of the input file into the table's next row. */
static int read_row(tf_ctx *ctx, const char *path, long line_no, char *line, table *t, int q31)
{
    char *cells[8];
    size_t n = split(line, cells, 7);
    if (n != t->cols) {
        return tf_fail(ctx, "%s:%ld: %s%zu columns, expected %zu", path, line_no,
                       n > 7 ? "more than " : "", n > 7 ? (size_t)7 : n, t->cols);
    }
    if (table_add(ctx, t) != 0) {
        return -1;
    }
    for (size_t c = 0; c < n; ++c) {
        size_t k = (t->n - 1) * t->cols + c;
        if (cell(cells[c], q31, &t->v[k].f, &t->v[k].i) != 0) {
            return tf_fail(ctx, "%s:%ld: column %zu: '%s' is not %s", path, line_no, c + 1,
                           cells[c], q31 ? "an int32 word" : "a float32 number");
        }
    }
    return 0;
}

/* The input CSV: blank lines and lines starting with # are skipped; the
 * first other line names the columns when its first cell starts with a
 * letter and is not a number (nan, inf). */
static int read_inputs(tf_ctx *ctx, const char *path, int q31, table *t)
{
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        return tf_fail(ctx, "%s: %s", path, strerror(errno));
    }
    char line[4096];
    long no = 0;
    int first = 1, rc = 0;
    while (rc == 0 && fgets(line, sizeof line, f) != NULL) {
        ++no;
        if (strchr(line, '\n') == NULL && !feof(f)) {
            rc = tf_fail(ctx, "%s:%ld: line longer than %zu characters", path, no,
                         sizeof line - 2);
            break;
        }
        char *p = line + strspn(line, " \t");
        if (*p == '#' || p[strspn(p, " \t\r\n")] == '\0') {
            continue;
        }
        if (first) {
            first = 0;
            float x;
            int32_t i;
            char copy[4096];
            memcpy(copy, p, sizeof line - (size_t)(p - line));
            copy[strcspn(copy, ",\n")] = '\0';
            if ((isalpha((unsigned char)copy[0]) || copy[0] == '_') && cell(copy, q31, &x, &i) != 0) {
                continue; /* the column names */
            }
        }
        rc = read_row(ctx, path, no, line, t, q31);
    }
    if (rc == 0 && ferror(f)) {
        rc = tf_fail(ctx, "%s: read error", path);
    }
    fclose(f);
    if (rc == 0 && t->n == 0) {
        rc = tf_fail(ctx, "%s: no input rows", path);
    }
    return rc;
}

/* ---- evaluation ---------------------------------------------------------- */

/* Evaluates the n rows of t; writes the CSV rows to f. */
static int evaluate(tf_ctx *ctx, const tf_eval_shim *sh, const chosen *m, const table *t,
                    FILE *f)
{
    const size_t n = t->n, w = 3u * m->n_out;
    const int surface = m->family == TFIT_FAMILY_REGION_SURFACE;
    size_t out_words = surface ? n * (3 + w) : n * w;
    int32_t *status = malloc(2 * n * sizeof *status);
    float *in = malloc(n * 4 * sizeof *in), *s = malloc(n * sizeof *s);
    float *out = malloc(out_words * sizeof *out);
    int rc = status && in && s && out ? 0 : tf_fail(ctx, "out of memory");
    for (size_t k = 0; rc == 0 && k < n; ++k) {
        memcpy(in + 3 * k, &t->v[k * t->cols], 3 * sizeof *in);
        if (t->cols == 4) {
            s[k] = t->v[k * t->cols + 3].f;
        }
    }
    if (rc == 0) {
        uint32_t nn = (uint32_t)n;
        int32_t r = surface ? sh->eval_region(m->law, m->index, nn, in, out, status, out + 3 * n,
                                              status + n)
                    : m->q31 ? sh->eval_q31(m->index, nn, (const int32_t *)(const void *)in,
                                            (int32_t *)(void *)out, status)
                             : sh->eval(m->index, nn, in, s, out, status);
        rc = r == 0 ? 0 : tf_fail(ctx, "model %s: evaluation refused", m->name);
    }
    for (size_t k = 0; rc == 0 && k < n; ++k) {
        fprintf(f, "%d", (int)status[k]);
        const float *y = surface ? out + 3 * k : out + w * k;
        for (size_t j = 0; j < (surface ? 3 : w); ++j) {
            put(f, m->q31, y + j);
        }
        if (surface) {
            fprintf(f, ",%d", (int)status[n + k]);
            for (size_t j = 0; j < w; ++j) {
                put(f, 0, out + 3 * n + w * k + j);
            }
        }
        fputc('\n', f);
    }
    free(status);
    free(in);
    free(s);
    free(out);
    return rc;
}

/* The model's golden set as CSV rows: inputs (and a cut model's progress),
 * then the expected status and outputs. */
static int golden_rows(tf_ctx *ctx, const char *header, const tf_eval_shim *sh,
                       const chosen *m, FILE *f)
{
    if (m->family == TFIT_FAMILY_REGION_SURFACE) {
        return tf_fail(ctx, "%s: the golden vectors of region surface %s place its proxy "
                            "directly, not through tool tips: not written",
                       header, m->name);
    }
    uint32_t sets = m->q31 ? sh->goldens_q31() : sh->goldens();
    for (uint32_t j = 0; j < sets; ++j) {
        uint32_t model, n;
        const uint32_t *in, *out;
        const int32_t *st;
        int32_t r = m->q31 ? sh->golden_q31(j, &model, &n, (const int32_t **)(void *)&in, &st,
                                            (const int32_t **)(void *)&out)
                           : sh->golden(j, &model, &n, &in, &st, &out);
        if (r != 0 || model != m->index) {
            continue;
        }
        for (uint32_t v = 0; v < n; ++v) {
            for (int c = 0; c < 3; ++c) {
                put(f, m->q31, in + 3u * v + (uint32_t)c);
            }
            if (m->family == TFIT_FAMILY_CUT) {
                float s = sh->cut_golden_s(v);
                put(f, 0, &s);
            }
            fprintf(f, ",%d", (int)st[v]);
            for (uint32_t k = 0; k < 3u * m->n_out; ++k) {
                put(f, m->q31, out + (size_t)3u * m->n_out * v + k);
            }
            fputc('\n', f);
        }
        return 0;
    }
    return tf_fail(ctx, "%s: no golden vectors for %s (is %s beside it?)", header, m->name,
                   "NAME_golden.h");
}

/* The golden CSV in memory (*text, malloc'd), so that a refusal writes
 * nothing.  Rows from golden_rows start with put's comma: stripped. */
static int render_golden(tf_ctx *ctx, const char *header, const tf_eval_shim *sh,
                         const chosen *m, char **text)
{
    char *rows = NULL, *all = NULL;
    size_t len = 0, all_len = 0;
    FILE *mem = open_memstream(&rows, &len), *out = open_memstream(&all, &all_len);
    int rc = mem && out ? golden_rows(ctx, header, sh, m, mem) : tf_fail(ctx, "out of memory");
    if (mem != NULL) {
        fclose(mem);
    }
    if (rc == 0) {
        write_input_names(out, m);
        write_output_names(out, m, m->n_out);
        for (char *line = rows; *line != '\0';) {
            size_t l = strcspn(line, "\n");
            fprintf(out, "%.*s\n", (int)l - 1, line + 1);
            line += l + (line[l] == '\n');
        }
    }
    if (out != NULL) {
        fclose(out);
    }
    free(rows);
    if (rc != 0) {
        free(all);
        return -1;
    }
    *text = all;
    return 0;
}

/* The output file: written to a temporary and renamed. */
static int write_output(tf_ctx *ctx, const char *path, const char *golden,
                        const tf_eval_shim *sh, const chosen *m, const table *t)
{
    tf_afile f;
    if (tf_afile_open(ctx, &f, path) != 0) {
        return -1;
    }
    int rc = 0;
    if (golden != NULL) {
        fputs(golden, f.fp);
    } else {
        write_output_names(f.fp, m, m->n_out);
        rc = evaluate(ctx, sh, m, t, f.fp);
    }
    if (rc != 0) {
        tf_afile_abort(&f);
        return -1;
    }
    return tf_afile_commit(ctx, &f);
}

static int run(tf_ctx *ctx, int argc, char **argv)
{
    eval_args a;
    if (parse(ctx, argc, argv, &a) != 0) {
        return TF_EXIT_USAGE;
    }
    tf_eval_decls *d = malloc(sizeof *d);
    table t = {0};
    chosen m = {0};
    tf_eval_shim sh = {0};
    char *golden = NULL;
    int rc = TF_EXIT_USAGE;
    if (d == NULL || tf_cmd_outputs(ctx, "eval", (const char *[]){a.out}, 1) != 0) {
        free(d);
        return d == NULL ? TF_EXIT_FAIL : TF_EXIT_USAGE;
    }
    if (tf_eval_decls_read(ctx, a.header, a.golden, d) != 0 || choose_name(ctx, &a, d, &m) != 0) {
        tf_error(ctx, "eval: %s", ctx->err);
        goto done;
    }
    if (tf_eval_shim_open(ctx, &sh, a.header, d) != 0) {
        tf_error(ctx, "eval: %s", ctx->err);
        rc = TF_EXIT_FAIL; /* no compiler, or a header it cannot compile */
        goto done;
    }
    if (describe(ctx, a.header, d, &sh, &m) != 0) {
        tf_error(ctx, "eval: %s", ctx->err);
        goto done;
    }
    t.cols = input_cols(&m);
    if (a.golden ? render_golden(ctx, a.header, &sh, &m, &golden) != 0
                 : read_inputs(ctx, a.in, a.q31, &t) != 0) {
        tf_error(ctx, "eval: %s", ctx->err);
        goto done;
    }
    rc = TF_EXIT_FAIL;
    if (write_output(ctx, a.out, golden, &sh, &m, &t) != 0) {
        tf_error(ctx, "eval: %s", ctx->err);
        goto done;
    }
    tf_info(ctx, "eval: %s (%s%s, %u outputs): %s into %s", m.name, family_name(m.family),
            m.q31 ? ", Q31" : "", m.n_out, a.golden ? "its golden vectors" : "the inputs", a.out);
    rc = TF_EXIT_OK;
done:
    tf_eval_shim_close(&sh);
    free(golden);
    free(t.v);
    free(d);
    return rc;
}

const tf_command tf_cmd_eval = {
    .name = "eval",
    .summary = "evaluate a generated header's model on inputs from a CSV file (libtfit's bits)",
    .run = run,
    .help = help,
};
