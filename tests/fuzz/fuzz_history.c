/*
 * fuzz_history.c — libFuzzer target: arbitrary bytes as a load-history
 * table.  The bytes are written to table.csv beside a fixed small scene
 * whose `history: {table: table.csv}` names it, and the scene is loaded as
 * the tool loads it (tf_scene_load: base/input_file.c's bounded read, then
 * scene_history.c's rows, header, byte-order mark, NUL, range and order
 * checks).  A table the scene accepts is then sampled as `tissuefit solve`
 * samples it (tf_history_sample), and the samples are checked: times
 * non-decreasing and ending at the duration, forces finite and within the
 * table's bound.  Built with ASan + UBSan; a crash, a leak, undefined
 * behaviour, a broken invariant (abort) or a run over the time limit is a
 * finding.  tests/fuzz.mk runs it.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "problem/history.h"
#include "scene/scene.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* scene_history.c's bound on a table's forces, N. */
#define FORCE_MAX 1e6

static char dir[512], scene_path[600], table_path[600];

static void remove_files(void)
{
    unlink(table_path);
    unlink(scene_path);
    rmdir(dir);
}

/* A block48-like box on a coarse grid (a load is fast), one contact site
 * for the table's force, 17 steps of 0.25 s. */
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    const char *tmp = getenv("TMPDIR");
    snprintf(dir, sizeof dir, "%s/fuzz_history_XXXXXX", tmp && *tmp ? tmp : "/tmp");
    if (mkdtemp(dir) == NULL) {
        perror("fuzz_history: mkdtemp");
        exit(2);
    }
    snprintf(scene_path, sizeof scene_path, "%s/scene.yaml", dir);
    snprintf(table_path, sizeof table_path, "%s/table.csv", dir);
    FILE *f = fopen(scene_path, "w");
    if (f == NULL) {
        perror("fuzz_history: scene");
        exit(2);
    }
    fprintf(f, "name: fuzz_history\n"
               "geometry: {box: {min: [0, 0, 0], max: [48, 48, 6]}, grid: [5, 5, 2]}\n"
               "material: {E: 0.32, nu: 0.49}\n"
               "fixed: [{face: x-}, {face: x+}]\n"
               "contact: [{name: top-centre, node: 38}]\n"
               "outputs: {select: face, face: z+}\n"
               "history: {dt: 0.25, duration: 4.1, table: table.csv}\n");
    fclose(f);
    atexit(remove_files);
    return 0;
}

/* What tf_history_sample must give for an accepted table. */
static void check_samples(const tf_history *h, const tf_samples *s)
{
    if (s->n == 0 || s->t[s->n - 1] != h->duration) {
        fprintf(stderr, "fuzz_history: %zu samples, the last not at the duration\n", s->n);
        abort();
    }
    for (size_t k = 0; k < s->n; ++k) {
        if (!(s->t[k] >= 0) || (k > 0 && !(s->t[k] >= s->t[k - 1]))) {
            fprintf(stderr, "fuzz_history: sample %zu at t = %g: times not ordered\n", k,
                    s->t[k]);
            abort();
        }
        for (int a = 0; a < 3; ++a) {
            /* linear between two rows within the bound (one rounding) */
            if (!(fabs(s->force[k][a]) <= FORCE_MAX * (1 + 1e-15))) {
                fprintf(stderr, "fuzz_history: sample %zu: force %g N\n", k, s->force[k][a]);
                abort();
            }
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FILE *f = fopen(table_path, "wb");
    if (f == NULL || fwrite(data, 1, size, f) != size || fclose(f) != 0) {
        perror("fuzz_history: table");
        abort();
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = tf_scene_load(&ctx, scene_path, NULL, 0);
    if (s != NULL) {
        tf_samples smp;
        if (tf_history_sample(&s->problem.history, &smp) == 0) {
            check_samples(&s->problem.history, &smp);
            tf_samples_free(&smp);
        }
        tf_scene_free(s);
    }
    return 0;
}
