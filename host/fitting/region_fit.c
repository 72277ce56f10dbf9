/*
 * region_fit.c — a contact region's law and surface, and the site density
 * rule (region_fit.h).
 */
#include "fitting/region_fit.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/log.h"
#include "numerics/grid_spline.h"
#include "problem/region_chart.h"

tf_region_targets tf_region_targets_default(void)
{
    return (tf_region_targets){.force = 0.01, .surface = 0.05, .coupling = 0.02, .max_sites = 33,
                               .max_rank = TF_REGION_MAX_RANK, .levels = 0, .near = 1.5,
                               .near_cap = TF_REGION_MAX_NEAR};
}

double tf_mat3_norm2(const double M[9])
{
    double MtM[9], lam[3];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            MtM[3 * i + j] = M[i] * M[j] + M[3 + i] * M[3 + j] + M[6 + i] * M[6 + j];
        }
    }
    tf_sym3_eigenvalues(MtM, lam);
    return sqrt(fmax(lam[2], 0));
}

double tf_region_scale(const tf_region_sites *t, const size_t *idx, size_t n, double R_F)
{
    double cmax = 0;
    for (size_t s = 0; s < n; ++s) {
        double lam[3];
        tf_sym3_eigenvalues(t->C + 9 * idx[s], lam);
        cmax = fmax(cmax, lam[2]);
    }
    return 1 / (R_F * cmax);
}

int tf_region_law_fit(tf_ctx *ctx, const tf_region_sites *t, const size_t *idx, unsigned nx,
                      unsigned ny, const double h[2], const tf_region_chart *chart, double s_u,
                      double mu, tf_region_law *law)
{
    size_t n = (size_t)nx * ny, m = 7;
    memset(law, 0, sizeof *law);
    *law = (tf_region_law){.nx = nx, .ny = ny, .h = {h[0], h[1]}, .P = 2, .T = 6, .s_u = s_u,
                           .mu = mu};
    double *site = malloc(n * m * sizeof *site);
    law->ctrl = malloc((size_t)(nx + 2) * (ny + 2) * m * sizeof *law->ctrl);
    if (!site || !law->ctrl) {
        free(site);
        tf_region_law_free(law);
        return tf_fail(ctx, "out of memory");
    }
    for (size_t s = 0; s < n; ++s) {
        double K[9], q[3];
        if (tf_mat3_inverse(t->C + 9 * idx[s], K) != 0) {
            free(site);
            tf_region_law_free(law);
            return tf_fail(ctx, "the compliance at site (%g, %g) mm is singular", t->ab[2 * idx[s]],
                           t->ab[2 * idx[s] + 1]);
        }
        for (int i = 0; i < 3; ++i) { /* symmetrised */
            for (int j = i + 1; j < 3; ++j) {
                K[3 * i + j] = K[3 * j + i] = 0.5 * (K[3 * i + j] + K[3 * j + i]);
            }
        }
        tf_region_chart_coords(chart, t->x + 3 * idx[s], q);
        site[s * m] = q[2];
        tf_region_quadratic_coefs(K, s_u, site + s * m + 1);
    }
    int rc = tf_spline_interpolate(ctx, nx, ny, m, site, law->ctrl);
    free(site);
    if (rc != 0) {
        tf_region_law_free(law);
    }
    return rc;
}

void tf_region_result_free(tf_region_result *res)
{
    for (unsigned k = 0; k < res->n_levels; ++k) {
        tf_region_law_free(&res->level[k].law);
        tf_region_surface_free(&res->level[k].surface_model);
        tf_region_modes_free(&res->level[k].modes);
        free(res->level[k].train);
        free(res->level[k].check);
    }
    tf_region_sites_free(&res->sites);
    memset(res, 0, sizeof *res);
}

/* ---- the density rule ---------------------------------------------------- */

/* Index of the solved site at (a, b), or -1. */
static long find_site(const tf_region_sites *t, double a, double b, double tol)
{
    for (size_t i = 0; i < t->n; ++i) {
        if (fabs(t->ab[2 * i] - a) <= tol && fabs(t->ab[2 * i + 1] - b) <= tol) {
            return (long)i;
        }
    }
    return -1;
}

/* Indices of the points ab (2 n) among the solved sites, solving those not
 * yet solved. */
static int sites_for(tf_ctx *ctx, tf_solver *s, const tf_problem *p, const tf_contact_region *r,
                     const double *ab, size_t n, double radius, tf_region_sites *all, size_t *idx)
{
    double tol = 1e-9 * (r->chart.len[0] + r->chart.len[1]);
    double *todo = malloc((2 * n + 1) * sizeof *todo);
    size_t nt = 0;
    if (todo == NULL) {
        return tf_fail(ctx, "out of memory");
    }
    for (size_t i = 0; i < n; ++i) {
        if (find_site(all, ab[2 * i], ab[2 * i + 1], tol) < 0) {
            todo[2 * nt] = ab[2 * i];
            todo[2 * nt + 1] = ab[2 * i + 1];
            nt++;
        }
    }
    int rc = 0;
    if (nt > 0) {
        tf_region_sites fresh;
        rc = tf_region_sites_solve(ctx, s, p, r, todo, nt, radius > 0 ? all : NULL, radius,
                                   &fresh);
        if (rc == 0) {
            rc = tf_region_sites_append(ctx, all, &fresh);
        }
    }
    for (size_t i = 0; rc == 0 && i < n; ++i) {
        idx[i] = (size_t)find_site(all, ab[2 * i], ab[2 * i + 1], tol);
    }
    free(todo);
    return rc;
}

double tf_region_peak(const tf_region_sites *t, const size_t *idx, size_t n, double R_F)
{
    double peak = 0;
    for (size_t s = 0; s < n; ++s) {
        const double *U = t->U + 9 * t->n_out * (idx != NULL ? idx[s] : s);
        size_t rows = 3 * t->n_out;
        for (size_t j = 0; j < t->n_out; ++j) {
            double M[9];
            for (int a = 0; a < 3; ++a) {
                for (int l = 0; l < 3; ++l) {
                    M[3 * a + l] = U[(size_t)l * rows + 3 * j + (size_t)a];
                }
            }
            peak = fmax(peak, R_F * tf_mat3_norm2(M));
        }
    }
    return peak;
}

/* The surface error at site s: max over outputs of the spectral norm of the
 * response error, times R_F. */
static double surface_error(const tf_region_surface *sf, const tf_region_sites *t, size_t s,
                            double *work)
{
    size_t rows = 3 * t->n_out;
    const double *U = t->U + 9 * t->n_out * s;
    for (int l = 0; l < 3; ++l) {
        double F[3] = {0, 0, 0};
        F[l] = 1;
        tf_region_surface_eval(sf, t->ab[2 * s], t->ab[2 * s + 1], F, work + (size_t)l * rows);
    }
    double worst = 0;
    for (size_t j = 0; j < t->n_out; ++j) {
        double M[9];
        for (int a = 0; a < 3; ++a) {
            for (int l = 0; l < 3; ++l) {
                M[3 * a + l] = work[(size_t)l * rows + 3 * j + (size_t)a] -
                               U[(size_t)l * rows + 3 * j + (size_t)a];
            }
        }
        worst = fmax(worst, tf_mat3_norm2(M));
    }
    return worst * sf->R_F;
}

/* The law's errors at sites idx: force (||K C - I||_2) and height. */
static void law_errors(const tf_region_law *law, const tf_region_chart *chart,
                       const tf_region_sites *t, const size_t *idx, size_t n, double *force,
                       double *force_rms, double *height)
{
    double sum2 = 0;
    *force = *height = 0;
    for (size_t i = 0; i < n; ++i) {
        size_t s = idx[i];
        double K[9], M[9], q[3], F[3], h, zero[3] = {0, 0, 0};
        tf_region_law_stiffness(law, t->ab[2 * s], t->ab[2 * s + 1], K);
        const double *C = t->C + 9 * s;
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) {
                M[3 * a + b] = K[3 * a] * C[b] + K[3 * a + 1] * C[3 + b] + K[3 * a + 2] * C[6 + b] -
                               (a == b);
            }
        }
        const double e = tf_mat3_norm2(M);
        *force = fmax(*force, e);
        sum2 += e * e;
        tf_region_law_force(law, t->ab[2 * s], t->ab[2 * s + 1], zero, F, &h);
        tf_region_chart_coords(chart, t->x + 3 * s, q);
        *height = fmax(*height, fabs(h - q[2]));
    }
    *force_rms = n > 0 ? sqrt(sum2 / (double)n) : 0;
}

/* The pairs recorded between this spacing's grid sites and its cell
 * centres (indices into t's pairs), every k-th of them so that at most
 * TF_REGION_PAIRS_JUDGED are judged. */
static size_t level_pairs(const tf_region_sites *t, const tf_region_level *lv, const size_t *chk,
                          size_t nc, size_t *out)
{
    size_t m = 0, n = (size_t)lv->nx * lv->ny;
    unsigned char *role = calloc(t->n + 1, 1); /* 1: a grid site, 2: a cell centre */
    if (role == NULL) {
        return 0;
    }
    for (size_t i = 0; i < n; ++i) {
        role[lv->train[i]] = 1;
    }
    for (size_t i = 0; i < nc; ++i) {
        role[chk[i]] = 2;
    }
    for (size_t k = 0; k < t->n_pairs; ++k) {
        if (role[t->pair[2 * k]] == 1 && role[t->pair[2 * k + 1]] == 2) {
            out[m++] = k;
        }
    }
    free(role);
    size_t step = (m + TF_REGION_PAIRS_JUDGED - 1) / TF_REGION_PAIRS_JUDGED, kept = 0;
    for (size_t q = 0; step > 1 && q < m; q += step) {
        out[kept++] = out[q];
    }
    return step > 1 ? kept : m;
}

/* The coupling error of a surface: over the pairs, the force error the
 * cross compliance's error makes in the two-instrument solve (spec §5),
 * to first order ||K_i (C_model(i, j) - C(i, j))||_2 (|F_j| = R_F, as a
 * fraction of R_F), both ways (C(j, i) = C(i, j)^T). */
static double coupling_error(const tf_region_surface *sf, const tf_region_law *law,
                             const tf_region_sites *t, const size_t *pk, size_t np)
{
    double worst = 0;
    for (size_t q = 0; q < np; ++q) {
        size_t k = pk[q];
        const double *gi = t->ab + 2 * t->pair[2 * k], *gj = t->ab + 2 * t->pair[2 * k + 1];
        const double *C = t->cross + 9 * k;
        for (int way = 0; way < 2; ++way) {
            const double *g1 = way ? gj : gi, *g2 = way ? gi : gj;
            double Cm[9], K[9], D[9], M[9];
            tf_region_surface_cross(sf, g1[0], g1[1], g2[0], g2[1], Cm);
            tf_region_law_stiffness(law, g1[0], g1[1], K);
            for (int a = 0; a < 3; ++a) {
                for (int b = 0; b < 3; ++b) {
                    D[3 * a + b] = Cm[3 * a + b] - (way ? C[3 * b + a] : C[3 * a + b]);
                }
            }
            for (int a = 0; a < 3; ++a) {
                for (int b = 0; b < 3; ++b) {
                    M[3 * a + b] = K[3 * a] * D[b] + K[3 * a + 1] * D[3 + b] + K[3 * a + 2] * D[6 + b];
                }
            }
            worst = fmax(worst, tf_mat3_norm2(M));
        }
    }
    return worst;
}

/* What a rank is judged on at one spacing. */
typedef struct rank_judge {
    const tf_region_modes *m;
    const tf_region_sites *t;
    const size_t *chk;
    size_t nc;
    const size_t *pairs;
    size_t np;
    double R_F, peak;
    const tf_region_targets *tg;
    double *work;
} rank_judge;

/* The surface of rank r, its surface and coupling errors at the check
 * sites, and whether both meet their targets. */
static int surface_at_rank(tf_ctx *ctx, const rank_judge *j, const tf_region_level *lv,
                           unsigned r, tf_region_surface *sf, double *err, double *rms,
                           double *cpl, int *met)
{
    if (tf_region_surface_fit(ctx, j->m, lv->nx, lv->ny, lv->h, j->R_F, r, sf) != 0) {
        return -1;
    }
    double sum2 = 0;
    *err = 0;
    for (size_t i = 0; i < j->nc; ++i) {
        const double e = surface_error(sf, j->t, j->chk[i], j->work) / j->peak;
        *err = fmax(*err, e);
        sum2 += e * e;
    }
    *rms = j->nc > 0 ? sqrt(sum2 / (double)j->nc) : 0;
    *cpl = coupling_error(sf, &lv->law, j->t, j->pairs, j->np);
    *met = *err <= j->tg->surface && *cpl <= j->tg->coupling;
    return 0;
}

/* The rank: the smallest meeting the surface and coupling targets at the
 * check sites, searched by doubling (1, 2, 4, ... and the largest) and then
 * bisection between the last two ranks tried (the errors are not monotone
 * in the rank, so this is the smallest of those tried); when none meets
 * them, the rank of the smallest surface error tried.  The surface is
 * fitted into lv. */
static int choose_rank(tf_ctx *ctx, const rank_judge *jd, tf_region_level *lv)
{
    unsigned lo = 0, hi = 0, best = 0, r_max = jd->m->r_max;
    double best_e = INFINITY, e, c, rms;
    int rc = 0, met = 0;
    for (unsigned r = 1; rc == 0; r = r * 2 < r_max ? r * 2 : r_max) {
        tf_region_surface sf;
        rc = surface_at_rank(ctx, jd, lv, r, &sf, &e, &rms, &c, &met);
        tf_region_surface_free(&sf);
        if (rc == 0 && e < best_e) {
            best_e = e;
            best = r;
        }
        if (rc != 0 || met) {
            hi = r;
            break;
        }
        lo = r;
        if (r == r_max) {
            break;
        }
    }
    while (rc == 0 && hi > 0 && hi - lo > 1) { /* the targets are met at hi, not at lo */
        unsigned mid = lo + (hi - lo) / 2;
        tf_region_surface sf;
        rc = surface_at_rank(ctx, jd, lv, mid, &sf, &e, &rms, &c, &met);
        tf_region_surface_free(&sf);
        if (rc == 0 && met) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    if (rc == 0) {
        lv->rank = hi > 0 ? hi : best;
        tf_region_surface_free(&lv->surface_model);
        rc = surface_at_rank(ctx, jd, lv, lv->rank, &lv->surface_model, &lv->surface,
                             &lv->surface_rms, &lv->coupling, &met);
    }
    return rc;
}

/* Grid nodes (train) and cell centres (check) of an nx x ny grid. */
static void grid_points(unsigned nx, unsigned ny, const double h[2], double *train, double *chk)
{
    for (unsigned j = 0; j < ny; ++j) {
        for (unsigned i = 0; i < nx; ++i) {
            train[2 * ((size_t)j * nx + i)] = i * h[0];
            train[2 * ((size_t)j * nx + i) + 1] = j * h[1];
            if (i + 1 < nx && j + 1 < ny) {
                chk[2 * ((size_t)j * (nx - 1) + i)] = (i + 0.5) * h[0];
                chk[2 * ((size_t)j * (nx - 1) + i) + 1] = (j + 0.5) * h[1];
            }
        }
    }
}

/* What the surface's near field is fitted from: the outputs' and the
 * grid sites' chart coordinates (owned by the modes), the radius. */
static int near_spec(tf_ctx *ctx, const tf_problem *p, const tf_contact_region *r,
                     const tf_region_sites *t, const size_t *train, size_t n,
                     const tf_region_targets *tg, tf_region_modes *m)
{
    size_t n_out = p->outputs.n_nodes;
    double *oq = malloc(3 * n_out * sizeof *oq), *sq = malloc(3 * n * sizeof *sq), w[2];
    if (!oq || !sq) {
        free(oq);
        free(sq);
        return tf_fail(ctx, "out of memory");
    }
    for (size_t j = 0; j < n_out; ++j) {
        const double *x = p->outputs.points ? p->outputs.points + 3 * j
                                            : p->cloud.xyz + 3 * (size_t)p->outputs.nodes[j];
        tf_region_chart_coords(&r->chart, x, oq + 3 * j);
    }
    for (size_t i = 0; i < n; ++i) {
        tf_region_chart_coords(&r->chart, t->x + 3 * train[i], sq + 3 * i);
    }
    tf_region_tip_extent(r, w);
    m->near = (tf_region_near_spec){t, train, oq, sq, tg->near * 2 * fmax(w[0], w[1]),
                                    tg->near_cap};
    return 0;
}

/* One spacing: solve what is missing, fit, judge. */
static int fit_level(tf_ctx *ctx, tf_solver *s, const tf_problem *p, const tf_contact_region *r,
                     const tf_region_targets *tg, tf_region_result *res, tf_region_level *lv)
{
    size_t n = (size_t)lv->nx * lv->ny, nc = (size_t)(lv->nx - 1) * (lv->ny - 1);
    double R_F = p->envelope.radius;
    double *pts = malloc(2 * (n + nc) * sizeof *pts);
    size_t *chk = malloc((nc + 1) * sizeof *chk);
    lv->train = malloc(n * sizeof *lv->train);
    if (!pts || !chk || !lv->train) {
        free(pts);
        free(chk);
        return tf_fail(ctx, "out of memory");
    }
    grid_points(lv->nx, lv->ny, lv->h, pts, pts + 2 * n);
    /* the cell centres' cross compliances with their neighbours among the
     * grid's sites: what the two-instrument coupling is judged on */
    double w[2];
    tf_region_tip_extent(r, w);
    int rc = sites_for(ctx, s, p, r, pts, n, 0, &res->sites, lv->train);
    if (rc == 0) {
        rc = sites_for(ctx, s, p, r, pts + 2 * n, nc, TF_REGION_PAIR_REACH * fmax(w[0], w[1]),
                       &res->sites, chk);
    }
    double solves = tf_solver_info_of(s)->t_setup, t1 = omp_get_wtime();
    for (size_t i = 0; rc == 0 && i < n + nc; ++i) {
        solves += res->sites.seconds[i < n ? lv->train[i] : chk[i - n]];
    }
    tf_region_modes *modes = &lv->modes;
    double s_u = tf_region_scale(&res->sites, lv->train, n, R_F);
    if (rc == 0) {
        rc = tf_region_law_fit(ctx, &res->sites, lv->train, lv->nx, lv->ny, lv->h, &r->chart, s_u,
                               r->friction, &lv->law);
    }
    if (rc == 0) {
        rc = tf_region_modes_build(ctx, s, &res->sites, lv->train, n, R_F, tg->max_rank, modes);
    }
    if (rc == 0 && tg->near > 0) {
        rc = near_spec(ctx, p, r, &res->sites, lv->train, n, tg, modes);
    }
    if (rc == 0) {
        double peak_t = tf_region_peak(&res->sites, lv->train, n, R_F);
        double peak_c = tf_region_peak(&res->sites, chk, nc, R_F);
        lv->peak = fmax(peak_t, peak_c);
        size_t *pk = malloc((res->sites.n_pairs + 1) * sizeof *pk);
        double *work = malloc(9 * res->sites.n_out * sizeof *work);
        if (!pk || !work) {
            rc = tf_fail(ctx, "out of memory");
        } else {
            rank_judge jd = {modes, &res->sites, chk, nc, pk, 0, R_F, lv->peak, tg, work};
            jd.np = level_pairs(&res->sites, lv, chk, nc, pk);
            lv->pairs = jd.np;
            rc = choose_rank(ctx, &jd, lv);
        }
        free(pk);
        free(work);
    }
    if (rc == 0) {
        law_errors(&lv->law, &r->chart, &res->sites, chk, nc, &lv->force, &lv->force_rms,
                   &lv->height);
        /* Passive: every control point SPD suffices (a blend with
         * non-negative weights of SPD matrices is SPD); else the blend
         * itself, sampled 8 times per site interval. */
        lv->min_stiffness = tf_region_law_min_stiffness(&lv->law);
        lv->cp_spd = lv->min_stiffness > 0;
        if (!lv->cp_spd) {
            lv->min_stiffness = tf_region_law_min_stiffness_sampled(&lv->law, 8);
        }
        lv->law_floats = tf_region_law_floats(&lv->law);
        lv->surface_floats = tf_region_surface_floats(&lv->surface_model);
        lv->met = lv->force <= tg->force && lv->surface <= tg->surface &&
                  lv->coupling <= tg->coupling;
        lv->seconds = solves + (omp_get_wtime() - t1); /* (the fit includes the r solves) */
    }
    free(pts);
    lv->check = chk;
    lv->n_check = nc;
    return rc;
}

double tf_region_surface_coupling(const tf_region_surface *sf, const tf_region_result *res,
                                  const tf_region_level *lv)
{
    size_t *pk = malloc((res->sites.n_pairs + 1) * sizeof *pk);
    if (pk == NULL) {
        return INFINITY;
    }
    const size_t np = level_pairs(&res->sites, lv, lv->check, lv->n_check, pk);
    const double c = coupling_error(sf, &lv->law, &res->sites, pk, np);
    free(pk);
    return c;
}

void tf_region_surface_heldout(const tf_region_surface *sf, const tf_region_result *res,
                               const tf_region_level *lv, double *max, double *rms)
{
    double *work = malloc(9 * res->sites.n_out * sizeof *work), sum2 = 0;
    *max = *rms = 0;
    if (work == NULL) {
        *max = *rms = INFINITY;
        return;
    }
    for (size_t i = 0; i < lv->n_check; ++i) {
        const double e = surface_error(sf, &res->sites, lv->check[i], work) / lv->peak;
        *max = fmax(*max, e);
        sum2 += e * e;
    }
    *rms = lv->n_check > 0 ? sqrt(sum2 / (double)lv->n_check) : 0;
    free(work);
}

/* The first spacing: the scene's, or about the probe's diameter. */
static double first_spacing(const tf_contact_region *r)
{
    if (r->spacing > 0) {
        return r->spacing;
    }
    return r->tip == TF_TIP_RECT ? fmax(r->tip_size[0], r->tip_size[1]) : 2 * r->tip_radius;
}

static unsigned sites_along(double len, double S)
{
    double n = ceil(len / S - 1e-9) + 1;
    return n < TF_SPLINE_MIN_SITES ? TF_SPLINE_MIN_SITES : (unsigned)n;
}

int tf_region_fit(tf_ctx *ctx, tf_solver *s, const tf_problem *p, int contact,
                  const tf_region_targets *tg, tf_region_result *res)
{
    memset(res, 0, sizeof *res);
    const tf_contact_region *r = &p->contacts[contact].region;
    if (r->kind == TF_CONTACT_REGION_NONE) {
        return tf_fail(ctx, "contact %s is a site, not a region", p->contacts[contact].name);
    }
    double S = first_spacing(r);
    unsigned nx = sites_along(r->chart.len[0], S), ny = sites_along(r->chart.len[1], S);
    unsigned levels = r->spacing > 0 ? 1 : tg->levels > 0 ? tg->levels : TF_REGION_MAX_LEVELS;
    for (unsigned k = 0; k < levels && k < TF_REGION_MAX_LEVELS; ++k) {
        tf_region_level *lv = &res->level[res->n_levels++];
        lv->nx = nx;
        lv->ny = ny;
        lv->h[0] = r->chart.len[0] / (nx - 1);
        lv->h[1] = r->chart.len[1] / (ny - 1);
        if (fit_level(ctx, s, p, r, tg, res, lv) != 0) {
            tf_region_result_free(res);
            return -1;
        }
        tf_info(ctx,
                "region %s: %u x %u sites (spacing %.3g x %.3g mm): force %.3g %%, surface %.3g "
                "%% and coupling %.3g %% at rank %u (held out at %u cell centres, %zu pairs), "
                "height %.2g mm",
                p->contacts[contact].name, nx, ny, lv->h[0], lv->h[1], 100 * lv->force,
                100 * lv->surface, 100 * lv->coupling, lv->rank, (nx - 1) * (ny - 1), lv->pairs,
                lv->height);
        if (!(lv->min_stiffness > 0)) {
            tf_region_result_free(res);
            return tf_fail(ctx, "region %s: the blended stiffness is not positive definite "
                                "everywhere (smallest eigenvalue %g N/mm over a sampling 8 per "
                                "site interval): the law would not be passive",
                           p->contacts[contact].name, lv->min_stiffness);
        }
        const int done = tg->levels == 0 && lv->met;
        char cpl[64]; /* the coupling against its target, or stated alone */
        if (isfinite(tg->coupling)) {
            snprintf(cpl, sizeof cpl, "coupling %.2g %% %s %.2g %%", 100 * lv->coupling,
                     done ? "<=" : "(target", 100 * tg->coupling);
        } else {
            snprintf(cpl, sizeof cpl, "coupling %.2g %% (not a target)", 100 * lv->coupling);
        }
        if (done) {
            snprintf(res->why, sizeof res->why,
                     "target met at spacing %.3g x %.3g mm (%u x %u sites): force %.2g %% <= %.2g "
                     "%%, surface %.2g %% <= %.2g %%, %s at rank %u",
                     lv->h[0], lv->h[1], nx, ny, 100 * lv->force, 100 * tg->force,
                     100 * lv->surface, 100 * tg->surface, cpl, lv->rank);
            break;
        }
        if (2 * nx - 1 > tg->max_sites || 2 * ny - 1 > tg->max_sites || k + 1 == levels) {
            snprintf(res->why, sizeof res->why,
                     "%s at spacing %.3g x %.3g mm (%u x %u sites): force %.2g %% (target %.2g "
                     "%%), surface %.2g %% (target %.2g %%), %s%s at rank %u",
                     r->spacing > 0          ? "the scene's spacing"
                     : tg->levels > 0        ? "the spacings asked for end"
                                             : "the cap of the site count",
                     lv->h[0], lv->h[1], nx, ny, 100 * lv->force, 100 * tg->force,
                     100 * lv->surface, 100 * tg->surface, cpl,
                     isfinite(tg->coupling) ? ")" : "", lv->rank);
            break;
        }
        nx = 2 * nx - 1;
        ny = 2 * ny - 1;
    }
    tf_info(ctx, "region %s: %s", p->contacts[contact].name, res->why);
    return 0;
}
