/*
 * region_model.c — region models on the host (see region_model.h): layout,
 * builder, checks, golden design.
 */
#include "model/region_model.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/rng.h"
#include "model/golden.h"
#include "model/ref_eval.h"
#include "model/region_ref.h"
#include "numerics/grid_spline.h"

/* One bit of margin under the device's limits (tfit_region_check.c): the
 * device bounds in float, the host in double. */
#define BOUND_LIMIT 0x1p99
/* Floats per control point of a law, at most: h and T(4) - 4 terms. */
#define MAX_LAW_STRIDE 32

/* A zeroed model of the shape; NULL with the message in ctx. */
static tf_model *alloc_model(tf_ctx *ctx, const char *name, tfit_family family, uint32_t n_out,
                             const uint32_t *dims, uint32_t n_dims)
{
    tf_model *m = tf_model_new(ctx, name, family, n_out, dims, n_dims);
    if (m != NULL) {
        m->envelope_radius = 0.0; /* set_ball's: the law has no ball, the surface its R_F */
    }
    return m;
}

/* The chart and the scalars both models share. */
static void put_chart(float *coef, const tf_region_grid *c, double s_u, double mu)
{
    for (int i = 0; i < 3; ++i) {
        coef[i] = (float)c->origin[i];
    }
    for (int i = 0; i < 9; ++i) {
        coef[3 + i] = (float)c->rot[i];
    }
    float *sc = coef + TF_REGION_CHART;
    sc[TF_REGION_INV_HA] = (float)(1.0 / c->ha);
    sc[TF_REGION_INV_HB] = (float)(1.0 / c->hb);
    sc[TF_REGION_HA] = (float)c->ha;
    sc[TF_REGION_HB] = (float)c->hb;
    sc[TF_REGION_SU] = (float)s_u;
    sc[TF_REGION_U_SCALE] = (float)(1.0 / s_u);
    sc[TF_REGION_MU] = (float)mu;
}

tf_model *tf_region_law_new(tf_ctx *ctx, const char *name, const tf_region_grid *chart,
                            uint32_t degree, double s_u, double mu, const double *ctrl,
                            uint32_t region)
{
    const uint32_t dims[3] = {chart->nx, chart->ny, degree};
    tf_model *m = alloc_model(ctx, name, TFIT_FAMILY_REGION, 1, dims, 3);
    if (m == NULL) {
        return NULL;
    }
    put_chart(m->coef, chart, s_u, mu);
    const size_t n = (size_t)tf_region_control_points(dims) * tf_region_law_stride(dims);
    for (size_t i = 0; i < n; ++i) {
        m->coef[TF_REGION_LAW_CTRL + i] = (float)ctrl[i];
    }
    m->node_ids[0] = region;
    if (tf_region_law_validate(ctx, m) != 0) {
        tf_model_free(m);
        return NULL;
    }
    return m;
}

tf_model *tf_region_surface_new(tf_ctx *ctx, const char *name, const tf_region_grid *chart,
                                double s_u, double mu, double force_radius, uint32_t rank,
                                uint32_t degree, int site_modes, const double *ctrl,
                                const tf_region_near_table *near, const double *modes,
                                uint32_t n_out, const uint32_t *node_ids)
{
    const uint32_t n_near = near ? near->n : 0;
    const uint32_t dims[TFIT_REGION_SURFACE_DIMS] = {chart->nx,  chart->ny, rank, degree,
                                                     site_modes ? 1u : 0u, n_near};
    tf_model *m = alloc_model(ctx, name, TFIT_FAMILY_REGION_SURFACE, n_out, dims,
                              TFIT_REGION_SURFACE_DIMS);
    if (m == NULL) {
        return NULL;
    }
    put_chart(m->coef, chart, s_u, mu);
    m->coef[TF_REGION_CHART + TF_REGION_INV_RF] = (float)(1.0 / force_radius);
    float *map = m->coef + TF_REGION_FORCE_MAP; /* x0 = 0, W = R / R_F */
    for (int i = 0; i < 9; ++i) {
        map[3 + i] = (float)(chart->rot[i] / force_radius);
    }
    const size_t n = (size_t)tf_region_control_points(dims) * tf_region_surface_stride(dims);
    for (size_t i = 0; i < n; ++i) {
        m->coef[TF_REGION_SURFACE_CTRL + i] = (float)ctrl[i];
    }
    float *nf = m->coef + TF_REGION_SURFACE_CTRL + n;
    for (size_t e = 0; e < (size_t)tf_region_control_points(dims) * n_near; ++e) {
        nf[TF_REGION_NEAR_FLOATS * e] = (float)near->idx[e];
        for (size_t i = 0; i < 9; ++i) {
            nf[TF_REGION_NEAR_FLOATS * e + 1 + i] = (float)near->D[9 * e + i];
        }
    }
    nf += (size_t)tf_region_control_points(dims) * n_near * TF_REGION_NEAR_FLOATS;
    for (size_t i = 0; i < 3 * (size_t)n_out * rank; ++i) {
        nf[i] = (float)modes[i];
    }
    memcpy(m->node_ids, node_ids, n_out * sizeof *node_ids);
    m->envelope_radius = force_radius;
    if (tf_region_surface_validate(ctx, m) != 0) {
        tf_model_free(m);
        return NULL;
    }
    return m;
}

/* --- checks ------------------------------------------------------------------ */
static int chart_check(tf_ctx *ctx, const tf_model *m)
{
    const float *c = m->coef, *sc = m->coef + TF_REGION_CHART;
    static const char *const names[] = {"1/ha", "1/hb", "ha", "hb", "s_u", "1/s_u", "mu"};
    for (int i = 0; i < 3; ++i) {
        if (!(fabs((double)c[i]) <= 0x1p19)) {
            return tf_fail(ctx, "region model '%s': chart origin %d is %g (beyond 2^19 mm)",
                           m->name, i, (double)c[i]);
        }
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double d = 0;
            for (int k = 0; k < 3; ++k) {
                d += (double)c[3 + 3 * i + k] * (double)c[3 + 3 * j + k];
            }
            if (!(fabs(d - (i == j)) <= 1e-6)) {
                return tf_fail(ctx, "region model '%s': the chart's rows %d and %d are not "
                                    "orthonormal (dot %.9g)", m->name, i, j, d);
            }
        }
    }
    for (int i = 0; i < 6; ++i) {
        if (!(sc[i] >= 0x1p-19f && sc[i] <= 0x1p19f)) {
            return tf_fail(ctx, "region model '%s': %s is %g, outside [2^-19, 2^19]", m->name,
                           names[i], (double)sc[i]);
        }
    }
    if (!(sc[TF_REGION_MU] >= 0.0f && sc[TF_REGION_MU] <= 0x1p9f)) {
        return tf_fail(ctx, "region model '%s': friction %g outside [0, 2^9]", m->name,
                       (double)sc[TF_REGION_MU]);
    }
    if (!(fabs((double)sc[0] * sc[2] - 1) <= 1e-6 && fabs((double)sc[1] * sc[3] - 1) <= 1e-6 &&
          fabs((double)sc[4] * sc[5] - 1) <= 1e-6)) {
        return tf_fail(ctx, "region model '%s': 1/ha, 1/hb or 1/s_u is not the reciprocal of "
                            "its partner", m->name);
    }
    return 0;
}

static double max_abs(const float *c, size_t points, size_t stride)
{
    double b = 0;
    for (size_t j = 0; j < points; ++j) {
        b = fmax(b, fabs((double)c[j * stride]));
    }
    return b;
}

/* Cholesky of a symmetric 3x3: 0 when positive definite. */
static int not_spd(const double a[9])
{
    const double l00 = a[0];
    if (!(l00 > 0)) {
        return 1;
    }
    const double l10 = a[3] / sqrt(l00), l20 = a[6] / sqrt(l00);
    const double l11 = a[4] - l10 * l10;
    if (!(l11 > 0)) {
        return 1;
    }
    const double l21 = (a[7] - l20 * l10) / sqrt(l11);
    return !(a[8] - l20 * l20 - l21 * l21 > 0);
}

/* v^n, 0 for n < 0 (a derivative of a lower power). */
static double power(double v, int n)
{
    return n < 0 ? 0.0 : pow(v, n);
}

/* The Hessian in v of sum_t e_t m_t(v), degrees 2 .. P, graded order. */
static void potential_hessian(uint32_t P, const float *e, const double v[3], double h[9])
{
    memset(h, 0, 9 * sizeof *h);
    int t = 0;
    for (int deg = 2; deg <= (int)P; ++deg) {
        for (int i = deg; i >= 0; --i) {
            for (int j = deg - i; j >= 0; --j, ++t) {
                const int ex[3] = {i, j, deg - i - j};
                for (int a = 0; a < 3; ++a) {
                    for (int b = 0; b < 3; ++b) {
                        int p[3] = {ex[0], ex[1], ex[2]};
                        double c = (double)e[t] * p[a];
                        p[a] -= 1;
                        c *= p[b];
                        p[b] -= 1;
                        h[3 * a + b] += c * power(v[0], p[0]) * power(v[1], p[1]) *
                                        power(v[2], p[2]);
                    }
                }
            }
        }
    }
}

/* Every control point's potential convex: exactly (P = 2, its Hessian
 * SPD), or at 27 points of the unit ball (P > 2: the centre, and 26
 * directions at radius 1/2 and 1). */
static int convexity_check(tf_ctx *ctx, const tf_model *m)
{
    const uint32_t P = m->dims[2], S = tf_region_law_stride(m->dims);
    const size_t points = tf_region_control_points(m->dims);
    for (size_t j = 0; j < points; ++j) {
        const float *e = m->coef + TF_REGION_LAW_CTRL + j * S + 1;
        for (int s = 0; s < (P == 2 ? 1 : 53); ++s) {
            double v[3] = {0, 0, 0};
            if (s > 0) {
                const int d = (s - 1) % 26, k = d < 13 ? d : d + 1; /* skip the centre */
                const double rad = s <= 26 ? 0.5 : 1.0;
                v[0] = k % 3 - 1;
                v[1] = (k / 3) % 3 - 1;
                v[2] = k / 9 - 1;
                const double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                for (int i = 0; i < 3; ++i) {
                    v[i] *= rad / n;
                }
            }
            double h[9];
            potential_hessian(P, e, v, h);
            if (not_spd(h)) {
                return tf_fail(ctx,
                               "region model '%s': control point %zu's potential is not convex "
                               "at v = (%g, %g, %g): the law would not be passive",
                               m->name, j, v[0], v[1], v[2]);
            }
        }
    }
    return 0;
}

static int law_check(tf_ctx *ctx, const tf_model *m)
{
    const size_t points = tf_region_control_points(m->dims);
    const uint32_t S = tf_region_law_stride(m->dims), P = m->dims[2];
    const float *sc = m->coef + TF_REGION_CHART, *ctrl = m->coef + TF_REGION_LAW_CTRL;
    const double bh = 2 * max_abs(ctrl, points, S);
    double be = 0;
    for (uint32_t t = 1; t < S; ++t) {
        be += max_abs(ctrl + t, points, S);
    }
    be *= 2;
    const double su = sc[TF_REGION_SU];
    const double jb = fmax(fmax(sc[TF_REGION_HA], sc[TF_REGION_HB]), bh);
    const double fb = su * P * be, kb = 2 * su * su * be, hb = 9 * jb * jb * kb;
    const double gb = be + 2 * jb * fb;
    const struct {
        double v, limit;
        const char *what;
    } b[] = {{bh, 0x1p29, "2 max |h| (mm)"},
             {be, 0x1p59, "2 sum_t max |e_t|"},
             {fb, 0x1p59, "the force bound s_u P Be"},
             {hb, 0x1p49, "the proxy Hessian bound"},
             {gb, BOUND_LIMIT, "the proxy gradient bound"},
             {hb * gb, 0x1p58, "the proxy step's numerator bound"}};
    for (size_t i = 0; i < sizeof b / sizeof b[0]; ++i) {
        if (!(b[i].v <= b[i].limit)) {
            return tf_fail(ctx, "region model '%s': %s is %g, beyond %g (ill-scaled tables)",
                           m->name, b[i].what, b[i].v, b[i].limit);
        }
    }
    return convexity_check(ctx, m);
}

/* The near field's entries: j an integer output point, |D| <= 2^80
 * (tfit_region_check.c's bound). */
static int near_check(tf_ctx *ctx, const tf_model *m)
{
    const size_t count = (size_t)tf_region_control_points(m->dims) * m->dims[5];
    const float *e = m->coef + tf_region_surface_near_at(m->dims);
    for (size_t k = 0; k < count; ++k, e += TF_REGION_NEAR_FLOATS) {
        if (!(e[0] >= 0 && e[0] < (float)m->n_out && e[0] == floorf(e[0]))) {
            return tf_fail(ctx, "region model '%s': near-field entry %zu names output point %g "
                                "of %u", m->name, k, (double)e[0], m->n_out);
        }
        for (size_t i = 1; i < TF_REGION_NEAR_FLOATS; ++i) {
            if (!(fabs((double)e[i]) <= 0x1p80)) {
                return tf_fail(ctx, "region model '%s': near-field entry %zu holds %g, beyond "
                                    "2^80", m->name, k, (double)e[i]);
            }
        }
    }
    return 0;
}

static int surface_check(tf_ctx *ctx, const tf_model *m)
{
    const size_t points = tf_region_control_points(m->dims);
    const uint32_t r = m->dims[2], n_t = tf_region_surface_terms(m->dims[3]);
    const uint32_t S = tf_region_surface_stride(m->dims);
    const float *ctrl = m->coef + TF_REGION_SURFACE_CTRL, *map = m->coef + TF_REGION_FORCE_MAP;
    const float *phi = m->coef + (m->n_coef - 3 * r * m->n_out);
    const double inv_rf = m->coef[TF_REGION_CHART + TF_REGION_INV_RF];
    if (!(inv_rf >= 0x1p-39 && inv_rf <= 0x1p39)) {
        return tf_fail(ctx, "region model '%s': 1/R_F is %g, outside [2^-39, 2^39]", m->name,
                       inv_rf);
    }
    for (int i = 0; i < TFIT_INPUT_MAP_FLOATS; ++i) {
        if (!(fabs((double)map[i]) <= (i < 3 ? 0x1p63 : 0x1p55))) {
            return tf_fail(ctx, "region model '%s': force map entry %d is %g", m->name, i,
                           (double)map[i]);
        }
    }
    double ba[TFIT_REGION_MAX_RANK];
    for (uint32_t k = 0; k < r; ++k) {
        ba[k] = 0;
        for (uint32_t t = 0; t < n_t; ++t) {
            ba[k] += max_abs(ctrl + k * n_t + t, points, S);
        }
        ba[k] *= 2;
        if (!(ba[k] <= BOUND_LIMIT)) {
            return tf_fail(ctx, "region model '%s': mode %u's amplitude can reach %g", m->name,
                           k, ba[k]);
        }
    }
    for (uint32_t i = r * n_t; i < S; ++i) {
        if (!(max_abs(ctrl + i, points, S) <= BOUND_LIMIT)) {
            return tf_fail(ctx, "region model '%s': site mode entry %u beyond 2^99", m->name,
                           i - r * n_t);
        }
    }
    for (size_t o = 0; o < 3 * (size_t)m->n_out; ++o) {
        double b = 0;
        for (uint32_t k = 0; k < r; ++k) {
            b += fabs((double)phi[o * r + k]) * ba[k];
        }
        if (!(b <= BOUND_LIMIT)) {
            return tf_fail(ctx, "region model '%s': output %zu can reach %g, beyond 2^99",
                           m->name, o, b);
        }
    }
    return near_check(ctx, m);
}

/* What both forms check first: the size, finite coefficients, the chart. */
static int common_check(tf_ctx *ctx, const tf_model *m, uint32_t want)
{
    if (want != m->n_coef || m->n_coef == 0) {
        return tf_fail(ctx, "region model '%s': table size %u does not match its family and "
                            "dims", m->name, m->n_coef);
    }
    for (uint32_t i = 0; i < m->n_coef; ++i) {
        if (!isfinite(m->coef[i])) {
            return tf_fail(ctx, "region model '%s': coefficient %u is not finite", m->name, i);
        }
    }
    return chart_check(ctx, m);
}

int tf_region_law_validate(tf_ctx *ctx, const tf_model *m)
{
    if (m->n_dims != TFIT_REGION_DIMS) {
        return tf_fail(ctx, "region law '%s': %u dims", m->name, m->n_dims);
    }
    if (common_check(ctx, m, tf_region_law_ncoef(m->n_out, m->dims)) != 0) {
        return -1;
    }
    return law_check(ctx, m);
}

int tf_region_surface_validate(tf_ctx *ctx, const tf_model *m)
{
    if (m->n_dims != TFIT_REGION_SURFACE_DIMS) {
        return tf_fail(ctx, "region surface '%s': %u dims", m->name, m->n_dims);
    }
    if (common_check(ctx, m, tf_region_surface_ncoef(m->n_out, m->dims)) != 0) {
        return -1;
    }
    return surface_check(ctx, m);
}

int tf_region_agree(tf_ctx *ctx, const tf_model *law, const tf_model *surf)
{
    if (law->family != TFIT_FAMILY_REGION || surf->family != TFIT_FAMILY_REGION_SURFACE) {
        return tf_fail(ctx, "region models '%s' and '%s': not a law and a surface", law->name,
                       surf->name);
    }
    if (law->dims[0] != surf->dims[0] || law->dims[1] != surf->dims[1] ||
        memcmp(law->coef, surf->coef, TF_REGION_LAW_CTRL * sizeof *law->coef) != 0) {
        return tf_fail(ctx, "region models '%s' and '%s' disagree on the grid, chart or scalars",
                       law->name, surf->name);
    }
    return 0;
}

/* --- double-precision rest surface (design of inputs, property tests) ------- */
void tf_region_rest_point(const tf_model *law, const double g[2], double x[3], double *e)
{
    const uint32_t S = tf_region_law_stride(law->dims);
    const float *sc = law->coef + TF_REGION_CHART, *ctrl = law->coef + TF_REGION_LAW_CTRL;
    double q[MAX_LAW_STRIDE], t[2];
    unsigned cell[2];
    for (int a = 0; a < 2; ++a) { /* g clamped onto the grid, as the blend clamps it */
        tf_bspline_cell(g[a], law->dims[a], &cell[a], &t[a]);
    }
    tf_spline_eval_float(law->dims[0], law->dims[1], S, ctrl, g[0], g[1], q, NULL, NULL);
    x[0] = (cell[0] + t[0]) * sc[TF_REGION_HA];
    x[1] = (cell[1] + t[1]) * sc[TF_REGION_HB];
    x[2] = q[0];
    if (e != NULL) {
        memcpy(e, q + 1, (S - 1) * sizeof *e);
    }
}

/* --- golden design and self-test (§7, §8) ------------------------------------- */
typedef struct design {
    const tf_model *m;
    float (*in)[3];
    size_t n;
    double scale; /* the displacement scale 1/s_u, mm */
} design;

static void put(design *d, float x, float y, float z)
{
    if (d->n < TF_GOLDEN_MAX) {
        d->in[d->n][0] = x;
        d->in[d->n][1] = y;
        d->in[d->n][2] = z;
        d->n++;
    }
}

/* The tip at grid coordinates g, `depth` (in displacement scales) below the
 * rest surface along the chart normal, in the scene frame. */
static void put_site(design *d, double ga, double gb, double depth)
{
    const float *o = d->m->coef, *rot = d->m->coef + 3;
    double x[3];
    const double g[2] = {ga, gb};
    tf_region_rest_point(d->m, g, x, NULL);
    x[0] = ga * d->m->coef[TF_REGION_CHART + TF_REGION_HA]; /* beyond the edge too */
    x[1] = gb * d->m->coef[TF_REGION_CHART + TF_REGION_HB];
    x[2] -= depth * d->scale;
    double p[3];
    for (int j = 0; j < 3; ++j) {
        p[j] = o[j] + rot[j] * x[0] + rot[3 + j] * x[1] + rot[6 + j] * x[2];
    }
    put(d, (float)p[0], (float)p[1], (float)p[2]);
}

static float nan_bits(uint32_t b)
{
    float f;
    memcpy(&f, &b, sizeof f);
    return f;
}

size_t tf_region_law_golden_design(const tf_model *m, uint64_t seed, float in[][3])
{
    design d = {.m = m, .in = in, .n = 0,
                .scale = 1.0 / m->coef[TF_REGION_CHART + TF_REGION_SU]};
    tf_rng r = {seed};
    const double ga = m->dims[0] - 1.0, gb = m->dims[1] - 1.0;
    double g[2] = {tf_rng_range(&r, 0.2, 0.8) * ga, tf_rng_range(&r, 0.2, 0.8) * gb};
    double dir = tf_rng_range(&r, 0, 2 * M_PI);
    put_site(&d, g[0], g[1], -0.5); /* 0: above the surface */
    for (int k = 1; k <= 6; ++k) {  /* 1-6: a press */
        put_site(&d, g[0], g[1], 0.1 * k);
    }
    for (int k = 0; k < 12; ++k) { /* 7-18: a slide, a quarter cell a tick */
        g[0] += 0.25 * cos(dir);
        g[1] += 0.25 * sin(dir);
        put_site(&d, g[0], g[1], 0.6);
    }
    put(&d, NAN, 0.0f, 0.0f);      /* 19-20: skipped ticks */
    put(&d, 1.0f, INFINITY, 0.0f);
    for (int k = 1; k <= 6; ++k) { /* 21-26: deeper, beyond the envelope */
        g[0] += 0.25 * cos(dir);
        g[1] += 0.25 * sin(dir);
        put_site(&d, g[0], g[1], 0.6 + 0.2 * k);
    }
    const double edge_a = cos(dir) >= 0 ? ga + 1.5 : -1.5; /* 27-32: off the region's edge */
    for (int k = 1; k <= 6; ++k) {
        put_site(&d, g[0] + (edge_a - g[0]) * k / 6.0, g[1], 0.5);
    }
    static const double lift[4] = {0.3, 0.1, -0.05, -0.5}; /* 33-36: lifting off */
    for (int k = 0; k < 4; ++k) {
        put_site(&d, g[0], g[1], lift[k]);
    }
    put(&d, 1e30f, -2e30f, 5e29f); /* 37-42: far, huge, subnormal and zero tips */
    put(&d, FLT_MAX, -FLT_MAX, FLT_MAX / 3);
    put(&d, -FLT_MAX, 0.0f, 0.0f);
    put(&d, 1e38f, 1e-38f, -1e38f);
    put(&d, 1e-40f, -1e-42f, nan_bits(1u));
    put(&d, -0.0f, -0.0f, -0.0f);
    g[0] = tf_rng_range(&r, 0, 1) * ga; /* 43-48: a press elsewhere */
    g[1] = tf_rng_range(&r, 0, 1) * gb;
    for (int k = 1; k <= 6; ++k) {
        put_site(&d, g[0], g[1], 0.1 * k + 0.1);
    }
    const double c[2] = {tf_rng_range(&r, 0.2, 0.8) * ga, tf_rng_range(&r, 0.2, 0.8) * gb};
    put_site(&d, c[0] + 1, c[1], 0.5); /* 49: a jump while in contact (the proxy lags) */
    for (int k = 1; k <= 12; ++k) {    /* 50-61: a circle of radius one cell */
        const double a = 2 * M_PI * k / 12.0;
        put_site(&d, c[0] + cos(a), c[1] + sin(a), 0.5);
    }
    put(&d, -NAN, 0.0f, 1.0f); /* 62-65: NaN kinds, -Inf */
    put(&d, 0.25f, 0.5f, nan_bits(0x7f800001u));
    put(&d, nan_bits(0x7fc12345u), 0.0f, 0.0f);
    put(&d, 0.0f, -INFINITY, 2.0f);
    for (int k = 0; k < 10; ++k) { /* 66-75: random tips about the region */
        put_site(&d, tf_rng_range(&r, -0.5, ga + 0.5), tf_rng_range(&r, -0.5, gb + 0.5),
                 tf_rng_range(&r, -0.5, 1.5));
    }
    for (int k = 1; k <= 4; ++k) { /* 76-79: away */
        put_site(&d, c[0], c[1], -0.5 * k);
    }
    return d.n;
}

size_t tf_region_surface_golden_design(const tf_model *m, uint64_t seed, float in[][3])
{
    tf_model map = *m; /* the forces: golden.c's design over the force map */
    map.coef = m->coef + TF_REGION_FORCE_MAP;
    return tf_golden_inputs(&map, seed, in);
}
