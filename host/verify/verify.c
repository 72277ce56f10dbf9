/*
 * verify.c — convergence studies against analytic references (verify.h).
 */
#include "verify/verify.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "verify/error_norm.h"
#include "scene/scene.h"
#include "solvers/solver.h"
#include "solvers/solver_report.h"

/* The overrides that turn the base scene into level k. */
static void level_sets(const tf_scene *b, tf_vary vary, unsigned k, char sets[4][160], size_t *n)
{
    if (vary == TF_VARY_GAUSS) {
        snprintf(sets[0], sizeof sets[0], "solver.gauss=%u", k + 1);
        *n = 1;
        return;
    }
    double f = ldexp(1.0, (int)k), hi[3];
    unsigned grid[3], cells[3];
    for (int a = 0; a < 3; ++a) {
        int thin = b->grid[a] == 2;
        grid[a] = thin ? 2 : (b->grid[a] - 1) * (1u << k) + 1;
        cells[a] = thin ? b->solver.cells[a] : b->solver.cells[a] * (1u << k);
        hi[a] = thin ? b->box_min[a] + (b->box_max[a] - b->box_min[a]) / f : b->box_max[a];
    }
    snprintf(sets[0], sizeof sets[0], "geometry.grid=%u,%u,%u", grid[0], grid[1], grid[2]);
    snprintf(sets[1], sizeof sets[1], "geometry.box.max=%.17g,%.17g,%.17g", hi[0], hi[1], hi[2]);
    snprintf(sets[2], sizeof sets[2], "solver.cells=%u,%u,%u", cells[0], cells[1], cells[2]);
    snprintf(sets[3], sizeof sets[3], "solver.rbf.d_c=%.17g", b->solver.d_c / f);
    *n = 4;
}

static tf_scene *level_scene(const char *path, const char *const *sets, size_t n_sets,
                             tf_vary vary, unsigned k, char *err, size_t errlen)
{
    tf_scene *base = tf_scene_load(path, sets, n_sets, err, errlen);
    if (base == NULL) {
        return NULL;
    }
    char extra[4][160];
    size_t n_extra;
    level_sets(base, vary, k, extra, &n_extra);
    tf_scene_free(base);
    const char **all = malloc((n_sets + n_extra) * sizeof *all);
    if (all == NULL) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    for (size_t i = 0; i < n_sets; ++i) {
        all[i] = sets[i];
    }
    for (size_t i = 0; i < n_extra; ++i) {
        all[n_sets + i] = extra[i];
    }
    tf_scene *s = tf_scene_load(path, all, n_sets + n_extra, err, errlen);
    free(all);
    return s;
}

int tf_verify_level(const char *scene_path, const char *const *sets, size_t n_sets, tf_vary vary,
                    unsigned k, tf_verify_row *row, int *usage, char *err, size_t errlen)
{
    *usage = 1;
    tf_scene *s = level_scene(scene_path, sets, n_sets, vary, k, err, errlen);
    if (s == NULL) {
        return -1;
    }
    if (s->reference.kind == TF_REF_NONE) {
        snprintf(err, errlen, "%s: the scene has no reference section to verify against",
                 scene_path);
        tf_scene_free(s);
        return -1;
    }
    *usage = 0;
    double t0 = omp_get_wtime();
    tf_solver *sv = tf_solver_new(s, err, errlen);
    double *u = malloc(3 * s->cloud.n * sizeof *u);
    int rc = sv && u ? tf_solver_solve(sv, -1, NULL, 1, u, err, errlen) : -1;
    if (rc == 0) {
        row->seconds = omp_get_wtime() - t0;
        tf_solver_report(sv, s);
        rc = tf_error_norms(tf_solver_shape(sv), s, u, TF_VERIFY_ERROR_ORDER, &row->error_l2,
                            &row->error_energy, err, errlen);
    } else if (u == NULL) {
        snprintf(err, errlen, "out of memory");
    }
    row->level = vary == TF_VARY_GAUSS ? s->solver.gauss : k;
    row->nodes = s->cloud.n;
    row->dofs = 3 * s->cloud.n;
    row->h = 0;
    for (int a = 0; a < 3 && row->h == 0; ++a) {
        row->h = s->grid[a] > 2 ? s->cloud.spacing[a] : 0;
    }
    row->rate = NAN;
    free(u);
    tf_solver_free(sv);
    tf_scene_free(s);
    return rc;
}

void tf_verify_rates(tf_verify_row *rows, size_t n)
{
    for (size_t k = 1; k < n; ++k) {
        double dh = log(rows[k - 1].h / rows[k].h);
        rows[k].rate = dh != 0 ? log(rows[k - 1].error_l2 / rows[k].error_l2) / dh : NAN;
    }
}
