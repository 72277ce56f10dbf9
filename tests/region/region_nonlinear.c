/*
 * region_nonlinear.c — a contact region whose response is not affine
 * (make region-nonlinear): every (site, force) case solved through the
 * case runner, the potential of each site fitted by least squares on its
 * gradient at degrees 2 .. 4, judged at held-out forces at the fitted
 * sites and, blended by the region's splines, at sites never fitted.
 *
 *   region_nonlinear SCENE [--grid N] [--centres K] [--train M]
 *                    [--heldout H] [--rect a0,a1,b0,b1] [KEY=VALUE ...]
 *
 * Sites: an N x N grid over the domain and the first K of its cell
 * centres (never fitted).  Forces (chart frame): M training forces filling
 * the envelope (its six axis points first, then a Halton sequence) and H
 * random held-out forces, the same at every site.  Errors are |F_model(u) -
 * F| / R_F at the solved patch-averaged displacement u of each case.
 */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/context.h"
#include "fitting/force_samples.h"
#include "fitting/region_cases.h"
#include "fitting/region_law.h"
#include "numerics/grid_spline.h"
#include "problem/region_chart.h"
#include "scene/scene.h"

static double norm3(const double v[3]) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

int main(int argc, char **argv)
{
    const char *scene = NULL, *sets[16];
    size_t n_sets = 0;
    unsigned grid = 4, centres = 3, n_train = 24, n_held = 6;
    double rect[4];
    int has_rect = 0;
    for (int i = 1; i < argc; ++i) {
        const char *v = i + 1 < argc ? argv[i + 1] : "";
        if (strcmp(argv[i], "--grid") == 0) {
            grid = (unsigned)atoi(v), i++;
        } else if (strcmp(argv[i], "--centres") == 0) {
            centres = (unsigned)atoi(v), i++;
        } else if (strcmp(argv[i], "--train") == 0) {
            n_train = (unsigned)atoi(v), i++;
        } else if (strcmp(argv[i], "--heldout") == 0) {
            n_held = (unsigned)atoi(v), i++;
        } else if (strcmp(argv[i], "--rect") == 0) {
            has_rect = sscanf(v, "%lf,%lf,%lf,%lf", &rect[0], &rect[1], &rect[2], &rect[3]) == 4;
            i++;
        } else if (argv[i][0] != '-' && scene == NULL) {
            scene = argv[i];
        } else if (argv[i][0] != '-' && n_sets < 16) {
            sets[n_sets++] = argv[i];
        } else {
            scene = NULL;
            break;
        }
    }
    if (scene == NULL || grid < TF_SPLINE_MIN_SITES || n_train < 12 ||
        centres > (grid - 1) * (grid - 1)) {
        fprintf(stderr, "usage: region_nonlinear SCENE [--grid N>=4] [--centres K] [--train M>=12] "
                        "[--heldout H] [--rect a0,a1,b0,b1] [KEY=VALUE ...]\n");
        return 2;
    }
    tf_ctx ec;
    tf_ctx_init(&ec);
    tf_scene *sc = tf_scene_load(&ec, scene, sets, n_sets);
    if (sc == NULL) {
        fprintf(stderr, "%s\n", ec.err);
        return 2;
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    tf_problem *p = &sc->problem;
    tf_contact_region *r = &p->contacts[0].region;
    if (has_rect) {
        memcpy(r->rect, rect, sizeof rect);
        if (tf_region_chart_build(&ctx, p, r) != 0) {
            fprintf(stderr, "--rect: %s\n", ctx.err);
            return 2;
        }
    }
    /* sites: the grid, then cell centres spread over the domain */
    size_t ng = (size_t)grid * grid, n = ng + centres, nf = n_train + n_held;
    double h[2] = {r->chart.len[0] / (grid - 1), r->chart.len[1] / (grid - 1)};
    double *ab = malloc(2 * n * sizeof *ab), (*force)[3] = malloc(nf * sizeof *force);
    for (size_t j = 0; j < grid; ++j) {
        for (size_t i = 0; i < grid; ++i) {
            ab[2 * (j * grid + i)] = i * h[0];
            ab[2 * (j * grid + i) + 1] = j * h[1];
        }
    }
    for (unsigned k = 0; k < centres; ++k) { /* every (grid - 1)^2 / centres-th cell */
        size_t cell = (size_t)k * (grid - 1) * (grid - 1) / centres + (grid - 1) / 2;
        cell %= (size_t)(grid - 1) * (grid - 1);
        ab[2 * (ng + k)] = (cell % (grid - 1) + 0.5) * h[0];
        ab[2 * (ng + k) + 1] = (cell / (grid - 1) + 0.5) * h[1];
    }
    const double zero[3] = {0, 0, 0};
    double R_F = p->envelope.radius;
    tf_force_samples(zero, R_F, n_train, n_held, 7, force, force + n_train);
    tf_region_cases cs;
    if (tf_region_cases_build(&ctx, p, 0, ab, n, (const double(*)[3])force, nf, &cs) != 0) {
        fprintf(stderr, "%s\n", ctx.err);
        return 1;
    }
    double t0 = omp_get_wtime();
    tf_solver *sv = tf_solver_create(&cs.problem, NULL, &ctx);
    if (sv == NULL) {
        fprintf(stderr, "%s\n", ctx.err);
        return 1;
    }
    printf("%s: %s, %zu nodes; %u x %u sites (spacing %.3g mm) and %u cell centres x %zu forces "
           "(%u training, %u held out), envelope %g N; solver set-up %.1f s\n",
           p->name, tf_solver_name(sv), p->cloud.n, grid, grid, h[0], centres, nf, n_train,
           n_held, R_F, omp_get_wtime() - t0);
    size_t n3 = 3 * p->cloud.n;
    double *kept = malloc(n3 * nf * sizeof *kept), (*u)[3] = malloc(n * nf * sizeof *u);
    double t1 = omp_get_wtime();
    for (size_t s = 0; s < n; ++s) {
        tf_case_list l;
        tf_region_cases_list(&cs, s, &l);
        if (tf_case_run(NULL, sv, &l, kept) != 0) {
            fprintf(stderr, "site %zu: %s\n", s, ctx.err);
            return 1;
        }
        for (size_t k = 0; k < nf; ++k) {
            if (tf_region_cases_average(&ctx, sv, &cs, s, kept + k * n3, u[s * nf + k]) != 0) {
                fprintf(stderr, "%s\n", ctx.err);
                return 1;
            }
        }
    }
    double t_solve = omp_get_wtime() - t1, umax = 0;
    printf("%zu cases solved in %.1f s (%.2f s per case, 1 process)\n", n * nf, t_solve,
           t_solve / (double)(n * nf));
    for (size_t s = 0; s < ng; ++s) {
        for (size_t k = 0; k < n_train; ++k) {
            umax = fmax(umax, norm3(u[s * nf + k]));
        }
    }
    double s_u = 1 / umax;
    printf("largest patch-averaged displacement %.3g mm (s_u = 1 / that)\n\n", umax);
    printf("| P | terms | fitted sites: training rms %% | fitted sites: held-out max %% | never-fitted "
           "sites: max %% (all forces) | cases where the potential is not convex |\n");
    printf("|---|---|---|---|---|---|\n");
    for (unsigned P = 2; P <= TF_REGION_MAX_P; ++P) {
        size_t T = tf_region_terms(P), nonconvex = 0;
        double *site = malloc(ng * (1 + T) * sizeof *site), rms_max = 0, held_max = 0, far = 0;
        double (*F)[3] = force;
        for (size_t s = 0; s < ng; ++s) {
            double *e = site + s * (1 + T) + 1, rms;
            site[s * (1 + T)] = 0;
            if (tf_region_potential_fit(&ctx, P, s_u, (const double(*)[3])(u + s * nf),
                                        (const double(*)[3])F, n_train, e, &rms) != 0) {
                fprintf(stderr, "%s\n", ctx.err);
                return 1;
            }
            rms_max = fmax(rms_max, rms / R_F);
            for (size_t k = 0; k < nf; ++k) {
                double Fm[3], d[3];
                tf_region_potential_force(P, s_u, e, u[s * nf + k], Fm);
                for (int a = 0; a < 3; ++a) {
                    d[a] = Fm[a] - F[k][a];
                }
                if (k >= n_train) {
                    held_max = fmax(held_max, norm3(d) / R_F);
                }
                nonconvex += tf_region_potential_min_curvature(P, s_u, e, u[s * nf + k]) <= 0;
            }
        }
        tf_region_law law = {.nx = grid, .ny = grid, .h = {h[0], h[1]}, .P = P, .T = T,
                             .s_u = s_u};
        law.ctrl = malloc((grid + 2) * (grid + 2) * (1 + T) * sizeof *law.ctrl);
        if (tf_spline_interpolate(&ctx, grid, grid, 1 + T, site, law.ctrl) != 0) {
            fprintf(stderr, "%s\n", ctx.err);
            return 1;
        }
        for (size_t s = ng; s < n; ++s) {
            for (size_t k = 0; k < nf; ++k) {
                double Fm[3], d[3];
                tf_region_law_force(&law, ab[2 * s], ab[2 * s + 1], u[s * nf + k], Fm, NULL);
                for (int a = 0; a < 3; ++a) {
                    d[a] = Fm[a] - F[k][a];
                }
                far = fmax(far, norm3(d) / R_F);
            }
        }
        printf("| %u | %zu | %.3f | %.3f | %.3f | %zu of %zu |\n", P, T, 100 * rms_max,
               100 * held_max, 100 * far, nonconvex, ng * nf);
        tf_region_law_free(&law);
        free(site);
    }
    tf_solver_destroy(sv);
    tf_region_cases_free(&cs);
    tf_scene_free(sc);
    free(ab);
    free(force);
    free(kept);
    free(u);
    return 0;
}
