/*
 * region_study.c — how well a contact region's fitted models answer at
 * sites never fitted (make region-study, make check-region).
 *
 *   region_study SCENE [options] [KEY=VALUE ...]   (--set overrides)
 *     --levels K     fit K site spacings (halving from the first); 0: the
 *                    density rule alone (halve until the targets are met)
 *     --sites N      held-out sites (default 200), random in the domain
 *     --forces M     random forces per held-out site (default 5), uniform
 *                    in the envelope ball
 *     --pairs P      two-instrument cases (default 50)
 *     --seed S
 *     --rect a0,a1,b0,b1   fit only this part of a box face's region
 *     --device       the rule of tissuefit fit: at most TFIT_REGION_MAX_RANK
 *                    modes, the coupling measured but not a target
 *     --near K       the surface's near-field radius, K probe widths (0:
 *                    none; default 1.5, region_surface.h)
 *     --assert F,S,C fail unless the last spacing's held-out force error
 *                    <= F %, surface error <= S % and two-instrument error
 *                    <= C % (of the envelope radius / peak displacement)
 *
 * For every spacing fitted: the held-out force error of the law at the
 * true patch-averaged displacement (|K(g) C_s F - F| / R_F, max over the
 * random forces; and the worst over the envelope's sphere,
 * ||K(g) C_s - I||_2), the surface error (max over outputs of |u_model -
 * u_true|, as a fraction of the peak displacement: the largest output
 * displacement an envelope force makes at any held-out site; random
 * forces, and the envelope's worst), the rest surface's height error, the
 * rank, the table bytes (floats x 4, region_law.h and region_surface.h)
 * and the regeneration time.  Two instruments: random pairs of sites whose
 * tips do not overlap, random forces at both, one true solve with both
 * loads; the coupled prediction of spec §5 (block elimination with the
 * law's stiffnesses and the surface's cross compliances) from the two
 * true patch-averaged displacements, against the forces applied.
 */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/context.h"
#include "base/rng.h"
#include "fitting/force_samples.h"
#include "fitting/region_fit.h"
#include "problem/region_chart.h"
#include "tfit.h"
#include "scene/scene.h"
#include "solvers/solver.h"

typedef struct options {
    const char *scene;
    const char *sets[16];
    size_t n_sets;
    unsigned levels, sites, forces, pairs;
    uint64_t seed;
    double rect[4];
    int has_rect;
    double bound[3];
    int has_bound;
    int device;   /* tissuefit fit's rule: at most TFIT_REGION_MAX_RANK modes, coupling stated */
    double near;  /* the near-field radius in probe widths (< 0: the default) */
} options;

static int parse(int argc, char **argv, options *o)
{
    *o = (options){.levels = 0, .sites = 200, .forces = 5, .pairs = 50, .seed = 1, .near = -1};
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--levels") == 0 && v) {
            o->levels = (unsigned)atoi(v), i++;
        } else if (strcmp(a, "--sites") == 0 && v) {
            o->sites = (unsigned)atoi(v), i++;
        } else if (strcmp(a, "--forces") == 0 && v) {
            o->forces = (unsigned)atoi(v), i++;
        } else if (strcmp(a, "--pairs") == 0 && v) {
            o->pairs = (unsigned)atoi(v), i++;
        } else if (strcmp(a, "--seed") == 0 && v) {
            o->seed = strtoull(v, NULL, 10), i++;
        } else if (strcmp(a, "--rect") == 0 && v) {
            o->has_rect = sscanf(v, "%lf,%lf,%lf,%lf", &o->rect[0], &o->rect[1], &o->rect[2],
                                 &o->rect[3]) == 4;
            i++;
            if (!o->has_rect) {
                return -1;
            }
        } else if (strcmp(a, "--device") == 0) {
            o->device = 1;
        } else if (strcmp(a, "--near") == 0 && v) {
            o->near = atof(v), i++;
        } else if (strcmp(a, "--assert") == 0 && v) {
            o->has_bound = sscanf(v, "%lf,%lf,%lf", &o->bound[0], &o->bound[1], &o->bound[2]) == 3;
            i++;
            if (!o->has_bound) {
                return -1;
            }
        } else if (a[0] != '-' && o->scene == NULL) {
            o->scene = a;
        } else if (a[0] != '-' && o->n_sets < 16) {
            o->sets[o->n_sets++] = a;
        } else {
            return -1;
        }
    }
    return o->scene ? 0 : -1;
}

/* Held-out errors of one spacing's models. */
typedef struct errors {
    double force, force_env, force_rms;
    double surface, surface_env;
    double height;
} errors;

static double norm3(const double v[3]) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

static void mat_vec(const double M[9], const double x[3], double y[3])
{
    for (int i = 0; i < 3; ++i) {
        y[i] = M[3 * i] * x[0] + M[3 * i + 1] * x[1] + M[3 * i + 2] * x[2];
    }
}

static void mat_mul(const double A[9], const double B[9], double C[9])
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            C[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
        }
    }
}

static void heldout_errors(const tf_region_level *lv, const tf_region_chart *chart,
                           const tf_region_sites *h, const double (*force)[3], unsigned nf,
                           double R_F, double peak, errors *e)
{
    size_t rows = 3 * h->n_out;
    double *model = malloc(3 * rows * sizeof *model), sum2 = 0;
    size_t count = 0;
    memset(e, 0, sizeof *e);
    for (size_t s = 0; s < h->n; ++s) {
        double a = h->ab[2 * s], b = h->ab[2 * s + 1], K[9], M[9], q[3], F0[3], hh;
        const double *C = h->C + 9 * s, *U = h->U + 9 * h->n_out * s, zero[3] = {0, 0, 0};
        tf_region_law_stiffness(&lv->law, a, b, K);
        mat_mul(K, C, M);
        for (int i = 0; i < 3; ++i) {
            M[4 * i] -= 1;
        }
        e->force_env = fmax(e->force_env, tf_mat3_norm2(M));
        tf_region_law_force(&lv->law, a, b, zero, F0, &hh);
        tf_region_chart_coords(chart, h->x + 3 * s, q);
        e->height = fmax(e->height, fabs(hh - q[2]));
        for (int l = 0; l < 3; ++l) {
            double F[3] = {0, 0, 0};
            F[l] = 1;
            tf_region_surface_eval(&lv->surface_model, a, b, F, model + (size_t)l * rows);
        }
        for (size_t j = 0; j < h->n_out; ++j) { /* envelope worst */
            double D[9];
            for (int i = 0; i < 3; ++i) {
                for (int l = 0; l < 3; ++l) {
                    D[3 * i + l] = model[(size_t)l * rows + 3 * j + (size_t)i] -
                                   U[(size_t)l * rows + 3 * j + (size_t)i];
                }
            }
            e->surface_env = fmax(e->surface_env, R_F * tf_mat3_norm2(D) / peak);
        }
        for (unsigned k = 0; k < nf; ++k) {
            const double *F = force[s * nf + k];
            double u[3], Fm[3], d[3];
            mat_vec(C, F, u); /* the true patch-averaged displacement */
            tf_region_law_force(&lv->law, a, b, u, Fm, NULL);
            for (int i = 0; i < 3; ++i) {
                d[i] = Fm[i] - F[i];
            }
            e->force = fmax(e->force, norm3(d) / R_F);
            sum2 += (norm3(d) / R_F) * (norm3(d) / R_F);
            count++;
            for (size_t j = 0; j < h->n_out; ++j) {
                double du[3];
                for (int i = 0; i < 3; ++i) {
                    size_t r = 3 * j + (size_t)i;
                    du[i] = model[r] * F[0] + model[rows + r] * F[1] + model[2 * rows + r] * F[2] -
                            (U[r] * F[0] + U[rows + r] * F[1] + U[2 * rows + r] * F[2]);
                }
                e->surface = fmax(e->surface, norm3(du) / peak);
            }
        }
    }
    e->force_rms = count ? sqrt(sum2 / (double)count) : 0;
    free(model);
}

/* The surface's held-out errors alone (random forces, envelope worst). */
static void surface_heldout(const tf_region_surface *sf, const tf_region_sites *h,
                            const double (*force)[3], unsigned nf, double R_F, double peak,
                            double *random, double *env)
{
    size_t rows = 3 * h->n_out;
    double *model = malloc(3 * rows * sizeof *model);
    *random = *env = 0;
    for (size_t s = 0; s < h->n; ++s) {
        const double *U = h->U + 9 * h->n_out * s;
        for (int l = 0; l < 3; ++l) {
            double F[3] = {0, 0, 0};
            F[l] = 1;
            tf_region_surface_eval(sf, h->ab[2 * s], h->ab[2 * s + 1], F, model + (size_t)l * rows);
        }
        for (size_t j = 0; j < h->n_out; ++j) {
            double D[9];
            for (int i = 0; i < 3; ++i) {
                for (int l = 0; l < 3; ++l) {
                    D[3 * i + l] = model[(size_t)l * rows + 3 * j + (size_t)i] -
                                   U[(size_t)l * rows + 3 * j + (size_t)i];
                }
            }
            *env = fmax(*env, R_F * tf_mat3_norm2(D) / peak);
            for (unsigned k = 0; k < nf; ++k) {
                double du[3];
                mat_vec(D, force[s * nf + k], du);
                *random = fmax(*random, norm3(du) / peak);
            }
        }
    }
    free(model);
}

/* Surface error against table bytes over the rank, at one spacing. */
static void rank_table(tf_ctx *ctx, const tf_region_level *lv, const tf_region_sites *h,
                       const double (*force)[3], unsigned nf, double R_F, double peak)
{
    printf("\nsurface over the rank at spacing %.3g x %.3g mm (%u x %u sites; the rank rule chose "
           "%u):\n\n", lv->h[0], lv->h[1], lv->nx, lv->ny, lv->rank);
    printf("| rank | surface %% (random / envelope) | surface bytes | without site modes |\n");
    printf("|---|---|---|---|\n");
    size_t ncp = (size_t)(lv->nx + 2) * (lv->ny + 2);
    for (unsigned r = 4;; r *= 2) {
        unsigned rr = r < lv->modes.r_max ? r : lv->modes.r_max;
        tf_region_surface sf;
        if (tf_region_surface_fit(ctx, &lv->modes, lv->nx, lv->ny, lv->h, R_F, rr, &sf) != 0) {
            break;
        }
        double ran, env;
        surface_heldout(&sf, h, force, nf, R_F, peak, &ran, &env);
        size_t fl = tf_region_surface_floats(&sf);
        printf("| %u | %.2f / %.2f | %zu | %zu |\n", rr, 100 * ran, 100 * env, 4 * fl,
               4 * (fl - ncp * 3 * rr));
        tf_region_surface_free(&sf);
        if (rr == lv->modes.r_max) {
            break;
        }
    }
}

/* Two instruments: random pairs whose tips do not overlap, one true solve
 * each with both loads, the coupled and the uncoupled predictions. */
static int pairs(tf_ctx *ctx, tf_solver *sv, const tf_problem *p, const tf_contact_region *r,
                 const tf_region_level *lv, unsigned np, uint64_t seed, double *coupled,
                 double *uncoupled, double *coupling, double *near, unsigned *n_near)
{
    size_t n3 = 3 * p->cloud.n;
    double R_F = p->envelope.radius, w[2], len[2] = {r->chart.len[0], r->chart.len[1]};
    tf_region_tip_extent(r, w);
    double *f = calloc(n3 * np + 1, sizeof *f), *u = malloc((n3 * np + 1) * sizeof *u);
    double *L1 = malloc(3 * n3 * sizeof *L1), *L2 = malloc(3 * n3 * sizeof *L2);
    double *site = malloc(4 * np * sizeof *site), (*force)[3] = malloc(2 * np * sizeof *force);
    if (!f || !u || !L1 || !L2 || !site || !force) {
        return tf_fail(ctx, "out of memory");
    }
    tf_rng rng = {seed * 7919 + 17};
    double train[6][3]; /* (the training forces, not used) */
    tf_force_samples(p->envelope.centre, R_F, 6, 2 * np, seed + 101, train, force);
    int rc = 0;
    *coupled = *uncoupled = *coupling = *near = 0;
    *n_near = 0;
    for (unsigned k = 0; k < np && rc == 0; ++k) {
        double *g = site + 4 * k;
        do { /* two sites whose tips do not overlap */
            for (int i = 0; i < 2; ++i) {
                g[2 * i] = tf_rng_range(&rng, 0, len[0]);
                g[2 * i + 1] = tf_rng_range(&rng, 0, len[1]);
            }
        } while (fabs(g[0] - g[2]) < 2 * w[0] + 1e-9 && fabs(g[1] - g[3]) < 2 * w[1] + 1e-9 &&
                 (r->tip == TF_TIP_RECT || hypot(g[0] - g[2], g[1] - g[3]) < 2 * w[0]));
        rc = tf_region_site_loads(ctx, sv, p, r, g[0], g[1], L1, NULL);
        if (rc == 0) {
            rc = tf_region_site_loads(ctx, sv, p, r, g[2], g[3], L2, NULL);
        }
        for (size_t d = 0; rc == 0 && d < n3; ++d) {
            for (int i = 0; i < 3; ++i) {
                f[k * n3 + d] += L1[(size_t)i * n3 + d] * force[2 * k][i] +
                                 L2[(size_t)i * n3 + d] * force[2 * k + 1][i];
            }
        }
    }
    if (rc == 0) {
        rc = tf_solver_solve_loads(sv, f, np, u);
    }
    for (unsigned k = 0; k < np && rc == 0; ++k) { /* (the loads again: 6N per pair not kept) */
        const double *g = site + 4 * k;
        rc = tf_region_site_loads(ctx, sv, p, r, g[0], g[1], L1, NULL);
        if (rc == 0) {
            rc = tf_region_site_loads(ctx, sv, p, r, g[2], g[3], L2, NULL);
        }
        if (rc != 0) {
            break;
        }
        double u1[3] = {0, 0, 0}, u2[3] = {0, 0, 0};
        for (size_t d = 0; d < n3; ++d) {
            for (int i = 0; i < 3; ++i) {
                u1[i] += L1[(size_t)i * n3 + d] * u[k * n3 + d];
                u2[i] += L2[(size_t)i * n3 + d] * u[k * n3 + d];
            }
        }
        double K1[9], K2[9], C12[9], C21[9], T[9], T2[9], S[9], Si[9], v[3], y[3], F1[3], F2[3];
        tf_region_law_stiffness(&lv->law, g[0], g[1], K1);
        tf_region_law_stiffness(&lv->law, g[2], g[3], K2);
        tf_region_surface_cross(&lv->surface_model, g[0], g[1], g[2], g[3], C12);
        tf_region_surface_cross(&lv->surface_model, g[2], g[3], g[0], g[1], C21);
        /* F2 = (I - K2 C21 K1 C12)^-1 K2 (u2 - C21 K1 u1), F1 = K1 (u1 - C12 F2) */
        mat_mul(K2, C21, T);
        mat_mul(T, K1, T2);
        mat_mul(T2, C12, S);
        for (int i = 0; i < 9; ++i) {
            S[i] = (i % 4 == 0) - S[i];
        }
        mat_vec(K1, u1, y);
        mat_vec(C21, y, v);
        for (int i = 0; i < 3; ++i) {
            v[i] = u2[i] - v[i];
        }
        mat_vec(K2, v, y);
        if (tf_mat3_inverse(S, Si) != 0) {
            rc = tf_fail(ctx, "pair %u: the coupled system is singular", k);
            break;
        }
        mat_vec(Si, y, F2);
        mat_vec(C12, F2, v);
        for (int i = 0; i < 3; ++i) {
            v[i] = u1[i] - v[i];
        }
        mat_vec(K1, v, F1);
        double d1[3], d2[3], e1[3], e2[3], U1[3], U2[3];
        mat_vec(K1, u1, U1); /* uncoupled: each instrument alone */
        mat_vec(K2, u2, U2);
        for (int i = 0; i < 3; ++i) {
            d1[i] = F1[i] - force[2 * k][i];
            d2[i] = F2[i] - force[2 * k + 1][i];
            e1[i] = U1[i] - force[2 * k][i];
            e2[i] = U2[i] - force[2 * k + 1][i];
        }
        *coupled = fmax(*coupled, fmax(norm3(d1), norm3(d2)) / R_F);
        if (hypot(g[0] - g[2], g[1] - g[3]) < 4 * fmax(w[0], w[1])) { /* within 2 tips */
            *near = fmax(*near, fmax(norm3(d1), norm3(d2)) / R_F);
            (*n_near)++;
        }
        *uncoupled = fmax(*uncoupled, fmax(norm3(e1), norm3(e2)) / R_F);
        *coupling = fmax(*coupling, tf_mat3_norm2(C12) * tf_mat3_norm2(K1));
    }
    free(f);
    free(u);
    free(L1);
    free(L2);
    free(site);
    free(force);
    return rc;
}

int main(int argc, char **argv)
{
    options o;
    if (parse(argc, argv, &o) != 0) {
        fprintf(stderr, "usage: region_study SCENE [--levels K] [--sites N] [--forces M] "
                        "[--pairs P] [--seed S] [--rect a0,a1,b0,b1] [--assert F,S,C] "
                        "[KEY=VALUE ...]\n");
        return 2;
    }
    tf_ctx ec;
    tf_ctx_init(&ec);
    tf_scene *sc = tf_scene_load(&ec, o.scene, o.sets, o.n_sets);
    if (sc == NULL) {
        fprintf(stderr, "%s\n", ec.err);
        return 2;
    }
    tf_problem *p = &sc->problem;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    if (p->n_contacts == 0 || p->contacts[0].region.kind == TF_CONTACT_REGION_NONE) {
        fprintf(stderr, "%s: contact 0 is not a region\n", o.scene);
        return 2;
    }
    tf_contact_region *r = &p->contacts[0].region;
    if (o.has_rect) { /* a part of a box face's region */
        memcpy(r->rect, o.rect, sizeof r->rect);
        if (tf_region_chart_build(&ctx, p, r) != 0) {
            fprintf(stderr, "--rect: %s\n", ctx.err);
            return 2;
        }
    }
    double t0 = omp_get_wtime();
    tf_solver *sv = tf_solver_create(p, NULL, &ctx);
    if (sv == NULL) {
        fprintf(stderr, "%s\n", ctx.err);
        return 1;
    }
    double t_setup = omp_get_wtime() - t0, R_F = p->envelope.radius;
    printf("%s: %zu nodes, %zu outputs; region %.4g x %.4g mm, tip %s %.3g mm; solver set-up "
           "%.1f s\n",
           p->name, p->cloud.n, p->outputs.n_nodes, r->chart.len[0], r->chart.len[1],
           r->tip == TF_TIP_RECT ? "rect" : "disc",
           r->tip == TF_TIP_RECT ? r->tip_size[0] : r->tip_radius, t_setup);
    tf_region_targets tg = tf_region_targets_default();
    tg.levels = o.levels;
    if (o.device) { /* as tissuefit fit (region_models.c) */
        tg.max_rank = TFIT_REGION_MAX_RANK;
        tg.coupling = INFINITY;
    }
    if (o.near >= 0) {
        tg.near = o.near;
    }
    tf_region_result res;
    if (tf_region_fit(&ctx, sv, p, 0, &tg, &res) != 0) {
        fprintf(stderr, "%s\n", ctx.err);
        return 1;
    }
    printf("density rule: %s; patch-averaged compliance asymmetry %.2g\n", res.why,
           res.sites.asym);
    /* held-out sites and forces */
    double *ab = malloc(2 * o.sites * sizeof *ab), (*force)[3] = malloc(o.sites * o.forces * sizeof *force);
    double train[6][3]; /* (the training forces, not used) */
    tf_rng rng = {o.seed};
    for (unsigned s = 0; s < o.sites; ++s) {
        ab[2 * s] = tf_rng_range(&rng, 0, r->chart.len[0]);
        ab[2 * s + 1] = tf_rng_range(&rng, 0, r->chart.len[1]);
    }
    tf_force_samples(p->envelope.centre, R_F, 6, o.sites * o.forces, o.seed + 1, train, force);
    double th = omp_get_wtime();
    tf_region_sites held;
    if (tf_region_sites_solve(&ctx, sv, p, r, ab, o.sites, NULL, 0, &held) != 0) {
        fprintf(stderr, "%s\n", ctx.err);
        return 1;
    }
    double peak = tf_region_peak(&held, NULL, held.n, R_F);
    printf("held out: %u random sites x %u random forces in the envelope, solved in %.1f s; peak "
           "displacement %.4g mm\n\n",
           o.sites, o.forces, omp_get_wtime() - th, peak);
    printf("| spacing (mm) | sites | rank | force %% (random / envelope) | surface %% (random / "
           "envelope) | coupling %% (cell centres) | height (mm) | law bytes | surface bytes | "
           "regeneration (s) |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|\n");
    errors e = {0};
    for (unsigned k = 0; k < res.n_levels; ++k) {
        const tf_region_level *lv = &res.level[k];
        heldout_errors(lv, &r->chart, &held, (const double(*)[3])force, o.forces, R_F, peak, &e);
        printf("| %.3g x %.3g | %u x %u | %u | %.3f / %.3f | %.2f / %.2f | %.2f | %.2g | %zu | %zu "
               "| %.1f |\n",
               lv->h[0], lv->h[1], lv->nx, lv->ny, lv->rank, 100 * e.force, 100 * e.force_env,
               100 * e.surface, 100 * e.surface_env, 100 * lv->coupling, e.height,
               4 * lv->law_floats, 4 * lv->surface_floats, lv->seconds);
    }
    const tf_region_level *last = &res.level[res.n_levels - 1];
    rank_table(&ctx, last, &held, (const double(*)[3])force, o.forces, R_F, peak);
    double cpl = 0, unc = 0, strength = 0, near = 0;
    unsigned n_near = 0;
    if (o.pairs > 0 && pairs(&ctx, sv, p, r, last, o.pairs, o.seed, &cpl, &unc, &strength,
                             &near, &n_near) != 0) {
        fprintf(stderr, "%s\n", ctx.err);
        return 1;
    }
    printf("\ntwo instruments (%u random pairs whose tips do not overlap, spacing %.3g mm, rank "
           "%u): coupled prediction %.3f %% of the envelope radius (%.3f %% over the %u pairs "
           "less than two tip widths apart), uncoupled %.3f %% (largest |C12| |K1| %.3g)\n",
           o.pairs, last->h[0], last->rank, 100 * cpl, 100 * near, n_near, 100 * unc, strength);
    printf("total %.1f s\n", omp_get_wtime() - t0);
    int bad = 0;
    if (o.has_bound) {
        bad = !(100 * e.force <= o.bound[0]) || !(100 * e.surface <= o.bound[1]) ||
              (o.pairs > 0 && !(100 * cpl <= o.bound[2]));
        char two[64] = "two instruments not judged (no pairs)";
        if (o.pairs > 0) {
            snprintf(two, sizeof two, "two instruments %.3f %% (<= %g)", 100 * cpl, o.bound[2]);
        }
        printf("%s: held-out force %.3f %% (<= %g), surface %.2f %% (<= %g), %s\n",
               bad ? "FAILED" : "within bounds", 100 * e.force, o.bound[0], 100 * e.surface,
               o.bound[1], two);
    }
    tf_region_sites_free(&held);
    tf_region_result_free(&res);
    tf_solver_destroy(sv);
    tf_scene_free(sc);
    free(ab);
    free(force);
    return bad;
}
