/*
 * region_sites.c — a contact region's site solves (region_sites.h).
 */
#include "fitting/region_sites.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/log.h"
#include "problem/region_chart.h"
#include "solvers/probe.h"

/* Sites per block of right-hand sides (3 columns each). */
#define BATCH 16

/* The chart-axis load vectors of the patch at (a, b) into f (3N x 3)
 * (callable from several threads, each with its own context). */
static int site_loads(tf_ctx *ctx, const tf_solver *s, const tf_problem *p,
                      const tf_contact_region *r, double a, double b, double *f, double x[3])
{
    tf_patch patch;
    if (tf_region_site_patch(ctx, p, r, a, b, &patch, x) != 0) {
        return -1;
    }
    size_t n3 = 3 * p->cloud.n;
    double *g = malloc(3 * n3 * sizeof *g);
    int rc = g == NULL ? tf_fail(ctx, "out of memory") : tf_solver_patch_loads(ctx, s, &patch, g);
    const double *R = r->chart.R;
    for (size_t d = 0; rc == 0 && d < n3; ++d) {
        for (int k = 0; k < 3; ++k) { /* e_k = sum_a R[k][a] (scene axis a) */
            f[(size_t)k * n3 + d] = R[3 * k] * g[d] + R[3 * k + 1] * g[n3 + d] +
                                    R[3 * k + 2] * g[2 * n3 + d];
        }
    }
    free(g);
    tf_patch_release(&patch);
    return rc;
}

int tf_region_site_loads(tf_ctx *ctx, const tf_solver *s, const tf_problem *p,
                         const tf_contact_region *r, double a, double b, double *f, double x[3])
{
    return site_loads(ctx, s, p, r, a, b, f, x);
}

/* The non-zero rows of f (3N x 3) as a sparse load. */
static int sparse_of(const double *f, size_t n3, tf_region_load *l)
{
    size_t n = 0;
    for (size_t d = 0; d < n3; ++d) {
        n += f[d] != 0 || f[n3 + d] != 0 || f[2 * n3 + d] != 0;
    }
    l->dof = malloc((n + 1) * sizeof *l->dof);
    l->val = malloc((3 * n + 1) * sizeof *l->val);
    if (!l->dof || !l->val) {
        return -1;
    }
    l->n = 0;
    for (size_t d = 0; d < n3; ++d) {
        if (f[d] != 0 || f[n3 + d] != 0 || f[2 * n3 + d] != 0) {
            l->dof[l->n] = (uint32_t)d;
            for (int k = 0; k < 3; ++k) {
                l->val[3 * l->n + (size_t)k] = f[(size_t)k * n3 + d];
            }
            l->n++;
        }
    }
    return 0;
}

void tf_region_sites_average(const tf_region_sites *t, size_t i, const double *u, double out[3])
{
    const tf_region_load *l = &t->L[i];
    out[0] = out[1] = out[2] = 0;
    for (size_t m = 0; m < l->n; ++m) {
        for (int k = 0; k < 3; ++k) {
            out[k] += l->val[3 * m + (size_t)k] * u[l->dof[m]];
        }
    }
}

void tf_region_sites_free(tf_region_sites *t)
{
    for (size_t i = 0; t->L && i < t->n; ++i) {
        free(t->L[i].dof);
        free(t->L[i].val);
    }
    free(t->L);
    free(t->ab);
    free(t->x);
    free(t->C);
    free(t->U);
    free(t->seconds);
    free(t->pair);
    free(t->cross);
    memset(t, 0, sizeof *t);
}

static int alloc_sites(tf_region_sites *t, size_t n, size_t n_out)
{
    memset(t, 0, sizeof *t);
    t->n = n;
    t->n_out = n_out;
    t->ab = malloc((2 * n + 1) * sizeof *t->ab);
    t->x = malloc((3 * n + 1) * sizeof *t->x);
    t->C = malloc((9 * n + 1) * sizeof *t->C);
    t->U = malloc((9 * n_out * n + 1) * sizeof *t->U);
    t->L = calloc(n + 1, sizeof *t->L);
    t->seconds = calloc(n + 1, sizeof *t->seconds);
    return t->ab && t->x && t->C && t->U && t->L && t->seconds ? 0 : -1;
}

/* The response to the problem's own loads (NULL when the solver is linear:
 * there is none). */
static int base_response(tf_ctx *ctx, tf_solver *s, size_t n3, double **base)
{
    *base = NULL;
    if (tf_solver_caps_of(s) & TF_SOLVER_LINEAR) {
        return 0;
    }
    double *zero = calloc(n3, sizeof *zero);
    *base = malloc(n3 * sizeof **base);
    if (!zero || !*base) {
        free(zero);
        return tf_fail(ctx, "out of memory");
    }
    int rc = tf_solver_solve_loads(s, zero, 1, *base);
    free(zero);
    return rc;
}

/* C = L^T U of one site (3 columns each), its asymmetry, symmetrised. */
static double compliance(const double *f, const double *u, size_t n3, double C[9])
{
    for (int k = 0; k < 3; ++k) {
        for (int l = 0; l < 3; ++l) {
            double sum = 0;
            for (size_t d = 0; d < n3; ++d) {
                sum += f[(size_t)k * n3 + d] * u[(size_t)l * n3 + d];
            }
            C[3 * k + l] = sum;
        }
    }
    double asym = 0, norm = 0;
    for (int k = 0; k < 9; ++k) {
        double d = C[k] - C[3 * (k % 3) + k / 3];
        asym += d * d;
        norm += C[k] * C[k];
    }
    for (int k = 0; k < 3; ++k) {
        for (int l = k + 1; l < 3; ++l) {
            double m = 0.5 * (C[3 * k + l] + C[3 * l + k]);
            C[3 * k + l] = C[3 * l + k] = m;
        }
    }
    return norm > 0 ? sqrt(asym / norm) : 0;
}

/* Whether the tips at (a1, b1) and (a2, b2) overlap. */
static int tips_overlap(const tf_contact_region *r, const double g1[2], const double g2[2])
{
    double w[2], da = fabs(g1[0] - g2[0]), db = fabs(g1[1] - g2[1]);
    tf_region_tip_extent(r, w);
    return r->tip == TF_TIP_RECT ? da < 2 * w[0] && db < 2 * w[1] : hypot(da, db) < 2 * w[0];
}

/* Records C(j, s) for the partners j of new site s (global index gs), its
 * displacements u (3N x 3). */
static int record_pairs(const tf_region_sites *partners, double radius, const tf_contact_region *r,
                        const double g[2], size_t gs, const double *u, size_t n3,
                        tf_region_sites *t)
{
    for (size_t j = 0; partners != NULL && j < partners->n; ++j) {
        const double *gj = partners->ab + 2 * j;
        if (hypot(gj[0] - g[0], gj[1] - g[1]) > radius || tips_overlap(r, gj, g)) {
            continue;
        }
        if ((t->n_pairs & (t->n_pairs - 1)) == 0) { /* room doubles at powers of two */
            size_t cap = t->n_pairs ? 2 * t->n_pairs : 1;
            size_t *pair = realloc(t->pair, 2 * cap * sizeof *pair);
            t->pair = pair ? pair : t->pair;
            double *cross = realloc(t->cross, 9 * cap * sizeof *cross);
            t->cross = cross ? cross : t->cross;
            if (!pair || !cross) {
                return -1;
            }
        }
        const tf_region_load *l = &partners->L[j];
        double *C = t->cross + 9 * t->n_pairs;
        for (int k = 0; k < 3; ++k) {
            for (int c = 0; c < 3; ++c) {
                double sum = 0;
                for (size_t m = 0; m < l->n; ++m) {
                    sum += l->val[3 * m + (size_t)k] * u[(size_t)c * n3 + l->dof[m]];
                }
                C[3 * k + c] = sum;
            }
        }
        t->pair[2 * t->n_pairs] = j;
        t->pair[2 * t->n_pairs + 1] = gs;
        t->n_pairs++;
    }
    return 0;
}

/* One batch: sites [b0, b0 + nb) of t. */
static int solve_batch(tf_ctx *ctx, tf_solver *s, const tf_problem *p,
                       const tf_contact_region *r, const double *base, size_t b0, size_t nb,
                       const tf_region_sites *partners, double radius, double *f, double *u,
                       tf_region_sites *t)
{
    size_t n3 = 3 * p->cloud.n, n_out = t->n_out;
    int failed = 0;
    char err[TF_CTX_ERR_MAX + 128] = ""; /* a thread's message with its site */
    memset(f, 0, 3 * nb * n3 * sizeof *f);
#pragma omp parallel for schedule(dynamic) num_threads(tf_ctx_threads(ctx))
    for (size_t i = 0; i < nb; ++i) {
        tf_ctx e; /* this thread's */
        tf_ctx_init(&e);
        e.level = ctx->level;
        size_t k = b0 + i;
        if (site_loads(&e, s, p, r, t->ab[2 * k], t->ab[2 * k + 1], f + 3 * n3 * i,
                       t->x + 3 * k) != 0 ||
            sparse_of(f + 3 * n3 * i, n3, &t->L[k]) != 0) {
#pragma omp critical(tf_region_sites_err)
            {
                if (!failed) {
                    snprintf(err, sizeof err, "site (%g, %g) mm: %s", t->ab[2 * k],
                             t->ab[2 * k + 1], e.err);
                }
                failed = 1;
            }
        }
    }
    if (failed) {
        return tf_fail(ctx, "%s", err);
    }
    if (tf_solver_solve_loads(s, f, 3 * nb, u) != 0) {
        return ctx == s->ctx ? -1 : tf_fail(ctx, "%s", s->ctx->err);
    }
    for (size_t c = 0; base != NULL && c < 3 * nb; ++c) {
        for (size_t d = 0; d < n3; ++d) {
            u[c * n3 + d] -= base[d];
        }
    }
    size_t g0 = partners != NULL ? partners->n : 0;
    for (size_t i = 0; i < nb; ++i) {
        double a = compliance(f + 3 * n3 * i, u + 3 * n3 * i, n3, t->C + 9 * (b0 + i));
        t->asym = fmax(t->asym, a);
        if (record_pairs(partners, radius, r, t->ab + 2 * (b0 + i), g0 + b0 + i,
                         u + 3 * n3 * i, n3, t) != 0) {
            return tf_fail(ctx, "out of memory");
        }
    }
#pragma omp parallel for schedule(dynamic) num_threads(tf_ctx_threads(ctx))
    for (size_t c = 0; c < 3 * nb; ++c) {
        tf_ctx e; /* this thread's */
        tf_ctx_init(&e);
        e.level = ctx->level;
        double *out = t->U + 9 * n_out * b0 + 3 * n_out * c; /* site b0 + c/3, column c%3 */
        if (tf_solver_probe_outputs(&e, s, p, u + c * n3, out) != 0) {
#pragma omp critical(tf_region_sites_err)
            {
                if (!failed) {
                    snprintf(err, sizeof err, "outputs: %s", e.err);
                }
                failed = 1;
            }
        }
    }
    return failed ? tf_fail(ctx, "%s", err) : 0;
}

int tf_region_sites_solve(tf_ctx *ctx, tf_solver *s, const tf_problem *p,
                          const tf_contact_region *r, const double *ab, size_t n,
                          const tf_region_sites *partners, double radius, tf_region_sites *out)
{
    size_t n3 = 3 * p->cloud.n;
    if (alloc_sites(out, n, p->outputs.n_nodes) != 0) {
        tf_region_sites_free(out);
        return tf_fail(ctx, "out of memory for %zu sites", n);
    }
    memcpy(out->ab, ab, 2 * n * sizeof *ab);
    double *base = NULL, *f = malloc(3 * BATCH * n3 * sizeof *f), *u = malloc(3 * BATCH * n3 * sizeof *u);
    int rc = !f || !u ? tf_fail(ctx, "out of memory for %d sites' loads", BATCH)
                      : base_response(ctx, s, n3, &base);
    double t0 = omp_get_wtime(), last = t0;
    for (size_t b0 = 0; rc == 0 && b0 < n; b0 += BATCH) {
        size_t nb = n - b0 < BATCH ? n - b0 : BATCH;
        double tb = omp_get_wtime();
        rc = solve_batch(ctx, s, p, r, base, b0, nb, partners, radius, f, u, out);
        double now = omp_get_wtime();
        for (size_t i = 0; i < nb; ++i) {
            out->seconds[b0 + i] = (now - tb) / (double)nb;
        }
        if (rc == 0 && (now - last > 5 || b0 + nb == n) && n > BATCH) {
            tf_info(ctx, "region: %zu of %zu sites solved (%.1f s)", b0 + nb, n, now - t0);
            last = now;
        }
    }
    free(f);
    free(u);
    free(base);
    if (rc != 0) {
        tf_region_sites_free(out);
    }
    return rc;
}

int tf_region_sites_append(tf_ctx *ctx, tf_region_sites *dst, tf_region_sites *src)
{
    if (dst->n == 0) {
        tf_region_sites_free(dst);
        *dst = *src;
        memset(src, 0, sizeof *src);
        return 0;
    }
    size_t n = dst->n + src->n, no = dst->n_out;
    double *ab = realloc(dst->ab, 2 * n * sizeof *ab);
    dst->ab = ab ? ab : dst->ab;
    double *x = realloc(dst->x, 3 * n * sizeof *x);
    dst->x = x ? x : dst->x;
    double *C = realloc(dst->C, 9 * n * sizeof *C);
    dst->C = C ? C : dst->C;
    double *U = realloc(dst->U, 9 * no * n * sizeof *U);
    dst->U = U ? U : dst->U;
    tf_region_load *L = realloc(dst->L, n * sizeof *L);
    dst->L = L ? L : dst->L;
    double *sec = realloc(dst->seconds, n * sizeof *sec);
    dst->seconds = sec ? sec : dst->seconds;
    if (!ab || !x || !C || !U || !L || !sec) {
        return tf_fail(ctx, "out of memory");
    }
    memcpy(dst->ab + 2 * dst->n, src->ab, 2 * src->n * sizeof *ab);
    memcpy(dst->x + 3 * dst->n, src->x, 3 * src->n * sizeof *x);
    memcpy(dst->C + 9 * dst->n, src->C, 9 * src->n * sizeof *C);
    memcpy(dst->U + 9 * no * dst->n, src->U, 9 * no * src->n * sizeof *U);
    memcpy(dst->L + dst->n, src->L, src->n * sizeof *L);
    memcpy(dst->seconds + dst->n, src->seconds, src->n * sizeof *sec);
    dst->asym = fmax(dst->asym, src->asym);
    dst->n = n;
    if (src->n_pairs > 0) {
        size_t np = dst->n_pairs + src->n_pairs;
        size_t *pair = realloc(dst->pair, 2 * np * sizeof *pair);
        dst->pair = pair ? pair : dst->pair;
        double *cross = realloc(dst->cross, 9 * np * sizeof *cross);
        dst->cross = cross ? cross : dst->cross;
        if (!pair || !cross) {
            return tf_fail(ctx, "out of memory");
        }
        memcpy(dst->pair + 2 * dst->n_pairs, src->pair, 2 * src->n_pairs * sizeof *pair);
        memcpy(dst->cross + 9 * dst->n_pairs, src->cross, 9 * src->n_pairs * sizeof *cross);
        dst->n_pairs = np;
    }
    free(src->L); /* (its loads moved) */
    src->L = NULL;
    src->n = 0;
    tf_region_sites_free(src);
    return 0;
}

int tf_region_sites_combine(tf_ctx *ctx, tf_solver *s, const tf_region_sites *t,
                            const size_t *site, size_t n_sites, const double *coef, size_t ncomb,
                            double *u)
{
    size_t n3 = 3 * tf_solver_node_count(s);
    double *f = calloc(n3 * ncomb + 1, sizeof *f), *base = NULL;
    if (f == NULL) {
        return tf_fail(ctx, "out of memory");
    }
    for (size_t j = 0; j < ncomb; ++j) {
        for (size_t i = 0; i < n_sites; ++i) {
            const tf_region_load *l = &t->L[site[i]];
            const double *c = coef + 3 * n_sites * j + 3 * i;
            for (size_t m = 0; m < l->n; ++m) {
                f[j * n3 + l->dof[m]] += c[0] * l->val[3 * m] + c[1] * l->val[3 * m + 1] +
                                         c[2] * l->val[3 * m + 2];
            }
        }
    }
    int rc = base_response(ctx, s, n3, &base);
    if (rc == 0 && tf_solver_solve_loads(s, f, ncomb, u) != 0) {
        rc = ctx == s->ctx ? -1 : tf_fail(ctx, "%s", s->ctx->err);
    }
    for (size_t j = 0; rc == 0 && base != NULL && j < ncomb; ++j) {
        for (size_t d = 0; d < n3; ++d) {
            u[j * n3 + d] -= base[d];
        }
    }
    free(f);
    free(base);
    return rc;
}
