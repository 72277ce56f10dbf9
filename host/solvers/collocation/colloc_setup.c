/*
 * colloc_setup.c — the particles of a collocation body (colloc.h): options,
 * k-nearest supports, support radii, the kernel of seed 004 eq 1, volumes
 * and masses (eqs 2-3), state arrays.  The MLS part is colloc_mls.c.
 */
#include "solvers/collocation/colloc_internal.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "materials/elasticity.h"
#include "meshfree/neighbours.h"

/* A neighbour at the same distance as the k-th (relative): regular grids. */
#define TIE 1e-9

/* Allocations per particle are checked once: every array is freed by
 * tf_colloc_free whether it was allocated or not. */
#define NEW(p, count) ((p) = calloc((size_t)(count) + 1, sizeof *(p)))

void tf_colloc_defaults(tf_colloc_opts *o)
{
    /* k = 10, support 1.5, stab 0.2: the smallest supports that keep the
     * Hertz test within 5 % and put block48's in-plane static limit within
     * 2 % of CalculiX (docs/collocation.md, "Defaults"); seed 004 uses
     * k = 16 and gives no support factor. */
    o->neighbours = 10;
    o->support = 1.5;
    o->rcond_min = 1e-6;
    o->kv = 0;
    o->stab = 0.2;
    o->threads = 0;
}

int tf_colloc_threads(const tf_colloc *c)
{
    return c->opts.threads > 0 ? c->opts.threads : omp_get_max_threads();
}

/* Seed 004 eq 1: w(r) = 1 - 3r^2 + 3r^4 - r^6 = (1 - r^2)^3 for r <= 1. */
double tf_colloc_kernel(double r)
{
    if (!(r < 1)) {
        return 0;
    }
    double t = 1 - r * r;
    return t * t * t;
}

static int check_opts(tf_ctx *ctx, const tf_colloc_body *b, const tf_colloc_opts *o)
{
    char msg[256];
    const char *field = tf_material_check(&b->material, msg, sizeof msg);
    if (field) {
        return tf_fail(ctx, "material.%s: %s", field, msg);
    }
    if (o->neighbours < 4 || o->neighbours > 256) {
        return tf_fail(ctx, "neighbours = %u: need 4 .. 256 (3 for a gradient, and more)",
                       o->neighbours);
    }
    if (!(o->support > 1 && o->support <= 10)) {
        return tf_fail(ctx, "support = %g: the support radius factor must be in (1, 10]",
                       o->support);
    }
    if (o->threads < 0 || !(o->rcond_min > 0 && o->rcond_min < 1) ||
        !(o->kv >= 0 && isfinite(o->kv)) ||
        !(o->stab >= 0 && isfinite(o->stab))) {
        return tf_fail(ctx,
                       "rcond_min in (0, 1), kv >= 0 and stab >= 0 required "
                       "(got %g, %g, %g)",
                       o->rcond_min, o->kv, o->stab);
    }
    if (!(b->density > 0 && isfinite(b->density))) {
        return tf_fail(ctx, "density = %g t/mm^3: must be > 0 (water: 1e-9)", b->density);
    }
    if (b->n_mirrors > 3) {
        return tf_fail(ctx, "%zu mirror planes: at most 3", b->n_mirrors);
    }
    for (size_t p = 0; p < b->n_mirrors; ++p) {
        if (b->mirrors[p].axis < 0 || b->mirrors[p].axis > 2 || !isfinite(b->mirrors[p].at)) {
            return tf_fail(ctx,
                           "mirror plane %zu: axis %d must be 0, 1 or 2 and the "
                           "coordinate finite",
                           p, b->mirrors[p].axis);
        }
    }
    if (b->n <= o->neighbours) {
        return tf_fail(ctx, "%zu particles: need more than neighbours = %u", b->n, o->neighbours);
    }
    for (size_t i = 0; i < 3 * b->n; ++i) {
        if (!isfinite(b->X[i])) {
            return tf_fail(ctx, "particle %zu: coordinate %c is not finite", i / 3,
                           (int)('x' + i % 3));
        }
    }
    for (size_t i = 0; b->volume && i < b->n; ++i) {
        if (!(b->volume[i] > 0 && isfinite(b->volume[i]))) {
            return tf_fail(ctx, "particle %zu: volume %g mm^3 must be > 0", i, b->volume[i]);
        }
    }
    return 0;
}

/* A bin size of about one particle per bin. */
static void bin_size(const double *X, size_t n, double r[3])
{
    double lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        lo[a] = hi[a] = X[a];
    }
    for (size_t i = 0; i < n; ++i) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = fmin(lo[a], X[3 * i + a]);
            hi[a] = fmax(hi[a], X[3 * i + a]);
        }
    }
    double ext = fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2]));
    double vol = 1;
    for (int a = 0; a < 3; ++a) {
        vol *= fmax(hi[a] - lo[a], 1e-3 * ext);
    }
    double s = cbrt(vol / (double)n);
    for (int a = 0; a < 3; ++a) {
        r[a] = s > 0 ? s : 1;
    }
}

/* The k nearest (ties included) of each particle among the first npts
 * points of X: cnt[i] of them at tmp[i cap ..], distances at dist[i cap ..]. */
static int nearest_all(const tf_colloc *c, size_t npts, uint32_t *tmp, double *dist, size_t *cnt,
                       size_t cap)
{
    tf_nbr grid;
    double r[3];
    bin_size(c->X, npts, r);
    if (tf_nbr_build(&grid, c->X, npts, r) != 0) {
        return -1;
    }
#pragma omp parallel for schedule(dynamic, 64) num_threads(tf_colloc_threads(c))
    for (size_t i = 0; i < c->n; ++i) {
        cnt[i] = tf_nbr_nearest(&grid, c->X + 3 * i, c->opts.neighbours, TIE, i, tmp + i * cap,
                                dist + i * cap, cap);
    }
    tf_nbr_free(&grid);
    return 0;
}

/* Neighbour lists in CSR form from the k-nearest lists; rbar, rmin, h. */
static int fill_supports(tf_ctx *ctx, tf_colloc *c, const uint32_t *tmp, const double *dist,
                         const size_t *cnt, size_t cap)
{
    size_t n = c->n;
    c->start = malloc((n + 1) * sizeof *c->start);
    if (c->start == NULL) {
        return -1;
    }
    c->start[0] = 0;
    for (size_t i = 0; i < n; ++i) {
        c->start[i + 1] = c->start[i] + (uint32_t)cnt[i];
    }
    size_t nnz = c->start[n];
    if (!NEW(c->nbr, nnz) || !NEW(c->w, nnz) || !NEW(c->y, 3 * nnz)) {
        return -1;
    }
    for (size_t i = 0; i < n; ++i) {
        double sum = 0;
        for (size_t q = 0; q < cnt[i]; ++q) {
            c->nbr[c->start[i] + q] = tmp[i * cap + q];
            sum += dist[i * cap + q];
        }
        c->rbar[i] = sum / (double)cnt[i];
        c->rmin[i] = dist[i * cap];
        c->h[i] = c->opts.support * c->rbar[i];
        if (!(dist[i * cap + cnt[i] - 1] < c->h[i])) {
            tf_fail(ctx,
                    "particle %zu: its farthest neighbour (%g mm) lies outside its support "
                    "radius %g mm = %g x the mean neighbour distance: raise support",
                    i, dist[i * cap + cnt[i] - 1], c->h[i], c->opts.support);
            return -2;
        }
    }
    return 0;
}

/* k-nearest supports; with mirror planes, first among the particles (for
 * the reach that decides which images are needed), then with the images. */
static int supports(tf_ctx *ctx, tf_colloc *c)
{
    size_t n = c->n, cap = 2 * (size_t)c->opts.neighbours + 8;
    uint32_t *tmp = malloc(n * cap * sizeof *tmp);
    double *dist = malloc(n * cap * sizeof *dist), *reach = malloc(n * sizeof *reach);
    size_t *cnt = malloc(n * sizeof *cnt);
    int rc = !tmp || !dist || !reach || !cnt ? -1 : 0;
    if (rc == 0 && c->n_mirrors) {
        rc = nearest_all(c, n, tmp, dist, cnt, cap);
        for (size_t i = 0; rc == 0 && i < n; ++i) {
            reach[i] = dist[i * cap + cnt[i] - 1] * (1 + TIE);
        }
        if (rc == 0 && tf_colloc_make_ghosts(ctx, c, reach) != 0) {
            rc = -2;
        }
    }
    if (rc == 0) {
        rc = nearest_all(c, c->na, tmp, dist, cnt, cap);
    }
    if (rc == 0 && c->na > n) {
        rc = tf_colloc_drop_ghosts(c, tmp, cnt, cap);
    }
    if (rc == 0) {
        rc = fill_supports(ctx, c, tmp, dist, cnt, cap);
    }
    if (rc == -1) {
        tf_fail(ctx, "out of memory for the supports of %zu particles", n);
    }
    free(tmp);
    free(dist);
    free(reach);
    free(cnt);
    return rc ? -1 : 0;
}

/* Kernel weights w_ik = w(|X_k - X_i| / h_i) (eq 1, reference configuration:
 * total Lagrangian) and y_ik = w_ik X_ik. */
static void weights(tf_colloc *c)
{
#pragma omp parallel for schedule(static) num_threads(tf_colloc_threads(c))
    for (size_t i = 0; i < c->n; ++i) {
        for (uint32_t p = c->start[i]; p < c->start[i + 1]; ++p) {
            const double *xi = c->X + 3 * i, *xk = c->X + 3 * (size_t)c->nbr[p];
            double d0 = xk[0] - xi[0], d1 = xk[1] - xi[1], d2 = xk[2] - xi[2];
            double w = tf_colloc_kernel(sqrt(d0 * d0 + d1 * d1 + d2 * d2) / c->h[i]);
            c->w[p] = w;
            c->y[3 * (size_t)p] = w * d0;
            c->y[3 * (size_t)p + 1] = w * d1;
            c->y[3 * (size_t)p + 2] = w * d2;
        }
    }
}

/* Seed 004 eqs 2-3 as Müller et al. write them: m_i = s rbar_i^3 rho,
 * rho_i = sum_j m_j W(r_ij, h_i) over the support and the particle itself,
 * v_i = m_i / rho_i.  Eq 1 prints the kernel without its normalisation;
 * Müller's poly6 kernel W = 315 / (64 pi h^3) w(r / h) is used here so that
 * rho_i is a density (the extracted text is garbled there).  s makes the
 * mean density rho, as the seed says; v_i does not depend on s.  Eqs 2-3
 * count a boundary particle's volume as if the body went on (few
 * neighbours, low density, large volume): total_volume rescales them. */
static void seed_volumes(tf_colloc *c, double total)
{
    size_t n = c->n;
    double sum_rho = 0, sum_v = 0;
    for (size_t i = 0; i < n; ++i) {
        double hi = c->h[i], norm = 315 / (64 * M_PI * hi * hi * hi);
        double rho = c->rbar[i] * c->rbar[i] * c->rbar[i] * norm; /* j = i: w(0) = 1 */
        for (uint32_t p = c->start[i]; p < c->start[i + 1]; ++p) {
            double rj = c->rbar[c->nbr[p] < n ? c->nbr[p] : c->gsrc[c->nbr[p] - n]];
            rho += rj * rj * rj * norm * c->w[p];
        }
        c->vol[i] = c->rbar[i] * c->rbar[i] * c->rbar[i] / rho; /* s and rho cancel */
        sum_rho += rho;
        sum_v += c->vol[i] * tf_colloc_mirror_share(c, i);
    }
    double s = (double)n / sum_rho; /* mean of s rho_i / rho is 1 */
    double scale = total > 0 ? total / sum_v : 1;
    for (size_t i = 0; i < n; ++i) {
        double share = tf_colloc_mirror_share(c, i); /* the part on the body's side */
        c->vol[i] *= scale * share;
        c->mass[i] = total > 0 ? c->density * c->vol[i]
                               : share * s * c->rbar[i] * c->rbar[i] * c->rbar[i] * c->density;
    }
}

tf_colloc *tf_colloc_new(tf_ctx *ctx, const tf_colloc_body *b, const tf_colloc_opts *o)
{
    tf_colloc_opts def;
    if (o == NULL) {
        tf_colloc_defaults(&def);
        o = &def;
    }
    if (check_opts(ctx, b, o) != 0) {
        return NULL;
    }
    tf_colloc *c = calloc(1, sizeof *c);
    if (c == NULL) {
        tf_fail(ctx, "out of memory");
        return NULL;
    }
    size_t n = b->n;
    c->n = n;
    c->mat = b->material;
    unsigned caps = tf_material_caps(&b->material);
    c->small = !(caps & TF_MATERIAL_FINITE);
    c->hsize = tf_material_history_size(&b->material);
    /* the step's own path (colloc_force.c) */
    c->hooke = (caps & (TF_MATERIAL_HOOKE | TF_MATERIAL_FINITE)) ==
               (TF_MATERIAL_HOOKE | TF_MATERIAL_FINITE);
    tf_lame lame = tf_material_lame(&b->material);
    c->lame_lambda = lame.lambda;
    c->lame_mu = lame.mu;
    c->density = b->density;
    c->opts = *o;
    c->na = n;
    c->n_mirrors = b->n_mirrors;
    for (size_t p = 0; p < b->n_mirrors; ++p) {
        c->mirror[p] = b->mirrors[p];
    }
    if (!NEW(c->X, 3 * n) || !NEW(c->fixed, n) || !NEW(c->h, n) || !NEW(c->rbar, n) ||
        !NEW(c->rmin, n) || !NEW(c->vol, n) || !NEW(c->mass, n) || !NEW(c->ainv, 9 * n) ||
        !NEW(c->s, 3 * n) || !NEW(c->beta, n) || !NEW(c->u, 3 * n) || !NEW(c->v, 3 * n) ||
        !NEW(c->fext, 3 * n) || !NEW(c->ubar, 3 * n) || !NEW(c->f, 3 * n) ||
        !NEW(c->hold, c->hsize * n) || !NEW(c->hnew, c->hsize * n) ||
        !(c->ph1 = aligned_alloc(64, TF_COLLOC_PH1 * (n + 1) * sizeof *c->ph1)) || !NEW(c->epart, n) || !NEW(c->bad, n)) {
        tf_fail(ctx, "out of memory for %zu particles", n);
        tf_colloc_free(c);
        return NULL;
    }
    memcpy(c->X, b->X, 3 * n * sizeof *c->X);
    if (b->fixed) {
        memcpy(c->fixed, b->fixed, n);
    }
    for (size_t i = 0; i < n; ++i) {
        tf_material_history_init(&c->mat, c->hold + i * c->hsize);
        tf_material_history_init(&c->mat, c->hnew + i * c->hsize);
    }
    if (supports(ctx, c) != 0) {
        tf_colloc_free(c);
        return NULL;
    }
    if (c->na > c->n && (!NEW(c->ue, 3 * c->na) || !NEW(c->fe, 3 * c->na))) {
        tf_fail(ctx, "out of memory for %zu mirror images", c->na - c->n);
        tf_colloc_free(c);
        return NULL;
    }
    weights(c);
    if (b->volume) {
        for (size_t i = 0; i < n; ++i) {
            c->vol[i] = b->volume[i];
            c->mass[i] = c->density * b->volume[i];
        }
    } else {
        seed_volumes(c, b->total_volume);
    }
    if (tf_colloc_setup_mls(ctx, c) != 0) {
        tf_colloc_free(c);
        return NULL;
    }
    return c;
}

void tf_colloc_free(tf_colloc *c)
{
    if (c == NULL) {
        return;
    }
    void *all[] = {c->X,   c->fixed, c->start, c->nbr,  c->y,    c->w,    c->h,    c->rbar,
                   c->rmin, c->vol,  c->mass,  c->ainv, c->s,    c->beta, c->rstart, c->rsrc,
                   c->ryc, c->yw,     c->bsum,  c->u,    c->v,    c->fext, c->ubar, c->f,    c->hold,
                   c->hnew, c->ph1,  c->epart, c->bad, c->mdr, c->u0, c->f0, c->res,
                   c->gsrc, c->gstart, c->gsign, c->ue, c->fe};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; ++k) {
        free(all[k]);
    }
    free(c);
}

size_t tf_colloc_count(const tf_colloc *c) { return c->n; }
size_t tf_colloc_ghosts(const tf_colloc *c) { return c->na - c->n; }
const double *tf_colloc_volumes(const tf_colloc *c) { return c->vol; }
const double *tf_colloc_masses(const tf_colloc *c) { return c->mass; }
const double *tf_colloc_radii(const tf_colloc *c) { return c->h; }
double *tf_colloc_u(tf_colloc *c) { return c->u; }
double *tf_colloc_v(tf_colloc *c) { return c->v; }
double *tf_colloc_fext(tf_colloc *c) { return c->fext; }
double *tf_colloc_ubar(tf_colloc *c) { return c->ubar; }
double tf_colloc_time(const tf_colloc *c) { return c->time; }

const uint32_t *tf_colloc_neighbours(const tf_colloc *c, size_t i, size_t *count)
{
    *count = c->start[i + 1] - c->start[i];
    return c->nbr + c->start[i];
}

double tf_colloc_rcond(const tf_colloc *c, size_t *at)
{
    if (at) {
        *at = c->rcond_at;
    }
    return c->rcond;
}
