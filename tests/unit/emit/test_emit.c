/*
 * test_emit.c — the generated header: content, exact hexadecimal
 * coefficients, determinism, and that a failed emission writes nothing.
 */
#include <dirent.h>
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
#include <zlib.h>

#include "emit/emit_header.h"
#include "model/golden.h"
#include "random_model.h"

static char dir[256];

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/tfit_emit_XXXXXX");
    return mkdtemp(dir) == NULL;
}

static int teardown(void **state)
{
    (void)state;
    DIR *d = opendir(dir);
    struct dirent *e;
    char path[600];
    while (d != NULL && (e = readdir(d)) != NULL) {
        if (e->d_name[0] != '.') {
            snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
            unlink(path);
        }
    }
    if (d != NULL) {
        closedir(d);
    }
    return rmdir(dir);
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        return NULL;
    }
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = malloc((size_t)n + 1);
    size_t got = fread(buf, 1, (size_t)n, f);
    fclose(f);
    buf[got] = '\0';
    if (len) {
        *len = got;
    }
    return buf;
}

static int files_in_dir(void)
{
    int n = 0;
    DIR *d = opendir(dir);
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        n += e->d_name[0] != '.';
    }
    closedir(d);
    return n;
}

static tf_model *two_models[2];

static void make_models(uint64_t seed)
{
    tf_rng r = {seed};
    two_models[0] = tf_random_model(&r, "alpha_forward", TFIT_FAMILY_NODAL, 1);
    two_models[1] = tf_random_model(&r, "alpha_contact", TFIT_FAMILY_CONTACT, 1);
}

static void free_models(void)
{
    tf_model_free(two_models[0]);
    tf_model_free(two_models[1]);
}

static const tf_emit_info info = {.source = "scene.yaml", .has_source_crc = 1,
                                  .source_crc32 = 0xdeadbeef, .golden_seed = 3};

static void header_content_and_exact_literals(void **state)
{
    (void)state;
    char path[300];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    snprintf(path, sizeof path, "%s/alpha.h", dir);
    make_models(1);
    assert_int_equal(tf_emit_header(&ctx, path, two_models, 2, &info), 0);
    char *h = slurp(path, NULL);
    assert_non_null(h);
    assert_non_null(strstr(h, "#ifndef TFIT_ALPHA_H"));
    assert_non_null(strstr(h, "#if TFIT_API_VERSION != 4\n#error"));
    assert_non_null(strstr(h, "scene: scene.yaml (crc32 0xdeadbeef)"));
    assert_non_null(strstr(h, "#ifdef TFIT_ALPHA_IMPLEMENTATION"));
    assert_non_null(strstr(h, "extern const tfit_model tfit_alpha_contact;"));
    char crc[128];
    uint32_t check[TFIT_CHECK_WORDS];
    assert_int_equal(tf_check_vector(two_models[0], check), 0);
    const uint32_t want = tf_model_crc32_checked(two_models[0], check);
    snprintf(crc, sizeof crc, "#define TFIT_ALPHA_FORWARD_CRC32 0x%08xu", want);
    assert_non_null(strstr(h, crc));
    /* the link name carries the CRC (stale headers do not link) */
    snprintf(crc, sizeof crc, "#define tfit_alpha_forward tfit_alpha_forward_%08x", want);
    assert_non_null(strstr(h, crc));

    /* Every literal of the coefficient table reads back to the same float. */
    char *p = strstr(h, "tfit_alpha_forward_coef[");
    assert_non_null(p);
    p = strchr(p, '{') + 1;
    uint32_t i = 0;
    while (i < two_models[0]->n_coef) {
        while (*p == ' ' || *p == '\n' || *p == ',') {
            ++p;
        }
        if (p[0] == '/' && p[1] == '*') {
            p = strstr(p, "*/") + 2;
            continue;
        }
        char *end;
        float v = strtof(p, &end);
        assert_true(end != p && *end == 'f');
        assert_memory_equal(&v, &two_models[0]->coef[i], sizeof v);
        p = end + 1;
        ++i;
    }
    free(h);
    free_models();
}

/* Two emissions of the same models to two files (same name, two folders:
 * the name is part of the content) are byte-identical; writing both to one
 * path would compare a file with itself. */
static void emission_is_deterministic(void **state)
{
    (void)state;
    char da[300], db[300], a[320], b[320], ga[340], gb[340];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    snprintf(da, sizeof da, "%s/first", dir);
    snprintf(db, sizeof db, "%s/second", dir);
    assert_int_equal(mkdir(da, 0700), 0);
    assert_int_equal(mkdir(db, 0700), 0);
    snprintf(a, sizeof a, "%s/same.h", da);
    snprintf(b, sizeof b, "%s/same.h", db);
    make_models(2);
    assert_int_equal(tf_emit_header(&ctx, a, two_models, 2, &info), 0);
    size_t la, lb, lga, lgb;
    char *h1 = slurp(a, &la);
    tf_golden_path(a, ga, sizeof ga);
    char *g1 = slurp(ga, &lga);
    assert_int_equal(tf_emit_header(&ctx, b, two_models, 2, &info), 0);
    char *h2 = slurp(b, &lb);
    tf_golden_path(b, gb, sizeof gb);
    char *g2 = slurp(gb, &lgb);
    assert_int_equal(la, lb);
    assert_memory_equal(h1, h2, la);
    assert_int_equal(lga, lgb);
    assert_memory_equal(g1, g2, lga);
    free(h1);
    free(h2);
    free(g1);
    free(g2);
    free_models();
    assert_int_equal(unlink(a) | unlink(ga) | unlink(b) | unlink(gb), 0);
    assert_int_equal(rmdir(da) | rmdir(db), 0);
}

static void failure_writes_nothing(void **state)
{
    (void)state;
    char path[300];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    int before = files_in_dir();

    make_models(3);
    snprintf(path, sizeof path, "%s/Bad-Name.h", dir);
    assert_int_equal(tf_emit_header(&ctx, path, two_models, 2, &info), -1);
    assert_non_null(strstr(ctx.err, "C identifier"));
    assert_int_equal(files_in_dir(), before);

    /* An existing header survives a failed regeneration untouched. */
    snprintf(path, sizeof path, "%s/keep.h", dir);
    assert_int_equal(tf_emit_header(&ctx, path, two_models, 2, &info), 0);
    char *old = slurp(path, NULL);
    int with_old = files_in_dir();
    two_models[1]->coef[TFIT_INPUT_MAP_FLOATS + 2] = NAN;
    assert_int_equal(tf_emit_header(&ctx, path, two_models, 2, &info), -1);
    assert_non_null(strstr(ctx.err, "alpha_contact"));
    assert_non_null(strstr(ctx.err, "not finite"));
    char *now = slurp(path, NULL);
    assert_string_equal(old, now);
    assert_int_equal(files_in_dir(), with_old);
    free(old);
    free(now);

    assert_int_equal(tf_emit_header(&ctx, "/nonexistent-dir/x.h", two_models, 1, &info), -1);
    assert_non_null(strstr(ctx.err, "/nonexistent-dir/x.h"));

    tf_model *dup[2] = {two_models[0], two_models[0]};
    snprintf(path, sizeof path, "%s/dup.h", dir);
    assert_int_equal(tf_emit_header(&ctx, path, dup, 2, &info), -1);
    assert_non_null(strstr(ctx.err, "two models"));
    assert_int_equal(files_in_dir(), with_old);
    free_models();
}

/* The header carries the CRC-32 of its golden file up to the pairing check,
 * and the golden file compares it at compile time; hostile text copied into
 * the banner is escaped (issue 19). */
static void the_pair_names_each_other(void **state)
{
    (void)state;
    char path[300], gpath[300];
    make_models(5);
    snprintf(path, sizeof path, "%s/pair.h", dir);
    snprintf(gpath, sizeof gpath, "%s/pair_golden.h", dir);
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const tf_emit_info hostile = {.source = "a*/b/*c?\?/\\d\ne.yaml", .notes = "x */ y /* z",
                                  .golden_seed = 3};
    assert_int_equal(tf_emit_header(&ctx, path, two_models, 2, &hostile), 0);
    size_t glen;
    char *h = slurp(path, NULL), *g = slurp(gpath, &glen);
    assert_non_null(h);
    assert_non_null(g);
    char *check = strstr(g, "\n/* pair.h carries the CRC-32 of this file up to here. */");
    assert_non_null(check);
    uint32_t crc = (uint32_t)crc32(crc32(0L, Z_NULL, 0), (const Bytef *)g, (uInt)(check - g));
    char want[96];
    snprintf(want, sizeof want, "#define TFIT_PAIR_GOLDEN_CRC32 0x%08xu\n", crc);
    assert_non_null(strstr(h, want));
    snprintf(want, sizeof want, "TFIT_PAIR_GOLDEN_CRC32 != 0x%08xu\n#error", crc);
    assert_non_null(strstr(g, want));
    assert_non_null(strstr(h, " * source: a* /b/ *c? ?/\\x5cd\\x0ae.yaml\n"));
    assert_non_null(strstr(h, " * x * / y / * z\n"));
    free(h);
    free(g);
    free_models();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(header_content_and_exact_literals, setup, teardown),
        cmocka_unit_test_setup_teardown(emission_is_deterministic, setup, teardown),
        cmocka_unit_test_setup_teardown(failure_writes_nothing, setup, teardown),
        cmocka_unit_test_setup_teardown(the_pair_names_each_other, setup, teardown),
    };
    return cmocka_run_group_tests_name("emit_header", tests, NULL, NULL);
}
