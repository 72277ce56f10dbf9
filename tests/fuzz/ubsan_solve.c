/*
 * ubsan_solve.c — a small solve of every registered law by every registered
 * solver, under clang's AddressSanitizer and UndefinedBehaviorSanitizer
 * (check-fuzz builds it over the fuzzers' clang build of the host library).
 *
 * The fuzzers read scenes and overrides but never solve, and GCC's UBSan
 * (check-sanitize) has no check for an offset applied to a null pointer,
 * which clang's has: this program takes the solvers' assembly, Newton and
 * relaxation paths through clang's checks.  For each (law, solver) pair: a
 * block48-like box on a 5 x 5 x 2 grid, a static load case, and a two-step
 * load history (the time-dependent path for a law with history).  Any finding aborts (-fno-sanitize-recover=all); a refused
 * scene or a failed solve exits 1 naming the pair.
 *
 * usage: ubsan_solve   (prints one line per pair and a result line)
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/context.h"
#include "materials/material.h"
#include "scene/scene.h"
#include "solvers/solver.h"

/* A value for each parameter key a registered law requires (block48's
 * tissue: coeffs/block48.yaml, coeffs/block48_ve.yaml); a parameter with a
 * fallback takes the law's. */
static const struct {
    const char *key;
    double value;
} values[] = {
    {"E", 0.32}, {"nu", 0.49}, {"k1", 0.32}, {"k2", 0.16}, {"eta", 0.16},
};

static int value_of(const char *key, double *v)
{
    for (size_t i = 0; i < sizeof values / sizeof values[0]; ++i) {
        if (strcmp(values[i].key, key) == 0) {
            *v = values[i].value;
            return 0;
        }
    }
    return -1;
}

/* The scene of law into a temporary file (path: its name).  Returns 0, or
 * -1 naming a parameter this program has no value for. */
static int write_scene(const tf_law_ops *law, char path[64])
{
    strcpy(path, "/tmp/ubsan_solve_XXXXXX");
    int fd = mkstemp(path);
    FILE *f = fd < 0 ? NULL : fdopen(fd, "w");
    if (f == NULL) {
        perror("ubsan_solve: temporary scene");
        return -1;
    }
    fprintf(f, "name: ubsan\n"
               "geometry: {box: {min: [0, 0, 0], max: [48, 48, 6]}, grid: [5, 5, 2]}\n"
               "material: {law: %s",
            law->name);
    for (size_t i = 0; i < law->n_params; ++i) {
        double v;
        if (!isnan(law->params[i].fallback)) {
            continue; /* the law's own value */
        }
        if (value_of(law->params[i].key, &v) != 0) {
            fprintf(stderr, "ubsan_solve: no value for %s's parameter '%s'\n", law->name,
                    law->params[i].key);
            fclose(f);
            return -1;
        }
        fprintf(f, ", %s: %.17g", law->params[i].key, v);
    }
    fprintf(f, "}\n"
               "fixed: [{face: x-}, {face: x+}]\n"
               "contact: [{name: top, node: 13}]\n" /* top face centre (24, 24, 6) */
               "envelope: {radius: 1.0, centre: [0, 0, 0]}\n"
               "outputs: {select: face, face: z+}\n");
    return fclose(f) == 0 ? 0 : -1;
}

/* One pair: a static case and a two-step history.  Returns 0 or -1. */
static int solve_pair(const char *path, const tf_law_ops *law, const tf_solver_ops *type)
{
    static const double forces[2][3] = {{0.1, 0, -0.3}, {0, -0.2, -0.5}};
    char set[96];
    snprintf(set, sizeof set, "solver.method=%s", type->name);
    const char *sets[] = {set};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_ERROR;
    ctx.threads = 2;
    tf_scene *sc = tf_scene_load(&ctx, path, sets, 1);
    tf_solver *s = sc ? tf_solver_create(&sc->problem, NULL, &ctx) : NULL;
    double *u = NULL;
    int rc = -1;
    if (s != NULL) {
        size_t n3 = 3 * tf_solver_node_count(s);
        u = malloc(2 * n3 * sizeof *u);
        rc = u == NULL || tf_solver_solve(s, 0, forces, 1, NULL, u) != 0 ||
                     tf_solver_history(s, 0, forces, 2, 0.05, u) != 0
                 ? -1
                 : 0;
        for (size_t d = 0; rc == 0 && d < 2 * n3; ++d) {
            rc = isfinite(u[d]) ? 0 : -1;
        }
    }
    printf("%s by %s: %s%s\n", law->name, type->name, rc == 0 ? "solved" : "FAILED: ",
           rc == 0 ? "" : ctx.err);
    free(u);
    tf_solver_destroy(s);
    tf_scene_free(sc);
    return rc;
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0); /* a line per pair as it ends */
    size_t pairs = 0, failed = 0;
    for (size_t l = 0; l < tf_law_count(); ++l) {
        const tf_law_ops *law = tf_law_at(l);
        char path[64];
        if (write_scene(law, path) != 0) {
            return 1;
        }
        for (size_t t = 0; t < tf_solver_type_count(); ++t, ++pairs) {
            failed += solve_pair(path, law, tf_solver_type_at(t)) != 0;
        }
        unlink(path);
    }
    if (failed > 0 || pairs == 0) {
        printf("ubsan_solve: %zu of %zu (law, solver) pairs failed\n", failed, pairs);
        return 1;
    }
    printf("ok: %zu (law, solver) pairs solved (a static case, a 2-step history) under clang ASan + "
           "UBSan, no finding\n",
           pairs);
    return 0;
}
