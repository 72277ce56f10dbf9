/*
 * scene_run.c — see scene_run.h.
 */
#include "scene_run.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

tf_scene_run *tf_scene_run_solve(const char *scene, const tf_solver_ops *type,
                                 const char *const *sets, size_t n_sets, int threads,
                                 const double (*forces)[3], size_t n)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene_run *r = calloc(1, sizeof *r);
    tf_ctx_init(&r->ctx);
    r->ctx.level = TF_LOG_ERROR;
    r->ctx.threads = threads;
    r->scene = tf_scene_load(&ctx, scene, sets, n_sets);
    if (r->scene == NULL) {
        fail_msg("%s", ctx.err);
    }
    r->p = &r->scene->problem;
    r->solver = type ? tf_solver_create_as(type, r->p, NULL, &r->ctx)
                     : tf_solver_create(r->p, NULL, &r->ctx);
    if (r->solver == NULL) {
        fail_msg("%s", r->ctx.err);
    }
    r->n3 = 3 * tf_solver_node_count(r->solver);
    r->u = malloc(r->n3 * n * sizeof *r->u);
    if (tf_solver_solve(r->solver, forces ? 0 : -1, forces, n, NULL, r->u) != 0) {
        fail_msg("%s: %s", tf_solver_name(r->solver), r->ctx.err);
    }
    return r;
}

void tf_scene_run_free(tf_scene_run *r)
{
    free(r->u);
    tf_solver_destroy(r->solver);
    tf_scene_free(r->scene);
    free(r);
}

int tf_scene_run_balance(const tf_scene_run *r, const double force[3], const double *u,
                         double sum[3], double *resid)
{
    double *react = malloc(r->n3 * sizeof *react);
    unsigned char *fixed = malloc(r->n3);
    tf_problem_fixed_dofs(r->p, fixed);
    int rc = tf_solver_reactions(r->solver, 0, force, u, react);
    sum[0] = sum[1] = sum[2] = *resid = 0;
    for (size_t d = 0; rc == 0 && d < r->n3; ++d) {
        if (fixed[d]) {
            sum[d % 3] += react[d];
        } else {
            *resid = fmax(*resid, fabs(react[d]));
        }
    }
    free(fixed);
    free(react);
    return rc;
}

double tf_max_abs(const double *v, size_t n)
{
    double m = 0;
    for (size_t i = 0; i < n; ++i) {
        m = fmax(m, fabs(v[i]));
    }
    return m;
}
