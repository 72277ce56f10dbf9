/*
 * random_region.c — see random_region.h.
 */
#include "random_region.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static double uniform(tf_rng *r, double lo, double hi)
{
    return tf_rng_range(r, lo, hi);
}

/* A random rotation (rows e1, e2, n) from a unit quaternion, or a box
 * face's signed permutation. */
static void random_rotation(tf_rng *r, double rot[9])
{
    if (tf_rng_below(r, 3) == 0) {
        static const double faces[6][9] = {
            {1, 0, 0, 0, 1, 0, 0, 0, 1},  {1, 0, 0, 0, -1, 0, 0, 0, -1},
            {0, 1, 0, 0, 0, 1, 1, 0, 0},  {0, 0, 1, 0, 1, 0, -1, 0, 0},
            {0, 0, 1, 1, 0, 0, 0, 1, 0},  {1, 0, 0, 0, 0, 1, 0, -1, 0}};
        memcpy(rot, faces[tf_rng_below(r, 6)], 9 * sizeof *rot);
        return;
    }
    double q[4], n = 0;
    do {
        n = 0;
        for (int i = 0; i < 4; ++i) {
            q[i] = uniform(r, -1, 1);
            n += q[i] * q[i];
        }
    } while (n > 1 || n < 1e-3);
    n = sqrt(n);
    const double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    const double m[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                         2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                         2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
    memcpy(rot, m, sizeof m);
}

/* A random SPD matrix: eigenvalues in [lo, hi], random axes. */
static void random_spd(tf_rng *r, double lo, double hi, double k[9])
{
    double q[9], lam[3];
    random_rotation(r, q);
    for (int i = 0; i < 3; ++i) {
        lam[i] = exp(uniform(r, log(lo), log(hi)));
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            k[3 * i + j] = 0;
            for (int a = 0; a < 3; ++a) {
                k[3 * i + j] += q[3 * a + i] * lam[a] * q[3 * a + j];
            }
        }
    }
}

void tf_random_region_draw(tf_rng *r, uint32_t max_side, tf_random_region *g)
{
    memset(g, 0, sizeof *g);
    for (int i = 0; i < 3; ++i) {
        g->chart.origin[i] = uniform(r, -60, 60);
    }
    random_rotation(r, g->chart.rot);
    g->chart.nx = 2 + tf_rng_below(r, max_side - 1);
    g->chart.ny = 2 + tf_rng_below(r, max_side - 1);
    g->chart.ha = uniform(r, 0.5, 6);
    g->chart.hb = tf_rng_below(r, 2) ? g->chart.ha : uniform(r, 0.5, 6);
    g->s_u = 1 / uniform(r, 0.5, 5);
    static const double mus[4] = {0, 0.3, 1, 0.1};
    g->mu = mus[tf_rng_below(r, 4)];
    g->force_radius = uniform(r, 1, 20);
    random_spd(r, 0.05, 5, g->k0);
    g->variation = uniform(r, 0, 0.3);
    g->bump = tf_rng_below(r, 3) == 0 ? 0 : uniform(r, 0.1, 1.0) * g->chart.ha;
    for (int i = 0; i < 4; ++i) {
        g->phase[i] = uniform(r, 0, 2 * M_PI);
    }
    g->degree = 2 + tf_rng_below(r, TFIT_REGION_MAX_DEGREE - 1);
    g->cubic = uniform(r, 0, 1);
    g->quartic = uniform(r, 0, 1);
    double n = 0;
    for (int i = 0; i < 3; ++i) {
        g->cubic_dir[i] = uniform(r, -1, 1);
        n += g->cubic_dir[i] * g->cubic_dir[i];
    }
    for (int i = 0; i < 3; ++i) {
        g->cubic_dir[i] /= sqrt(n) + 1e-9;
    }
}

void tf_random_region_block(tf_random_region *g, uint32_t n, double h, double kt, double kn,
                            double variation, double bump, uint32_t degree, double mu)
{
    memset(g, 0, sizeof *g);
    g->chart.rot[0] = g->chart.rot[4] = g->chart.rot[8] = 1;
    g->chart.nx = g->chart.ny = n;
    g->chart.ha = g->chart.hb = h;
    g->chart.origin[2] = 6; /* block48's top face */
    g->s_u = 1 / 2.0;
    g->mu = mu;
    g->force_radius = 5;
    g->k0[0] = g->k0[4] = kt;
    g->k0[8] = kn;
    g->variation = variation;
    g->bump = bump;
    g->phase[0] = 0.3;
    g->phase[1] = 1.1;
    g->phase[2] = 2.0;
    g->phase[3] = 0.7;
    g->degree = degree;
    g->cubic = degree >= 3 ? 0.5 : 0;
    g->quartic = degree >= 4 ? 0.5 : 0;
    g->cubic_dir[2] = -1;
}

/* The smooth fields over the grid, |w| <= 1, a period of about 2.5 regions. */
static double field(const tf_random_region *g, double ga, double gb, int which)
{
    const double a = ga / (g->chart.nx + 1.0), b = gb / (g->chart.ny + 1.0);
    return sin(2.5 * a + g->phase[which]) * cos(2.0 * b + g->phase[which + 1]);
}

void tf_random_region_stiffness(const tf_random_region *g, double ga, double gb, double k[9])
{
    const double s = 1 + g->variation * field(g, ga, gb, 2);
    for (int i = 0; i < 9; ++i) {
        k[i] = g->k0[i] * s;
    }
}

/* Eigenvalues of a symmetric 3x3 (the trigonometric method), ascending. */
static void eigen_sym(const double a[9], double ev[3])
{
    const double p1 = a[1] * a[1] + a[2] * a[2] + a[5] * a[5];
    const double q = (a[0] + a[4] + a[8]) / 3;
    const double p2 = (a[0] - q) * (a[0] - q) + (a[4] - q) * (a[4] - q) + (a[8] - q) * (a[8] - q) +
                      2 * p1;
    const double p = sqrt(p2 / 6);
    if (p == 0) {
        ev[0] = ev[1] = ev[2] = q;
        return;
    }
    double b[9];
    for (int i = 0; i < 9; ++i) {
        b[i] = (a[i] - (i % 4 == 0 ? q : 0)) / p;
    }
    const double det = b[0] * (b[4] * b[8] - b[5] * b[7]) - b[1] * (b[3] * b[8] - b[5] * b[6]) +
                       b[2] * (b[3] * b[7] - b[4] * b[6]);
    const double rr = fmax(-1, fmin(1, det / 2));
    const double phi = acos(rr) / 3;
    ev[2] = q + 2 * p * cos(phi);
    ev[0] = q + 2 * p * cos(phi + 2 * M_PI / 3);
    ev[1] = 3 * q - ev[0] - ev[2];
}

double tf_random_region_max_stiffness(const tf_random_region *g)
{
    double kmax = 0;
    for (int j = -1; j <= (int)g->chart.ny; ++j) {
        for (int i = -1; i <= (int)g->chart.nx; ++i) {
            double k[9], ev[3];
            tf_random_region_stiffness(g, i, j, k);
            eigen_sym(k, ev);
            kmax = fmax(kmax, ev[2]);
        }
    }
    return kmax;
}

/* The potential's coefficients at one control point, graded order of
 * degrees 2 .. P (v_a exponent decreasing, then v_b):
 * E(v) = 1/2 v^T (K / s_u^2) v + c3 (d.v)^3 + c4 (v.v)^2, c3 and c4 small
 * enough that E stays convex on the unit ball. */
static void potential(const tf_random_region *g, const double k[9], double *e)
{
    const double s2 = g->s_u * g->s_u;
    double ev[3];
    eigen_sym(k, ev);
    const double lmin = ev[0] / s2; /* the quadratic part's Hessian >= lmin I */
    const double c3 = g->cubic * lmin / 12; /* |Hess| of c3 (d.v)^3 <= 6 c3 <= lmin / 2 */
    const double c4 = g->quartic * lmin / 4;
    int t = 0;
    for (int deg = 2; deg <= (int)g->degree; ++deg) {
        for (int i = deg; i >= 0; --i) {
            for (int j = deg - i; j >= 0; --j, ++t) {
                const int kk = deg - i - j;
                double c = 0;
                if (deg == 2) { /* 1/2 sum K_ab v_a v_b */
                    const int a = i == 2 ? 0 : j == 2 ? 1 : kk == 2 ? 2 : -1;
                    if (a >= 0) {
                        c = k[4 * a] / (2 * s2);
                    } else {
                        const int x = i == 0 ? 1 : 0, y = kk == 0 ? 1 : 2;
                        c = k[3 * x + y] / s2;
                    }
                } else if (deg == 3) { /* 3!/(i! j! k!) d^(i,j,k) */
                    static const double f[4] = {1, 1, 2, 6};
                    c = c3 * 6 / (f[i] * f[j] * f[kk]) * pow(g->cubic_dir[0], i) *
                        pow(g->cubic_dir[1], j) * pow(g->cubic_dir[2], kk);
                } else if (i % 2 == 0 && j % 2 == 0 && kk % 2 == 0) { /* (v.v)^2 */
                    c = c4 * ((i == 4 || j == 4 || kk == 4) ? 1 : 2);
                }
                e[t] = c;
            }
        }
    }
}

tf_model *tf_random_region_law(tf_ctx *ctx, const tf_random_region *g, const char *name)
{
    const uint32_t nx = g->chart.nx, ny = g->chart.ny;
    const uint32_t S = tf_region_law_terms(g->degree) + 1;
    double *ctrl = calloc((size_t)(nx + 2) * (ny + 2) * S, sizeof *ctrl);
    if (ctrl == NULL) {
        tf_fail(ctx, "out of memory");
        return NULL;
    }
    for (uint32_t j = 0; j < ny + 2; ++j) {
        for (uint32_t i = 0; i < nx + 2; ++i) {
            const double ga = (double)i - 1, gb = (double)j - 1;
            double *c = ctrl + ((size_t)j * (nx + 2) + i) * S;
            double k[9];
            c[0] = g->bump * field(g, ga, gb, 0);
            tf_random_region_stiffness(g, ga, gb, k);
            potential(g, k, c + 1);
        }
    }
    tf_model *m = tf_region_law_new(ctx, name, &g->chart, g->degree, g->s_u, g->mu, ctrl, 0);
    free(ctrl);
    return m;
}

tf_model *tf_random_region_surface(tf_ctx *ctx, tf_rng *r, const tf_random_region *g,
                                   const char *name, uint32_t rank, uint32_t degree,
                                   int site_modes, uint32_t n_out)
{
    const uint32_t nx = g->chart.nx, ny = g->chart.ny;
    const uint32_t n_t = tf_region_surface_terms(degree);
    const uint32_t S = rank * n_t + (site_modes ? 3 * rank : 0);
    const size_t points = (size_t)(nx + 2) * (ny + 2);
    double *ctrl = calloc(points * S, sizeof *ctrl);
    double *modes = calloc(3 * (size_t)n_out * rank, sizeof *modes);
    double *coefs = calloc(2 * (size_t)S, sizeof *coefs);
    uint32_t *ids = calloc(n_out, sizeof *ids), *nidx = NULL;
    double *nD = NULL;
    tf_model *m = NULL;
    if (ctrl == NULL || modes == NULL || coefs == NULL || ids == NULL) {
        tf_fail(ctx, "out of memory");
        goto done;
    }
    /* each table entry: a + b w(g), a smooth field with its own phase */
    for (uint32_t s = 0; s < S; ++s) {
        const double scale = s < rank * n_t ? pow(0.7, s / n_t) : 0.05 * pow(0.7, s % rank);
        coefs[2 * s] = uniform(r, -1, 1) * scale;
        coefs[2 * s + 1] = uniform(r, -0.3, 0.3) * scale;
    }
    for (size_t p = 0; p < points; ++p) {
        const double ga = (double)(p % (nx + 2)) - 1, gb = (double)(p / (nx + 2)) - 1;
        for (uint32_t s = 0; s < S; ++s) {
            const double w = sin(0.7 * ga + s) * cos(0.5 * gb + 2.0 * s);
            ctrl[p * S + s] = coefs[2 * s] + coefs[2 * s + 1] * w;
        }
    }
    for (size_t i = 0; i < 3 * (size_t)n_out * rank; ++i) {
        modes[i] = uniform(r, -1, 1) * pow(2.0, (double)tf_rng_below(r, 6) - 3);
    }
    for (uint32_t i = 0; i < n_out; ++i) {
        ids[i] = 100 + 7 * i;
    }
    tf_region_near_table near = {degree == 1 ? g->near : 0, NULL, NULL};
    nidx = calloc(points * near.n + 1, sizeof *nidx);
    nD = calloc(9 * points * near.n + 1, sizeof *nD);
    if (nidx == NULL || nD == NULL) {
        tf_fail(ctx, "out of memory");
        goto done;
    }
    for (size_t e = 0; e < points * near.n; ++e) { /* a tenth of the modes' scale */
        nidx[e] = tf_rng_below(r, n_out);
        for (int i = 0; i < 9; ++i) {
            nD[9 * e + (size_t)i] = 0.1 * uniform(r, -1, 1);
        }
    }
    near.idx = nidx;
    near.D = nD;
    m = tf_region_surface_new(ctx, name, &g->chart, g->s_u, g->mu, g->force_radius, rank, degree,
                              site_modes, ctrl, &near, modes, n_out, ids);
done:
    free(nidx);
    free(nD);
    free(ctrl);
    free(modes);
    free(coefs);
    free(ids);
    return m;
}
