/*
 * properties.c — what the region law must do as a contact, measured on the
 * target library (tfit_region_force, tfit_region_surface, tfit_region_pair)
 * with synthetic regions: a block-like one (block48's top face inside
 * [4.8, 43.2]^2: a flat z+ chart, 17 x 17 sites 2.4 mm apart, K(g) of
 * 0.5 / 0.5 / 1.2 N/mm varying smoothly by +-30 %, P = 2) and a curved one
 * (the same with a height field of 3 mm amplitude), both with a
 * displacement scale 1/s_u of 5 mm (the law's envelope |u| <= 5 mm covers
 * every path below: beyond it the force is the envelope's, and not a
 * gradient field: docs/header-format.md §5.10).
 * Prints the measured margins; exits 1 when one is beyond its bound:
 *
 *  (a) continuity: over 10^4 random paths sampled every 0.01 mm (a press
 *      from 0.05 mm above the surface to a random depth, a slide of 1 mm
 *      along two random directions, a lift to 0.05 mm above), no step
 *      changes the force by more than 1.5 k_max |step| (k_max the largest
 *      eigenvalue of K over the region), with and without friction;
 *  (b) frictionless closed paths (random loops of two Fourier harmonics in
 *      the chart's three coordinates: sliding while pressing and releasing
 *      by up to +-0.8 mm, sampled every 0.01 mm): the work the
 *      model returns exceeds the work put in by at most 0.1 % of the work
 *      put in.  Work by the trapezoid rule on the samples:
 *      dW = (F_k + F_k+1) / 2 . (p_k+1 - p_k), F the force on the tissue;
 *      put in = sum of the positive dW, returned = minus the sum of the
 *      negative ones;
 *  (c) with friction (mu = 0.3 and 1) the same loops return at most what
 *      was put in (to 10^-5 of it: a loop the proxy sticks through is
 *      elastic, returned = put in up to the rounding of the float forces);
 *  (d) no NaN or Inf in any output or state word: random regions of every
 *      degree, random tips (any bit pattern, NaN, Inf, huge, subnormal,
 *      near the surface), random states (any bit pattern: NaN and Inf
 *      proxies included), the surface and the two-instrument forms too;
 *  (e) a stuck contact reproduces the site law: with the proxy at g (in
 *      contact, mu = 10 so that nothing slips) and the tip at x(g) + u,
 *      the force is the gradient of the law's potential at g, computed in
 *      double from the same tables: the largest relative difference (float
 *      resolution of the tip: about 4e-6 mm at 45 mm, against |u| >= 0.2 mm).
 *
 *   properties [PATHS]     (default 10000 sliding paths, 1000 loops)
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/region_model.h"
#include "model/target_view.h"
#include "random_region.h"

#define STEP 0.01 /* mm */
#ifndef SCALE
#define SCALE 5.0 /* the law's displacement scale 1/s_u, mm */
#endif

typedef struct region {
    tf_random_region g;
    tf_model *law;
    tfit_model t;
    double kmax;
    double extent[2];
} region;

static tf_ctx ctx;

static int make(region *r, double bump, double mu, double scale)
{
    tf_random_region_block(&r->g, 17, 2.4, 0.5, 1.2, 0.3, bump, 2, mu);
    r->g.chart.origin[0] = r->g.chart.origin[1] = 4.8; /* block48's [4.8, 43.2]^2 */
    r->g.s_u = 1 / scale;
    r->law = tf_random_region_law(&ctx, &r->g, "law");
    if (r->law == NULL) {
        fprintf(stderr, "properties: %s\n", ctx.err);
        return -1;
    }
    tf_target_view(r->law, &r->t);
    if (tfit_model_check(&r->t) != TFIT_OK) {
        fprintf(stderr, "properties: %s\n", ctx.err);
        return -1;
    }
    r->kmax = tf_random_region_max_stiffness(&r->g);
    r->extent[0] = 16 * r->g.chart.ha;
    r->extent[1] = 16 * r->g.chart.hb;
    return 0;
}

/* The rest surface's height at chart (a, b), double. */
static double height(const region *r, double a, double b)
{
    const double g[2] = {a / r->g.chart.ha, b / r->g.chart.hb};
    double x[3];
    tf_region_rest_point(r->law, g, x, NULL);
    return x[2];
}

/* The tip at chart (a, b, c), scene frame (the chart's R is I here). */
static void tip_at(const region *r, const double q[3], float tip[3])
{
    for (int i = 0; i < 3; ++i) {
        tip[i] = (float)(r->g.chart.origin[i] + q[i]);
    }
}

typedef struct walk {
    const region *r;
    float state[3];
    double prev_tip[3], prev_f[3];
    int started;
    double max_ratio;         /* (a) */
    double work_in, work_out; /* (b), (c) */
    long steps;
} walk;

static void walk_reset(walk *w, const region *r)
{
    memset(w, 0, sizeof *w);
    w->r = r;
    tfit_region_reset(&r->t, w->state);
}

/* One tick at chart point q: the force change against k_max |step| and
 * the trapezoid work of the step. */
static void walk_to(walk *w, const double q[3])
{
    float tip[3], f[3];
    tip_at(w->r, q, tip);
    (void)tfit_region_force(&w->r->t, w->state, tip, f);
    if (w->started) {
        double df = 0, dp = 0, dw = 0;
        for (int i = 0; i < 3; ++i) {
            const double step = (double)tip[i] - w->prev_tip[i];
            df += (f[i] - w->prev_f[i]) * (f[i] - w->prev_f[i]);
            dp += step * step;
            dw += 0.5 * (f[i] + w->prev_f[i]) * step;
        }
        if (dp > 0) {
            w->max_ratio = fmax(w->max_ratio, sqrt(df) / (w->r->kmax * sqrt(dp)));
        }
        if (dw > 0) {
            w->work_in += dw;
        } else {
            w->work_out -= dw;
        }
        w->steps++;
    }
    for (int i = 0; i < 3; ++i) {
        w->prev_tip[i] = tip[i];
        w->prev_f[i] = f[i];
    }
    w->started = 1;
}

/* (a): press, slide along two directions, lift, every STEP. */
static void sliding_path(tf_rng *rng, walk *w)
{
    const region *r = w->r;
    double a = tf_rng_range(rng, 0.05, 0.95) * r->extent[0];
    double b = tf_rng_range(rng, 0.05, 0.95) * r->extent[1];
    const double depth = tf_rng_range(rng, 0.1, 1.0);
    const double top = height(r, a, b) + 0.05;
    double q[3] = {a, b, top};
    const int down = (int)lround((0.05 + depth) / STEP);
    for (int k = 0; k <= down; ++k) {
        q[2] = top - k * STEP;
        walk_to(w, q);
    }
    for (int leg = 0; leg < 2; ++leg) {
        const double dir = tf_rng_range(rng, 0, 2 * M_PI);
        for (int k = 0; k < 50; ++k) {
            q[0] += STEP * cos(dir);
            q[1] += STEP * sin(dir);
            walk_to(w, q);
        }
    }
    const double up = height(r, q[0], q[1]) + 0.05;
    while (q[2] < up) {
        q[2] += STEP;
        walk_to(w, q);
    }
}

/* (b), (c): a press to depth d, then one closed loop of two harmonics in
 * the chart's three coordinates (sliding while pressing and releasing by
 * up to +-0.8 mm), sampled so that no step exceeds STEP; the work is that
 * of the loop alone; *length its length in mm. */
static void closed_path(tf_rng *rng, walk *w, double *in, double *out, double *length)
{
    const region *r = w->r;
    const double a0 = tf_rng_range(rng, 0.2, 0.8) * r->extent[0];
    const double b0 = tf_rng_range(rng, 0.2, 0.8) * r->extent[1];
    const double depth = tf_rng_range(rng, 1.6, 2.0);
    const double half[3] = {1.5, 1.5, 0.3}; /* harmonic amplitudes, mm */
    double c1[3], c2[3], s1[3], s2[3];
    for (int i = 0; i < 3; ++i) {
        c1[i] = tf_rng_range(rng, -half[i], half[i]);
        s1[i] = tf_rng_range(rng, -half[i], half[i]);
        c2[i] = tf_rng_range(rng, -half[i] / 3, half[i] / 3);
        s2[i] = tf_rng_range(rng, -half[i] / 3, half[i] / 3);
    }
    const double top = height(r, a0, b0) + 0.05;
    double q[3] = {a0, b0, top};
    for (int k = 0; q[2] > top - 0.05 - depth; ++k) {
        q[2] = top - k * STEP;
        walk_to(w, q);
    }
    const double start[3] = {q[0], q[1], q[2]};
    /* the loop's length bounds its samples: 2 pi sum (|c1| + |s1| + 2 |c2| + 2 |s2|) */
    double len = 0;
    for (int i = 0; i < 3; ++i) {
        len += fabs(c1[i]) + fabs(s1[i]) + 2 * fabs(c2[i]) + 2 * fabs(s2[i]);
    }
    const int n = (int)ceil(2 * M_PI * len / STEP) + 1;
    w->work_in = w->work_out = 0;
    for (int k = 1; k <= n; ++k) {
        const double t = 2 * M_PI * k / n;
        for (int i = 0; i < 3; ++i) {
            q[i] = start[i] + c1[i] * (cos(t) - 1) + s1[i] * sin(t) + c2[i] * (cos(2 * t) - 1) +
                   s2[i] * sin(2 * t);
        }
        walk_to(w, q);
    }
    *in = w->work_in;
    *out = w->work_out;
    *length = (double)n * STEP; /* at most */
}

static int failures;

static void verdict(const char *what, double value, double bound, int below)
{
    const int ok = below ? value <= bound : value >= bound;
    printf("  %-66s %12.4g  (bound %s %g)%s\n", what, value, below ? "<=" : ">=", bound,
           ok ? "" : "  FAIL");
    failures += !ok;
}

/* (a), (b), (c) on one region shape at one friction. */
static void contact_properties(const char *name, double bump, double mu, double scale,
                               int paths, int loops)
{
    region r;
    if (make(&r, bump, mu, scale) != 0) {
        failures++;
        return;
    }
    tf_rng rng = {0x5eedu + (uint64_t)(bump * 10) + (uint64_t)(mu * 100)};
    walk w;
    double worst = 0;
    long steps = 0;
    for (int i = 0; i < paths; ++i) {
        walk_reset(&w, &r);
        sliding_path(&rng, &w);
        worst = fmax(worst, w.max_ratio);
        steps += w.steps;
    }
    printf("%s, mu = %g (k_max %.3f N/mm, displacement scale %g mm): %d sliding paths, %ld "
           "steps of %g mm\n", name, mu, r.kmax, 1 / r.g.s_u, paths, steps, STEP);
    if (paths > 0) {
        verdict("(a) largest |dF| / (k_max |step|)", worst, 1.5, 1);
    }
    double excess = -INFINITY, per_mm = -INFINITY, total_in = 0, total_out = 0;
    for (int i = 0; i < loops; ++i) {
        double in, out, length;
        walk_reset(&w, &r);
        closed_path(&rng, &w, &in, &out, &length);
        excess = fmax(excess, (out - in) / in);
        per_mm = fmax(per_mm, (out - in) / length);
        total_in += in;
        total_out += out;
    }
    printf("  %d closed loops: work put in %.4g N mm, returned %.4g N mm in all; the largest "
           "excess per mm of loop %.3g N mm/mm\n",
           loops, total_in, total_out, per_mm);
    if (mu == 0) {
        verdict("(b) largest (returned - put in) / put in, frictionless", excess, 1e-3, 1);
    } else { /* a loop the proxy sticks through is elastic: returned = put in, to rounding */
        verdict("(c) largest (returned - put in) / put in, with friction", excess, 1e-5, 1);
    }
    tf_model_free(r.law);
}

static int finite(const float *x, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        if (!isfinite(x[i])) {
            return 0;
        }
    }
    return 1;
}

static float random_word(tf_rng *rng)
{
    const uint32_t kind = tf_rng_below(rng, 8);
    uint32_t w = (uint32_t)tf_rng_next(rng);
    if (kind == 0) {
        w = (w & 0x80000000u) | 0x7f800000u | (tf_rng_below(rng, 2) ? 0x400000u : 0u); /* Inf/NaN */
    } else if (kind < 3) {
        w = (w & 0x807fffffu) | ((uint32_t)(tf_rng_below(rng, 40) + 110) << 23); /* near 1 */
    }
    float f;
    memcpy(&f, &w, sizeof f);
    return f;
}

/* (d): random regions of every degree, random tips, forces and states. */
static void finiteness(int n_regions, int ticks)
{
    tf_rng rng = {0xf1717eu};
    long calls = 0, bad = 0;
    for (int i = 0; i < n_regions; ++i) {
        tf_random_region g;
        tf_random_region_draw(&rng, 12, &g);
        const int affine = i % 2 == 0;
        if (affine) {
            g.degree = 2;
        }
        tf_model *law = tf_random_region_law(&ctx, &g, "law");
        const uint32_t rank = 1 + tf_rng_below(&rng, 12);
        const uint32_t p = affine ? 1 : 1 + tf_rng_below(&rng, 3);
        g.near = tf_rng_below(&rng, TFIT_REGION_MAX_NEAR + 1); /* p = 1: a near field */
        tf_model *surf = law == NULL ? NULL
                                     : tf_random_region_surface(&ctx, &rng, &g, "surface", rank, p,
                                                                affine, 1 + tf_rng_below(&rng, 20));
        tfit_model lt, st;
        if (surf == NULL) {
            fprintf(stderr, "properties: %s\n", ctx.err);
            failures++;
            return;
        }
        tf_target_view(law, &lt);
        tf_target_view(surf, &st);
        float out[3 * 20], state[6], tip[6], f[6];
        tfit_region_reset(&lt, state);
        tfit_region_reset(&lt, state + 3);
        for (int k = 0; k < ticks; ++k) {
            for (int j = 0; j < 6; ++j) {
                const double near = lt.coef[j % 3] + tf_rng_range(&rng, -30, 30);
                tip[j] = tf_rng_below(&rng, 2) ? random_word(&rng) : (float)near;
            }
            if (tf_rng_below(&rng, 8) == 0) { /* a caller's state of any bits */
                for (int j = 0; j < 6; ++j) {
                    state[j] = random_word(&rng);
                }
            }
            const int fresh = finite(state, 6); /* else a NaN tip keeps it */
            tfit_region_force(&lt, state, tip, f);
            tfit_region_surface(&st, state, f, out);
            bad += !finite(f, 3) || !finite(out, 3 * surf->n_out) ||
                   (fresh && !finite(state, 3));
            calls += 2;
            for (int j = 0; j < 3; ++j) {
                f[j] = random_word(&rng);
            }
            tfit_region_surface(&st, state, f, out);
            bad += !finite(out, 3 * surf->n_out);
            calls++;
            if (affine) {
                tfit_region_pair(&lt, &st, state, tip, f);
                tfit_region_surface_pair(&st, state, f, out);
                bad += !finite(f, 6) || !finite(out, 3 * surf->n_out) ||
                       (fresh && !finite(state, 6));
                calls += 2;
            }
        }
        tf_model_free(law);
        tf_model_free(surf);
    }
    printf("random regions (degrees 2-4), any tips, forces and states: %ld calls\n", calls);
    verdict("(d) calls with a NaN or Inf output or state word", (double)bad, 0, 1);
}

/* (e): the stuck contact against the potential's gradient in double. */
static void stuck(double bump, int samples)
{
    region r;
    if (make(&r, bump, 10.0, 2.0) != 0) {
        failures++;
        return;
    }
    tf_rng rng = {0x57acu};
    const double su = r.law->coef[TF_REGION_CHART + TF_REGION_SU];
    double worst = 0;
    int used = 0;
    for (int i = 0; i < samples; ++i) {
        double g[2] = {(float)tf_rng_range(&rng, 0, 16), (float)tf_rng_range(&rng, 0, 16)};
        if (i % 4 == 0) { /* a site: the grid node */
            g[0] = floor(g[0]);
            g[1] = floor(g[1]);
        }
        double x[3], e[6], xa[3], xb[3];
        tf_region_rest_point(r.law, g, x, e);
        const double da[2] = {g[0] + 1e-5, g[1]}, db[2] = {g[0], g[1] + 1e-5};
        tf_region_rest_point(r.law, da, xa, NULL);
        tf_region_rest_point(r.law, db, xb, NULL);
        /* the surface normal, then u = -d n + a small tangential part */
        double n[3] = {-(xa[2] - x[2]) / (1e-5 * r.g.chart.ha),
                       -(xb[2] - x[2]) / (1e-5 * r.g.chart.hb), 1};
        const double nn = sqrt(n[0] * n[0] + n[1] * n[1] + 1);
        const double d = tf_rng_range(&rng, 0.2, 1.6); /* |v| <= 0.9 */
        double u[3];
        for (int k = 0; k < 3; ++k) {
            u[k] = -d * n[k] / nn + tf_rng_range(&rng, -0.1, 0.1) * d;
        }
        float state[3] = {(float)g[0], (float)g[1], 1.0f}, tip[3], f[3];
        const double q[3] = {x[0] + u[0], x[1] + u[1], x[2] + u[2]};
        tip_at(&r, q, tip);
        if (tfit_region_force(&r.t, state, tip, f) != TFIT_OK) {
            continue; /* the tip's own site above the surface, or beyond the envelope */
        }
        /* F = s_u grad_v E, E = 1/2 v^T H v with H from e (chart = scene axes);
         * u from the float tip, as the device sees it */
        double v[3];
        for (int k = 0; k < 3; ++k) {
            v[k] = su * ((double)tip[k] - r.g.chart.origin[k] - x[k]);
        }
        const double h[9] = {2 * e[0], e[1], e[2], e[1], 2 * e[3], e[4], e[2], e[4], 2 * e[5]};
        double fe[3], diff = 0, norm = 0;
        for (int k = 0; k < 3; ++k) {
            fe[k] = su * (h[3 * k] * v[0] + h[3 * k + 1] * v[1] + h[3 * k + 2] * v[2]);
            diff += (f[k] - fe[k]) * (f[k] - fe[k]);
            norm += fe[k] * fe[k];
        }
        worst = fmax(worst, sqrt(diff / norm));
        used++;
    }
    printf("%s region, proxy held (mu = 10): %d stuck contacts (of %d drawn), a quarter at sites\n",
           bump > 0 ? "curved" : "block-like", used, samples);
    /* the float chart map and rest point of a 45 mm coordinate round by
     * about 4e-6 mm, against |u| >= 0.2 mm */
    verdict("(e) largest |F - grad E| / |grad E| (float tick vs double law)", worst, 5e-5, 1);
    if (used < samples / 2) {
        printf("  too few stuck contacts tested\n");
        failures++;
    }
    tf_model_free(r.law);
}

int main(int argc, char **argv)
{
    const int paths = argc > 1 ? atoi(argv[1]) : 10000;
    tf_ctx_init(&ctx);
    /* 10^4 sliding paths and 10^3 loops over the four (shape, friction) pairs */
    static const struct {
        const char *name;
        double bump, mu;
    } cases[] = {{"block-like region", 0, 0},   {"block-like region", 0, 0.3},
                 {"curved region", 3.0, 0},     {"curved region", 3.0, 0.3},
                 {"block-like region", 0, 1.0}, {"curved region", 3.0, 1.0}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        const int share = i < 4 ? paths / 4 : 0; /* mu = 1: loops only */
        contact_properties(cases[i].name, cases[i].bump, cases[i].mu, SCALE, share,
                           i < 4 ? paths / 40 : paths / 80);
    }
    finiteness(40, 2000);
    stuck(0, 4000);
    stuck(3.0, 4000);
    if (failures != 0) {
        printf("%d properties beyond their bounds\n", failures);
        return 1;
    }
    return 0;
}
