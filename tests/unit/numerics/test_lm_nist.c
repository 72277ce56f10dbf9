/*
 * test_lm_nist.c — the Levenberg–Marquardt core certified on the NIST StRD
 * nonlinear suite (../shared/reference/nist-strd): all 27 problems from
 * both starting points must reach 6 correct digits (LRE >= 6) in every
 * parameter and in the residual sum of squares, and the standard errors
 * must match the certified ones to 6 digits or to the RSS's digits.  Also: the reader (CRLF and
 * LF, values taken from the file, errors naming file and line) and the
 * hand-derived model derivatives against central differences.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include "assert_close.h"
#include "numerics/nist_fit.h"

/* The NIST StRD files live beside the repository; TF_NIST_DIR names another
 * place (check-lm uses it to show that a missing directory fails). */
static const char *nist_dir(void)
{
    const char *d = getenv("TF_NIST_DIR");
    return d != NULL ? d : "../shared/reference/nist-strd";
}
#define DIR nist_dir()

/* The data are part of the test: without them it fails, never skips. */
static void require_data(void)
{
    struct stat st;
    if (stat(DIR, &st) != 0) {
        fail_msg("%s is absent: the NIST StRD files live beside the repository "
                 "(../shared/reference/nist-strd); without them LM is not certified",
                 DIR);
    }
}

static void load(const char *name, tf_nist *d, const tf_nist_model **model)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    if (tf_nist_load(&ctx, DIR, name, d, model) != 0) {
        fail_msg("%s", ctx.err);
    }
    assert_string_equal(d->name, name);
}

/* The suite's names; there must be 27. */
static const char *const *suite(void)
{
    size_t n;
    const char *const *names = tf_nist_suite(&n);
    assert_int_equal(n, 27);
    return names;
}

/* ------------------------------------------------------------------------ */

static void all_54_runs_reach_six_digits(void **state)
{
    (void)state;
    require_data();
    int failures = 0, runs = 0;
    double min_par = 99, sum_par = 0, min_rss = 99, min_se = 99;
    size_t n_par_total = 0;
    const char *const *problems = suite();
    for (int k = 0; k < 27; ++k) {
        tf_nist d;
        const tf_nist_model *model;
        load(problems[k], &d, &model);
        double resolution = tf_nist_rss_resolution(&d, model);
        for (int start = 1; start <= 2; ++start) {
            tf_lsfit_options o;
            tf_nist_options(&o, d.n_par);
            tf_nist_score s;
            tf_ctx ctx;
            tf_ctx_init(&ctx);
            assert_int_equal(tf_nist_fit(&ctx, &d, model, start, &o, 0, &s), 0);
            ++runs;
            int bad = !tf_stop_converged(s.stop);
            for (size_t j = 0; j < d.n_par; ++j) {
                bad |= s.lre[j] < 6;
                min_par = fmin(min_par, s.lre[j]);
                sum_par += s.lre[j];
                ++n_par_total;
            }
            /* The RSS in digits, or, where the certified RSS is at the
             * rounding floor of double precision, within that floor. */
            int rss_ok = s.rss_lre >= 6 || fabs(s.rss - d.certified_rss) <= resolution;
            if (s.rss_lre >= 6) {
                min_rss = fmin(min_rss, s.rss_lre);
            }
            bad |= !rss_ok;
            /* Standard errors against the certified ones: 6 digits, or as
             * many as the RSS they are scaled by has. */
            for (size_t j = 0; j < d.n_par; ++j) {
                bad |= s.se_lre[j] < fmin(6, s.rss_lre);
                min_se = fmin(min_se, s.se_lre[j]);
            }
            if (bad) {
                print_error("%s start %d: stop %s, min LRE %.2f, RSS %.10g (LRE %.2f)\n",
                            d.name, start, tf_stop_name(s.stop), s.min_lre, s.rss, s.rss_lre);
                for (size_t j = 0; j < d.n_par; ++j) {
                    print_error("  b%zu = %.17g: LRE %.2f, standard error LRE %.2f\n", j + 1,
                                s.estimate[j], s.lre[j], s.se_lre[j]);
                }
                ++failures;
            }
        }
        tf_nist_free(&d);
    }
    print_message("nist: %d runs, %d below 6 digits; parameters: min LRE %.2f, mean %.2f; "
                  "RSS: min LRE %.2f where resolvable; standard errors: min LRE %.2f\n",
                  runs, failures, min_par, sum_par / (double)n_par_total, min_rss, min_se);
    assert_int_equal(runs, 54);
    assert_int_equal(failures, 0);
}

/* Calls fn for each of the 27 problems, loaded. */
static void each_problem(void (*fn)(const char *name, const tf_nist *d, const tf_nist_model *m))
{
    const char *const *problems = suite();
    for (int k = 0; k < 27; ++k) {
        tf_nist d;
        const tf_nist_model *m;
        load(problems[k], &d, &m);
        fn(problems[k], &d, m);
        tf_nist_free(&d);
    }
}

static void check_resolution(const char *name, const tf_nist *d, const tf_nist_model *m)
{
    double rel = tf_nist_rss_resolution(d, m) / d->certified_rss;
    if (strcmp(name, "Lanczos1") == 0) {
        assert_true(rel > 1e-3);
    } else {
        assert_true(rel < 1e-7);
    }
}

/* The resolution bound is what lets Lanczos1's RSS through, and only it. */
static void rss_resolution_matters_only_at_the_rounding_floor(void **state)
{
    (void)state;
    require_data();
    each_problem(check_resolution);
}

/* ------------------------------------------------------------------------ */

/* d f / d b_j by central differences with a step relative to b_j. */
static double central(const tf_nist_model *m, const double *b, const double *x, size_t j)
{
    double bp[TF_NIST_MAX_PAR], bm[TF_NIST_MAX_PAR];
    memcpy(bp, b, m->n_par * sizeof *b);
    memcpy(bm, b, m->n_par * sizeof *b);
    double h = 1e-6 * (b[j] != 0 ? fabs(b[j]) : 1.0);
    bp[j] += h;
    bm[j] -= h;
    return (m->f(bp, x, NULL) - m->f(bm, x, NULL)) / (bp[j] - bm[j]);
}

/* At both starts and the certified values, for every observation. */
static void check_derivatives(const char *name, const tf_nist *d, const tf_nist_model *m)
{
    (void)name;
    const double *points[3] = {d->start[0], d->start[1], d->certified};
    for (int p = 0; p < 3; ++p) {
        for (size_t i = 0; i < d->n_obs; ++i) {
            const double *x = d->x + i * d->n_x;
            double g[TF_NIST_MAX_PAR], f = m->f(points[p], x, g);
            assert_close(f, m->f(points[p], x, NULL), 0);
            for (size_t j = 0; j < d->n_par; ++j) {
                double bj = points[p][j] != 0 ? fabs(points[p][j]) : 1.0;
                double tol = 1e-6 * (fabs(g[j]) + fabs(f) / bj) + 1e-300;
                assert_close(g[j], central(m, points[p], x, j), tol);
            }
        }
    }
}

static void model_derivatives_match_differences(void **state)
{
    (void)state;
    require_data();
    each_problem(check_derivatives);
}

/* ------------------------------------------------------------------------ */
/* Reader. */

static void values_come_from_the_file(void **state)
{
    (void)state;
    require_data();
    tf_nist d;
    const tf_nist_model *m;
    load("Misra1a", &d, &m);
    assert_int_equal(d.n_par, 2);
    assert_int_equal(d.n_obs, 14);
    assert_int_equal(d.n_x, 1);
    assert_true(d.start[0][0] == 500 && d.start[1][0] == 250);
    assert_true(d.start[0][1] == 0.0001 && d.start[1][1] == 0.0005);
    assert_true(d.certified[0] == 2.3894212918E+02 && d.certified_sd[1] == 7.2668688436E-06);
    assert_true(d.certified_rss == 1.2455138894E-01);
    assert_true(d.y[0] == 10.07 && d.x[13] == 760.0);
    assert_string_equal(d.model, "y=b1*(1-exp(-b2*x))");
    tf_nist_free(&d);
    load("Nelson", &d, &m);
    assert_int_equal(d.n_x, 2);
    assert_true(m->log_response);
    assert_true(d.y[127] == 1.20 && d.x[2 * 127] == 64 && d.x[2 * 127 + 1] == 275);
    tf_nist_free(&d);
}

/* Temporary copy of a NIST file with an edit: line `line` (1-based)
 * replaced by `text` (NULL: deleted), CRLF turned into LF when lf. */
static void edited_copy(const char *name, size_t line, const char *text, int lf, char *out,
                        size_t outlen)
{
    char src[256];
    snprintf(src, sizeof src, "%s/%s.dat", DIR, name);
    snprintf(out, outlen, "/tmp/tfit-nist-%ld-%s.dat", (long)getpid(), name);
    FILE *in = fopen(src, "rb"), *o = fopen(out, "wb");
    assert_non_null(in);
    assert_non_null(o);
    char buf[1024];
    for (size_t n = 1; fgets(buf, sizeof buf, in) != NULL; ++n) {
        if (n == line) {
            if (text != NULL) {
                fprintf(o, "%s\r\n", text);
            }
            continue;
        }
        size_t l = strlen(buf);
        if (lf && l >= 2 && buf[l - 2] == '\r') {
            buf[l - 2] = '\n';
            buf[l - 1] = '\0';
        }
        fputs(buf, o);
    }
    fclose(in);
    fclose(o);
}

static void crlf_and_lf_read_the_same(void **state)
{
    (void)state;
    require_data();
    tf_nist a, b;
    const tf_nist_model *m;
    char path[256];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    load("ENSO", &a, &m);
    edited_copy("ENSO", 0, NULL, 1, path, sizeof path);
    assert_int_equal(tf_nist_read(&ctx, path, &b), 0);
    unlink(path);
    assert_string_equal(a.model, b.model);
    assert_int_equal(a.n_obs, b.n_obs);
    assert_memory_equal(a.certified, b.certified, sizeof a.certified);
    assert_memory_equal(a.y, b.y, a.n_obs * sizeof *a.y);
    assert_memory_equal(a.x, b.x, a.n_obs * sizeof *a.x);
    tf_nist_free(&a);
    tf_nist_free(&b);
}

/* The error for a file with one edited line, which must name it. */
static void expect_error(const char *name, size_t line, const char *text, const char *where,
                         const char *what)
{
    char path[256], want[300];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_nist d;
    edited_copy(name, line, text, 0, path, sizeof path);
    int rc = tf_nist_read(&ctx, path, &d);
    if (rc == 0) {
        rc = tf_nist_match(&ctx, &d, path) == NULL ? -1 : 0;
        tf_nist_free(&d);
    }
    unlink(path);
    snprintf(want, sizeof want, "%s%s", path, where);
    if (rc == 0 || strstr(ctx.err, want) == NULL || strstr(ctx.err, what) == NULL) {
        fail_msg("line %zu edited: got '%s', wanted '%s' ... '%s'", line, rc ? ctx.err : "success",
                 want, what);
    }
}

static void damaged_files_name_the_line(void **state)
{
    (void)state;
    require_data();
    expect_error("Misra1a", 61, "      10.07X0      77.6E0", ":61:", "expected 2 numbers");
    expect_error("Misra1a", 74, "      81.78E0", ":74:", "expected 2 numbers");
    expect_error("Misra1a", 42, "  b2 =     0.0001      0.0005", ":42:", "b2 = start1");
    expect_error("Misra1a", 42, "  b3 =     0.0001      0.0005      5.5E-04  7.2E-06", ":42:",
                 "b2 = start1");
    expect_error("Misra1a", 34, "               y = b1*(1-exp[-b2*x*x])  +  e", ":34:",
                 "unknown model 'y=b1*(1-exp(-b2*x*x))'");
    expect_error("Misra1a", 1, "NIST/ITL", ":1:", "not a NIST StRD file");
    expect_error("Misra1a", 7, "               Data              (lines 61 to 99)", ":7:",
                 "bad line range");
    expect_error("Misra1a", 44, "Residual Sum of Squares:     lots", ":44:",
                 "Residual Sum of Squares: VALUE");
    expect_error("Misra1a", 47, "Number of Observations:      15", "", "15 in the certified");
    expect_error("Nelson", 41, "  b1 =    2           2.5          2.5906836021E+00", ":41:",
                 "b1 = start1");

    char missing[512], said[560];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_nist d;
    snprintf(missing, sizeof missing, "%s/NoSuch.dat", DIR);
    snprintf(said, sizeof said, "%s: cannot open", missing);
    assert_int_equal(tf_nist_read(&ctx, missing, &d), -1);
    assert_non_null(strstr(ctx.err, said));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(values_come_from_the_file),
        cmocka_unit_test(crlf_and_lf_read_the_same),
        cmocka_unit_test(damaged_files_name_the_line),
        cmocka_unit_test(model_derivatives_match_differences),
        cmocka_unit_test(rss_resolution_matters_only_at_the_rounding_floor),
        cmocka_unit_test(all_54_runs_reach_six_digits),
    };
    return cmocka_run_group_tests_name("lm_nist", tests, NULL, NULL);
}
