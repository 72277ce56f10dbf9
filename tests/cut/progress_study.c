/*
 * progress_study.c — how to make the cut progress s a model input
 * (docs/cutting.md, "Cut progress"; issue 17 acceptance 4).
 *
 *   progress_study SCENE [KEY=VALUE]...
 *
 * Solves the scene with its cuts truncated at s = i/16 (i = 0..16), at the
 * midpoints between them and at 8 held-out values (fitting/cut_progress.h),
 * and compares, at the midpoints and held-out values, ways of carrying s:
 *
 *   - ignoring the cut: the uncut model (s = 0) for every s;
 *   - a family of K + 1 uncut-style models, one per knot s = k/K, the
 *     firmware picking the nearest (a nodal model's cost per call);
 *   - the cut family: those knots, linear in s between them (tfit_cut.c);
 *   - one polynomial of degree q in s (Chebyshev in 2s - 1), least squares
 *     on the 17 solved knots.
 *
 * Each is judged exactly over the force envelope |F - c| <= r: at each s
 * the response is affine, u = A_s [1; F], so the largest error of a
 * predictor B is max_o |d0_o + d_o . c| + r |d_o| with d = B - A_s, and its
 * RMS over forces uniform in the ball uses E[(F-c)(F-c)^T] = r^2/5 I.  The
 * float32 rounding of the target (about 1e-7 mm here) is left out.
 * Operation counts per output component are the evaluation formulas of
 * docs/header-format.md; the cut family's cycles are the cycle model's
 * (host/cost/cycles.c, checked under QEMU), the polynomial's are not
 * implemented on the target and are given as operations only.
 * Output: a markdown table on stdout.  Exit 0, 1 failure, 2 usage.
 */
#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/context.h"
#include "cost/cycles.h"
#include "fitting/cut_progress.h"
#include "model/model.h"
#include "scene/scene.h"
#include "solvers/solver.h"

#define KMAX 16
#define HELDOUT 8

typedef struct study {
    const tf_cut_cases *cc;
    double centre[3], radius;
} study;

/* Largest and summed squared (per force, ball average) error of the
 * affine map b (4 x rows) against sample i. */
static void judge(const study *st, const double *b, size_t i, double *max, double *sum2)
{
    const tf_cut_cases *cc = st->cc;
    const double *a = cc->resp + i * 4 * cc->rows;
    const size_t n = cc->rows;
    for (size_t o = 0; o < n; ++o) {
        double d[4], dn2 = 0;
        for (int k = 0; k < 4; ++k) {
            d[k] = b[k * n + o] - a[k * n + o];
        }
        double at_c = d[0] + d[1] * st->centre[0] + d[2] * st->centre[1] + d[3] * st->centre[2];
        dn2 = d[1] * d[1] + d[2] * d[2] + d[3] * d[3];
        *max = fmax(*max, fabs(at_c) + st->radius * sqrt(dn2));
        *sum2 += at_c * at_c + st->radius * st->radius * dn2 / 5.0;
    }
}

enum { IGNORE, NEAREST, LINEAR, POLY };

/* The predictor of a kind at s into b (4 x rows); order: K or q. */
static void predict(const study *st, int kind, uint32_t order, const double *poly, double s,
                    double *b)
{
    const tf_cut_cases *cc = st->cc;
    const size_t n4 = 4 * cc->rows;
    const double *knot = cc->resp; /* samples 0..KMAX are s = i / KMAX */
    if (kind == IGNORE) {
        memcpy(b, knot, n4 * sizeof *b);
    } else if (kind == NEAREST || kind == LINEAR) {
        const uint32_t step = KMAX / order;
        double t = s * order;
        uint32_t j = (uint32_t)t < order ? (uint32_t)t : order - 1;
        double w = t - j;
        const double *lo = knot + (size_t)j * step * n4, *hi = lo + step * n4;
        for (size_t e = 0; e < n4; ++e) {
            b[e] = kind == LINEAR ? lo[e] + w * (hi[e] - lo[e]) : (w < 0.5 ? lo[e] : hi[e]);
        }
    } else {
        double x = 2 * s - 1, tk[KMAX + 1];
        tk[0] = 1;
        tk[1] = x;
        for (uint32_t k = 2; k <= order; ++k) {
            tk[k] = 2 * x * tk[k - 1] - tk[k - 2];
        }
        for (size_t e = 0; e < n4; ++e) {
            double v = 0;
            for (uint32_t k = 0; k <= order; ++k) {
                v += poly[e * (order + 1) + k] * tk[k];
            }
            b[e] = v;
        }
    }
}

/* Chebyshev coefficients (n4 x (q+1)) of degree q by least squares on the
 * KMAX + 1 knots. */
static double *fit_poly(const tf_cut_cases *cc, uint32_t q)
{
    const size_t n4 = 4 * cc->rows, m = KMAX + 1, t = q + 1;
    double *a = malloc(m * t * sizeof *a), *y = malloc(m * n4 * sizeof *y);
    double *c = malloc(n4 * t * sizeof *c);
    for (size_t i = 0; i < m; ++i) {
        double x = 2.0 * (double)i / KMAX - 1, tk[KMAX + 1];
        tk[0] = 1;
        tk[1] = x;
        for (uint32_t k = 2; k <= q; ++k) {
            tk[k] = 2 * x * tk[k - 1] - tk[k - 2];
        }
        for (size_t k = 0; k < t; ++k) {
            a[i + k * m] = tk[k];
        }
        for (size_t e = 0; e < n4; ++e) {
            y[i + e * m] = cc->resp[i * n4 + e];
        }
    }
    if (LAPACKE_dgels(LAPACK_COL_MAJOR, 'N', (lapack_int)m, (lapack_int)t, (lapack_int)n4, a,
                      (lapack_int)m, y, (lapack_int)m) != 0) {
        return NULL;
    }
    for (size_t e = 0; e < n4; ++e) {
        for (size_t k = 0; k < t; ++k) {
            c[e * t + k] = y[k + e * m];
        }
    }
    free(a);
    free(y);
    return c;
}

/* Largest error and RMS over the samples of a role. */
static void errors(const study *st, int kind, uint32_t order, const double *poly, int role,
                   double *max, double *rms)
{
    const tf_cut_cases *cc = st->cc;
    double *b = malloc(4 * cc->rows * sizeof *b), sum2 = 0;
    size_t count = 0;
    *max = 0;
    for (size_t i = 0; i < cc->n; ++i) {
        if (cc->role[i] == role) {
            predict(st, kind, order, poly, cc->s[i], b);
            judge(st, b, i, max, &sum2);
            count += cc->rows;
        }
    }
    *rms = sqrt(sum2 / (double)count);
    free(b);
}

static void row(const study *st, const char *what, int kind, uint32_t order, const double *poly,
                const char *ops, const char *cycles, size_t floats)
{
    double vmax, vrms, hmax, hrms;
    errors(st, kind, order, poly, TF_CUT_VALIDATE, &vmax, &vrms);
    errors(st, kind, order, poly, TF_CUT_HELDOUT, &hmax, &hrms);
    printf("| %s | %s | %s | %zu | %.3g | %.3g | %.3g | %.3g |\n", what, ops, cycles,
           4 * floats, vmax, vrms, hmax, hrms);
}

static void cycles_of(tfit_family fam, uint32_t p, uint32_t k, uint32_t n_out, char *buf,
                      size_t n)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const uint32_t dims[2] = {p, k};
    tf_model *m = tf_model_new(&ctx, "x", fam, n_out, dims, fam == TFIT_FAMILY_CUT ? 2 : 1);
    tf_cycles c4 = tf_model_cycles(m, TF_CORE_M4F), c7 = tf_model_cycles(m, TF_CORE_M7);
    snprintf(buf, n, "%.0f / %.0f", c4.cycles, c7.cycles);
    tf_model_free(m);
}

int main(int argc, char **argv)
{
    if (argc < 2 || argc > 16) {
        fprintf(stderr, "usage: progress_study SCENE [KEY=VALUE]...\n");
        return 2;
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    tf_scene *sc = tf_scene_load(&ctx, argv[1], (const char **)argv + 2, (size_t)(argc - 2));
    if (sc == NULL) {
        fprintf(stderr, "progress_study: %s\n", ctx.err);
        return 2;
    }
    tf_fit_plan plan = sc->fit;
    plan.cut_intervals = KMAX;
    plan.cut_heldout = HELDOUT;
    tf_solver *sv = tf_solver_create(&sc->problem, NULL, &ctx);
    tf_cut_cases cc;
    if (sv == NULL || tf_cut_cases_solve(&sc->problem, sv, &plan, &cc) != 0) {
        fprintf(stderr, "progress_study: %s\n", ctx.err);
        return 1;
    }
    study st = {.cc = &cc, .radius = sc->problem.envelope.radius};
    memcpy(st.centre, sc->problem.envelope.centre, sizeof st.centre);
    const uint32_t n_out = (uint32_t)(cc.rows / 3);
    double umax = 0;
    for (size_t i = 0; i < cc.n; ++i) {
        const double *a = cc.resp + i * 4 * cc.rows;
        for (size_t o = 0; o < cc.rows; ++o) {
            double g = sqrt(a[cc.rows + o] * a[cc.rows + o] + a[2 * cc.rows + o] * a[2 * cc.rows + o] +
                            a[3 * cc.rows + o] * a[3 * cc.rows + o]);
            umax = fmax(umax, fabs(a[o]) + st.radius * g);
        }
    }
    printf("%s: %u output points, %zu values of s solved; largest displacement over the "
           "envelope and s: %.4g mm\n\n",
           argv[1], n_out, cc.n, umax);
    printf("| model of s | ops per output component | M4F / M7 cycles (%u points) | table bytes | "
           "max between knots (mm) | RMS between knots | max held-out s (mm) | RMS held-out s |\n"
           "|---|---|---|---|---|---|---|---|\n", n_out);
    char cyc[64];
    const size_t nodal = 12 * (size_t)n_out + 12;
    cycles_of(TFIT_FAMILY_NODAL, 1, 0, n_out, cyc, sizeof cyc);
    row(&st, "uncut nodal model, cut ignored", IGNORE, 0, NULL, "3 mul 3 add", cyc, nodal);
    for (uint32_t k = 1; k <= KMAX; k *= 2) {
        char what[96], ops[64], cc_cyc[64];
        snprintf(what, sizeof what, "%u + 1 nodal models, nearest knot", k);
        row(&st, what, NEAREST, k, NULL, "3 mul 3 add", cyc, (k + 1) * nodal);
        snprintf(what, sizeof what, "**cut family, K = %u** (linear in s)", k);
        snprintf(ops, sizeof ops, "7 mul 8 add");
        cycles_of(TFIT_FAMILY_CUT, 1, k, n_out, cc_cyc, sizeof cc_cyc);
        row(&st, what, LINEAR, k, NULL, ops, cc_cyc, (k + 1) * 12 * (size_t)n_out + 12);
    }
    for (uint32_t q = 1; q <= KMAX; q *= 2) {
        double *poly = fit_poly(&cc, q);
        char what[96], ops[64];
        if (poly == NULL) {
            fprintf(stderr, "progress_study: least squares failed at q = %u\n", q);
            return 1;
        }
        snprintf(what, sizeof what, "polynomial in s, degree %u (not on the target)", q);
        /* q + 1 rows of 3 mul 3 add, then Clenshaw: q + 1 mul, 2q + 3 add */
        snprintf(ops, sizeof ops, "%u mul %u add", 3 * (q + 1) + q + 1, 3 * (q + 1) + 2 * q + 3);
        row(&st, what, POLY, q, poly, ops, "-", (q + 1) * 12 * (size_t)n_out + 12);
        free(poly);
    }
    tf_cut_cases_free(&cc);
    tf_solver_destroy(sv);
    tf_scene_free(sc);
    return 0;
}
