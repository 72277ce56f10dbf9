/*
 * test_scene_hostile.c — scene files and --set values a careless user or an
 * attacker would write (issue 19): numbers with trailing text, loose whole
 * numbers and booleans, a second document, aliases, bad UTF-8 and binary
 * bytes, physically absurd values, overlong --set values, paths that are
 * not regular files, and load-history tables gone wrong.  Each is refused with file:line:field (or the --set
 * argument) and a message that says what is wrong.
 */
#include <fcntl.h>
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

#include "scene/scene.h"
#include "scene_refused.h"

#define BLOCK48 "tests/solver/block48_seed.yaml"

/* tf_test_scene (scene_refused.h) with line `line` replaced by `with`. */
static void refused(int line, const char *with, const char *const *fragments)
{
    tf_test_refused(line, 1, with, fragments);
}

static void refused_text(const char *text, size_t len, const char *const *fragments)
{
    tf_test_refused_text(text, len, fragments);
}

#define FRAGS(...) ((const char *const[]){__VA_ARGS__, NULL})

static void numbers_with_trailing_text(void **state)
{
    (void)state;
    refused(7, "  nu: 0,45\n", FRAGS("t.yaml:7: material.nu: '0,45' is not a number"));
    refused(6, "  E: 3,2\n", FRAGS("t.yaml:6: material.E: '3,2' is not a number"));
    refused(6, "  E: 0.32 MPa\n", FRAGS("t.yaml:6: material.E: '0.32 MPa' is not a number"));
    refused(6, "  E: 0x1p3\n", FRAGS("t.yaml:6: material.E:", "not a number"));
    refused(6, "  E: nan\n", FRAGS("t.yaml:6: material.E:", "not a number"));
    refused(6, "  E: \"1 \"\n", FRAGS("t.yaml:6: material.E:", "not a number"));
    refused(3, "  box: {min: [0, 0, 0], max: [10, 10, 2mm]}\n",
            FRAGS("t.yaml:3: geometry.box.max.2: '2mm' is not a number"));
}

static void loose_whole_numbers_and_booleans(void **state)
{
    (void)state;
    refused(4, "  grid: [011, 5, 2]\n", FRAGS("t.yaml:4: geometry.grid.0: '011' has a leading zero"));
    refused(4, "  grid: [11.5, 5, 2]\n", FRAGS("t.yaml:4: geometry.grid.0: '11.5' is not a"));
    refused(11, "  - node: 61.9\n", FRAGS("t.yaml:11: contact.0.node: '61.9' is not a"));
    refused(11, "  - node: +13\n", FRAGS("t.yaml:11: contact.0.node:", "whole number"));
    refused(1, "name: t\nfit: {seed: -1}\n", FRAGS("t.yaml:2: fit.seed: '-1' is not a non-negative"));
    refused(9, "  - {face: z-, exact: maybe}\n", FRAGS("t.yaml:9: fixed.0.exact: 'maybe' is not true or false"));
}

static void one_document_no_aliases(void **state)
{
    (void)state;
    char text[2048];
    snprintf(text, sizeof text, "%s---\nname: other\n", tf_test_scene);
    refused_text(text, strlen(text), FRAGS("t.yaml:15:", "second YAML document"));
    const char *alias = "name: t\n"
                        "geometry:\n"
                        "  box: &b {min: [0, 0, 0], max: [10, 10, 2]}\n"
                        "  grid: [5, 5, 2]\n"
                        "material: {E: 1.0, nu: 0.3}\n"
                        "fixed:\n"
                        "  - box: *b\n"
                        "outputs: {select: all}\n";
    refused_text(alias, strlen(alias),
                 FRAGS("t.yaml:7: fixed.0.box: aliases (*b) are not supported"));
}

static void syntax_errors_have_lines(void **state)
{
    (void)state;
    refused_text("[1, 2]\n", 7, FRAGS("t.yaml:1: expected a mapping of keys", "got a list"));
    refused_text("\n\nhello\n", 8, FRAGS("t.yaml:3: expected a mapping of keys"));
    refused(2, "? [a]\n: b\ngeometry:\n", FRAGS("t.yaml:2: a key must be a plain word"));
    refused(7, "  nu: 0.3\xff\xfe\n", FRAGS("t.yaml:7:", "YAML syntax error", "UTF-8"));
    refused(12, "outputs:\x01\x02\x03\n", FRAGS("t.yaml:12:", "YAML syntax error", "control"));
    const char garbage[] = "\x7f" "ELF\x02\x01\x01\x00\x00\x00\n\x00\x00";
    refused_text(garbage, sizeof garbage - 1, FRAGS("t.yaml:1:", "YAML syntax error"));
}

static void absurd_values_fail_up_front(void **state)
{
    (void)state;
    refused(6, "  E: 1e308\n", FRAGS("t.yaml:6: material.E: Young's modulus", "1e+308"));
    refused(6, "  E: 5e-324\n", FRAGS("t.yaml:6: material.E: Young's modulus", "positive"));
    refused(6, "  E: 1e999\n", FRAGS("t.yaml:6: material.E:", "inf"));
    refused(1, "name: t\nenvelope: {radius: 1e308}\n",
            FRAGS("t.yaml:2: envelope.radius: the envelope radius", "1e+308"));
    refused(3, "  box: {min: [0, 0, 0], max: [1e300, 10, 2]}\n",
            FRAGS("t.yaml:3: geometry.box.max.0: coordinates"));
    refused(1, "name: t\nsolver: {penalty: 1e300}\n",
            FRAGS("t.yaml:2: solver.penalty: numbers in a scene are 0 or between"));
    refused(1, "name: t\nsolver: {support: 1e-16}\n", FRAGS("t.yaml:2: solver.support:"));
}

/* Cuts the solve cannot take are refused at their entry before it: one
 * far shallower or shorter than the node spacing (1e-15 mm deep changed
 * the answer by 1.7 %), a path folding onto itself, a cut along a face,
 * and one leaving a node's support with its visible nodes in one plane
 * (that solve failed with "MLS moment matrix singular ... raise
 * solver.support", naming no cut).  The box is 10 x 10 x 2 mm at 2.5 x
 * 2.5 x 2 mm spacing. */
static void cuts_fail_at_their_entry(void **state)
{
    (void)state;
    refused(1, "name: t\ncuts:\n  - {path: [[5, 0], [5, 10]], depth: 1e-15}\n",
            FRAGS("t.yaml:3: cuts.0.depth: 1e-15 mm deep, under 0.001 of the node spacing there "
                  "(2 mm)"));
    refused(1, "name: t\ncuts:\n  - {path: [[5, 5], [5, 5.000001]], depth: 1}\n",
            FRAGS("t.yaml:3: cuts.0.path: 1e-06 mm long, under 0.001 of the node spacing"));
    refused(1, "name: t\ncuts:\n  - {path: [[2, 5], [8, 5], [4, 5]], depth: 1}\n",
            FRAGS("t.yaml:3: cuts.0.path.2: the path doubles back along the segment before"));
    refused(1, "name: t\ncuts:\n  - {path: [[2, 2], [8, 8], [8, 2], [2, 8], [2, 2]], depth: 1}\n",
            FRAGS("t.yaml:3: cuts.0.path: a closed path that encloses no area"));
    refused(1, "name: t\ncuts:\n  - {path: [[0, 2], [0, 8]], depth: 1}\n",
            FRAGS("t.yaml:3: cuts.0.path: runs along the box's x- face (x = 0)"));
    refused(1, "name: t\ncuts:\n  - {path: [[3, 3], [7, 3]], depth: 1}\n"
               "  - {path: [[0.5, 0], [0.5, 10]], depth: 2}\n",
            FRAGS("t.yaml:4: cuts.1.path: hides", "node 1 at (0, 0, 2) mm",
                  "all in one plane, so the local systems there are singular"));
}

/* Clamps that leave nothing to move, or leave the body free to turn, are
 * refused at their entry (they failed in the solver, naming no entry:
 * "every degree of freedom is fixed", "not positive definite"). */
static void clamps_fail_at_their_entry(void **state)
{
    (void)state;
    refused(9, "  - box: {min: [-1, -1, -1], max: [11, 11, 3]}\n",
            FRAGS("t.yaml:9: fixed.0: this region holds every node of the body (50)"));
    refused(9, "  - box: {min: [-1, -1, -1], max: [1, 1, 1]}\n",
            FRAGS("t.yaml:9: fixed.0: this region holds 1 node (the first at (0, 0, 0) mm)",
                  "free to turn", "singular"));
    refused(9, "  - box: {min: [-1, -1, -1], max: [11, 1, 1]}\n",
            FRAGS("t.yaml:9: fixed.0: this region holds 5 nodes", "free to turn"));
    refused(9, "  - {face: z-, components: [x, y]}\n",
            FRAGS("t.yaml:9: fixed.0:", "free to slide"));
    refused(9, "  - box: {min: [-1, -1, -1], max: [11, 11, 1]}\n  - face: z+\n",
            FRAGS("t.yaml:9: fixed: the fixed regions together hold every component of every "
                  "node (50 nodes): nothing is left to move"));
}

static void set_values_get_the_same_checks(void **state)
{
    (void)state;
    const char *bad[][2] = {
        {"material.nu=0,45", "--set material.nu=0,45: material.nu: '0,45' is not a number"},
        {"material.E=1e308", "--set material.E=1e308: material.E: Young's modulus"},
        {"material={E: 5e-324, nu: 0.3}", "material.E: Young's modulus"},
        {"geometry.grid=011,11,3", "geometry.grid.0: '011' has a leading zero"},
        {"fit.seed=-1", "fit.seed: '-1' is not a non-negative whole number"},
        {"fixed=[{face: x-}, *a]", "aliases (*a)"},
        /* a cut listed twice changed the answer by 26 %; a closed cut
         * through the full height freed a plug nothing holds */
        {"cuts=[{path: [[10, 0], [10, 10]], depth: 5}, {path: [[10, 0], [10, 10]], depth: 5}]",
         "cuts.1.path: repeats cuts.0"},
        {"cuts=[{path: [[12, 12], [36, 12], [36, 36], [12, 36], [12, 12]], depth: 6}]",
         "cuts.0.path: a closed cut through the full height frees a plug of"},
        /* each axis within its range, the product past what memory holds */
        {"solver.cells=4096,4096,8",
         "solver.cells: 4096 x 4096 x 8 = 134217728 background cells, more than 1000000"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        tf_ctx ctx;
        tf_ctx_init(&ctx);
        tf_scene *s = tf_scene_load(&ctx, BLOCK48, &bad[k][0], 1);
        assert_null(s);
        if (strstr(ctx.err, bad[k][1]) == NULL) {
            fail_msg("--set %s: message '%s' lacks '%s'", bad[k][0], ctx.err, bad[k][1]);
        }
    }
}

/* A value of 2,000 characters: the reason is in the message, which shows
 * only the start of the argument; a long valid value is read whole. */
static void long_set_values(void **state)
{
    (void)state;
    char set[2100];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    int n = snprintf(set, sizeof set, "name=");
    memset(set + n, 'a', 2000);
    set[n + 2000] = '\0';
    const char *sets[] = {set};
    assert_null(tf_scene_load(&ctx, BLOCK48, sets, 1));
    if (strstr(ctx.err, "(2005 characters): name: at most 63 characters") == NULL) {
        fail_msg("%s", ctx.err);
    }
    n = snprintf(set, sizeof set, "outputs={select: nodes, nodes: [");
    for (int k = 0; k < 300; ++k) {
        n += snprintf(set + n, sizeof set - (size_t)n, "%s%d", k ? ", " : "", 1 + k % 363);
    }
    snprintf(set + n, sizeof set - (size_t)n, "]}");
    assert_true(strlen(set) > 1100);
    tf_scene *s = tf_scene_load(&ctx, BLOCK48, sets, 1);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    assert_int_equal(s->problem.outputs.n_nodes, 300);
    tf_scene_free(s);
}

/* A FIFO blocked the reader forever (alarm: the test fails rather than
 * hangs); a directory or a device is not a scene; the size is capped. */
static void scene_paths_that_are_not_files(void **state)
{
    (void)state;
    char dir[] = "/tmp/tf_hostile_XXXXXX", fifo[64], big[64];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_non_null(mkdtemp(dir));
    snprintf(fifo, sizeof fifo, "%s/fifo.yaml", dir);
    snprintf(big, sizeof big, "%s/big.yaml", dir);
    assert_int_equal(mkfifo(fifo, 0600), 0);
    alarm(20);
    assert_null(tf_scene_load(&ctx, fifo, NULL, 0));
    alarm(0);
    assert_non_null(strstr(ctx.err, "fifo.yaml: not a regular file"));
    assert_null(tf_scene_load(&ctx, dir, NULL, 0));
    assert_non_null(strstr(ctx.err, "not a regular file"));
    assert_null(tf_scene_load(&ctx, "/dev/zero", NULL, 0));
    assert_non_null(strstr(ctx.err, "/dev/zero: not a regular file"));
    int fd = open(big, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    assert_true(fd >= 0);
    assert_int_equal(ftruncate(fd, TF_SCENE_MAX_BYTES + 1), 0);
    close(fd);
    assert_null(tf_scene_load(&ctx, big, NULL, 0));
    assert_non_null(strstr(ctx.err, "more than the 16 MiB a scene file may hold"));
    unlink(fifo);
    unlink(big);
    rmdir(dir);
}

/* A load-history table written to dir/table.csv (len bytes of text), read
 * through a scene beside it: returns the scene (NULL: refused, the message
 * in ctx). */
static tf_scene *with_table(tf_ctx *ctx, const char *dir, const char *table, const char *text,
                            size_t len)
{
    char scene[128], path[128];
    snprintf(scene, sizeof scene, "%s/t.yaml", dir);
    FILE *f = fopen(scene, "w");
    assert_non_null(f);
    fprintf(f, "name: t\n"
               "geometry: {box: {min: [0, 0, 0], max: [48, 48, 6]}, grid: [5, 5, 2]}\n"
               "material: {E: 0.32, nu: 0.49}\n"
               "fixed: [{face: x-}]\n"
               "contact: [{name: top, node: 13}]\n"
               "outputs: {select: face, face: z+}\n"
               "history: {dt: 0.5, duration: 2, table: %s}\n",
            table);
    fclose(f);
    if (text != NULL) {
        snprintf(path, sizeof path, "%s/%s", dir, table);
        f = fopen(path, "wb");
        assert_non_null(f);
        assert_int_equal(fwrite(text, 1, len, f), len);
        fclose(f);
    }
    tf_ctx_init(ctx);
    alarm(20); /* a reader that blocks or loops fails the test rather than hangs it */
    tf_scene *s = tf_scene_load(ctx, scene, NULL, 0);
    alarm(0);
    return s;
}

/* Refused, the message holding fragment. */
static void table_refused(const char *dir, const char *text, size_t len, const char *fragment)
{
    tf_ctx ctx;
    tf_scene *s = with_table(&ctx, dir, "table.csv", text, len);
    if (s != NULL) {
        tf_scene_free(s);
        fail_msg("a table of %zu bytes beginning '%.20s' was accepted", len, text);
    }
    if (strstr(ctx.err, fragment) == NULL) {
        fail_msg("'%s' lacks '%s'", ctx.err, fragment);
    }
}

/* Accepted with rows rows, the first at time t0. */
static void table_rows(const char *dir, const char *text, size_t rows, double t0)
{
    tf_ctx ctx;
    tf_scene *s = with_table(&ctx, dir, "table.csv", text, strlen(text));
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    assert_int_equal(s->problem.history.n_rows, rows);
    assert_true(s->problem.history.table[0] == t0);
    tf_scene_free(s);
}

#define TEXT(t) t, sizeof t - 1

/* Load-history tables: a device, a FIFO, a binary file; a malformed first
 * data row (never dropped as a header); a line longer than any buffer; a
 * force beyond the double range's use; a byte-order mark. */
static void history_tables(void **state)
{
    (void)state;
    char dir[] = "/tmp/tf_table_XXXXXX", fifo[64];
    tf_ctx ctx;
    assert_non_null(mkdtemp(dir));
    assert_null(with_table(&ctx, dir, "/dev/zero", NULL, 0));
    assert_non_null(strstr(ctx.err, "/dev/zero: not a regular file"));
    snprintf(fifo, sizeof fifo, "%s/fifo.csv", dir);
    assert_int_equal(mkfifo(fifo, 0600), 0);
    assert_null(with_table(&ctx, dir, "fifo.csv", NULL, 0));
    assert_non_null(strstr(ctx.err, "fifo.csv: not a regular file"));
    unlink(fifo);
    table_refused(dir, TEXT("0,0,0,-1\n1,0\0,0,-1\n"), "holds a NUL byte");
    /* a first row that is data gone wrong: a typo, a unit, three numbers,
     * a quoted decimal comma */
    table_refused(dir, TEXT("0, 0, 0, -1x\n1, 0, 0, -1\n"), "table.csv:1: expected four numbers");
    table_refused(dir, TEXT("0 s, 0 N, 0 N, -1 N\n"), "table.csv:1: expected four numbers");
    table_refused(dir, TEXT("0, 0, -1\n1, 0, 0, -1\n"), "table.csv:1: expected four numbers");
    table_refused(dir, TEXT("\"0,5\", 0, 0, -1\n"), "table.csv:1: expected four numbers");
    table_refused(dir, TEXT("t,fx,fy,fz\n0, 0, 0, -1e308\n"), "table.csv:2: force -1e+308 N");
    /* two rows' numbers on one 600-byte line are one bad row */
    char line[700];
    int n = snprintf(line, sizeof line, "0, 0, 0, -1%*s1, 0, 0, -1\n", 580, "");
    table_refused(dir, line, (size_t)n, "table.csv:1: expected four numbers");
    table_rows(dir, "\xEF\xBB\xBF" "0.5, 0, 0, -1\n1, 0, 0, -1\n", 2, 0.5);
    table_rows(dir, "# a comment\ntime_s,fx_N,fy_N,fz_N\n0.25, 0, 0, -1\n", 1, 0.25);
    char path[128];
    snprintf(path, sizeof path, "%s/t.yaml", dir);
    unlink(path);
    snprintf(path, sizeof path, "%s/table.csv", dir);
    unlink(path);
    rmdir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(numbers_with_trailing_text),
        cmocka_unit_test(history_tables),
        cmocka_unit_test(loose_whole_numbers_and_booleans),
        cmocka_unit_test(one_document_no_aliases),
        cmocka_unit_test(syntax_errors_have_lines),
        cmocka_unit_test(absurd_values_fail_up_front),
        cmocka_unit_test(set_values_get_the_same_checks),
        cmocka_unit_test(cuts_fail_at_their_entry),
        cmocka_unit_test(clamps_fail_at_their_entry),
        cmocka_unit_test(long_set_values),
        cmocka_unit_test(scene_paths_that_are_not_files),
    };
    return cmocka_run_group_tests_name("scene: hostile input", tests, NULL, NULL);
}
