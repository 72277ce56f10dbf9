/*
 * hertz.c — the Hertz test of the collocation solver (hertz.h).
 */
#include "verify/hertz.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>

#include "verify/hertz_cloud.h"

void tf_hertz_defaults(tf_hertz_opts *o)
{
    *o = (tf_hertz_opts){.law = tf_law_find("linear"), .young = 1, .nu = 0.3, .radius = 100,
                         .core = 5, .cells = 8, .levels = 7, .ratio = 2,
                         .indent = {1e-4, 2.5e-4, 4e-4, 6.25e-4}, .n_indent = 4, .tol = 1e-6};
    tf_colloc_defaults(&o->colloc);
}

static int check(const tf_hertz_opts *o, tf_ctx *ctx)
{
    if (o->cells < 2 || o->levels < 1 || o->levels > 40 || !(o->ratio >= 1.2 && o->ratio <= 4) ||
        !(o->core > 0) || !(o->radius > 0) || !(o->young > 0) || !(o->nu > -1 && o->nu < 0.5) ||
        o->n_indent < 1 || o->n_indent > TF_HERTZ_MAX_INDENT || !(o->tol > 0 && o->tol < 1)) {
        return tf_fail(ctx, "hertz: cells >= 2, levels 1..40, ratio 1.2..4, core, radius and E "
                            "> 0, -1 < nu < 0.5, 1..%d indentations, tolerance in (0, 1)",
                       TF_HERTZ_MAX_INDENT);
    }
    if (o->law == NULL || tf_law_param_index(o->law, "E") < 0 ||
        tf_law_param_index(o->law, "nu") < 0) {
        return tf_fail(ctx, "hertz: the law must have a Young's modulus E and a Poisson's ratio "
                            "nu%s%s", o->law ? ": not " : "", o->law ? o->law->name : "");
    }
    for (size_t k = 0; k < o->n_indent; ++k) {
        if (!(o->indent[k] > 0 && o->indent[k] < 0.5)) {
            return tf_fail(ctx, "hertz: indentation d/R = %g must lie in (0, 0.5)", o->indent[k]);
        }
    }
    return 0;
}

static tf_colloc *body(const tf_hertz_opts *o, const tf_hertz_cloud *hc, tf_ctx *ctx)
{
    static const tf_colloc_mirror mirrors[2] = {{0, 0}, {1, 0}};
    tf_colloc_body b = {.n = hc->n, .X = hc->X, .fixed = hc->fixed,
                        .volume = o->seed_volumes ? NULL : hc->volume,
                        .total_volume = hc->volume_total,
                        .material = tf_material_of(o->law),
                        .density = 1e-9, .mirrors = mirrors, .n_mirrors = 2};
    tf_material_set(&b.material, "E", o->young); /* (check: the law has both) */
    tf_material_set(&b.material, "nu", o->nu);
    tf_colloc *c = tf_colloc_new(ctx, &b, &o->colloc);
    if (c == NULL) {
        tf_fail(ctx, "hertz: %s", ctx->err);
        return NULL;
    }
    tf_colloc_sphere s = {.centre = {0, 0, o->radius}, .dir = {0, 0, -1}, .radius = o->radius,
                          .drive = TF_COLLOC_INDENT};
    if (tf_colloc_set_sphere(ctx, c, &s) != 0) {
        tf_colloc_free(c);
        tf_fail(ctx, "hertz: %s", ctx->err);
        return NULL;
    }
    return c;
}

int tf_hertz_run(const tf_hertz_opts *o, tf_hertz_row *rows, tf_ctx *ctx)
{
    if (check(o, ctx) != 0) {
        return -1;
    }
    tf_hertz_cloud hc;
    double h0 = o->core / o->cells;
    if (tf_hertz_cloud_make(&hc, h0, o->cells, o->levels, o->ratio) != 0) {
        return tf_fail(ctx, "hertz: out of memory for the cloud");
    }
    tf_colloc *c = body(o, &hc, ctx);
    if (c == NULL) {
        tf_hertz_cloud_free(&hc);
        return -1;
    }
    double estar = o->young / (1 - o->nu * o->nu), sr = sqrt(o->radius);
    tf_colloc_relax_opts ro;
    tf_colloc_relax_defaults(&ro);
    ro.tol = o->tol;
    int rc = 0;
    for (size_t k = 0; k < o->n_indent && rc == 0; ++k) {
        double d = o->indent[k] * o->radius, t0 = omp_get_wtime();
        tf_colloc_set_travel(c, d);
        tf_colloc_relax_stats st;
        int q = tf_colloc_relax(ctx, c, &ro, &st);
        if (q != 0) {
            rc = tf_fail(ctx, "hertz: d/R = %g: %s", o->indent[k],
                         q < 0 ? ctx->err : "the relaxation did not converge");
            break;
        }
        double F = 4 * tf_colloc_contact_force(c); /* the quarter's, times 4 */
        rows[k] = (tf_hertz_row){.particles = hc.n, .images = tf_colloc_ghosts(c), .h0 = h0,
                                 .L = hc.L, .d = d, .a = sqrt(o->radius * d), .F = F,
                                 .F_theory = 4.0 / 3 * estar * sr * pow(d, 1.5),
                                 .d_theory = pow(3 * F / (4 * estar * sr), 2.0 / 3),
                                 .contacts = tf_colloc_contacts(c), .steps = st.steps,
                                 .seconds = omp_get_wtime() - t0};
    }
    tf_colloc_free(c);
    tf_hertz_cloud_free(&hc);
    return rc;
}

void tf_hertz_errors(const tf_hertz_row *rows, size_t n, double *l2_force, double *l2_indent,
                     double *worst)
{
    double sF = 0, sF0 = 0, sd = 0, sd0 = 0, w = 0;
    for (size_t k = 0; k < n; ++k) {
        const tf_hertz_row *x = rows + k;
        sF += (x->F - x->F_theory) * (x->F - x->F_theory);
        sF0 += x->F_theory * x->F_theory;
        sd += (x->d - x->d_theory) * (x->d - x->d_theory);
        sd0 += x->d_theory * x->d_theory;
        w = fmax(w, fabs(x->d / x->d_theory - 1));
    }
    *l2_force = sqrt(sF / sF0);
    *l2_indent = sqrt(sd / sd0);
    *worst = w;
}
