/*
 * recursion_study.c — the float32 accuracy of one resonant mode's update
 * (tfit_resonant_step, weight 1 on every axis: all the response in one
 * mode, the worst case) against the same zero-order-hold recursion in
 * double with the exact transition matrix, over N ticks of a haptic force
 * history (holds, presses, strikes of 1..8 ticks, smooth random stretches;
 * |g| <= 0.26), by omega T and zeta.  What is compared is the mode's own
 * position y = g + s from the device's state (not its clamped output: a
 * lightly damped mode driven near resonance rises far beyond the
 * envelope, where the device clamps h by design).  Prints, per case, the float F's contraction margin
 * 1 - |F|_2, whether the host accepts the mode (tf_resonant_params_check),
 * and the largest error relative to the peak response (docs/fitting.md §8.3).
 *
 *   recursion_study [TICKS]      (default 10^6)
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/rng.h"
#include "model/ref_eval.h"
#include "model/forms/resonant.h"
#include "model/target_view.h"

static tf_model *one_mode(double omega_t, double zeta)
{
    const uint32_t dims[TFIT_RESONANT_DIMS] = {1, 0, 1, 1000000};
    const double origin[3] = {0, 0, 0}, w[3] = {1, 1, 1};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = tf_model_new(&ctx, "s", TFIT_FAMILY_RESONANT, 1, dims, TFIT_RESONANT_DIMS);
    tf_model_set_ball(m, origin, 1.0);
    float *rows = tf_model_tables(m) + 7;
    for (int c = 0; c < 3; ++c) {
        rows[4 * c + 1 + c] = 1.0f;
    }
    tf_resonant_set_mode(m, 0, omega_t / 1e-3, zeta, w);
    return m;
}

/* The force of tick n: a new segment every 1..2000 ticks (hold, strike,
 * ramp, smooth random), levels in [-0.45, 0.45]. */
typedef struct gen {
    tf_rng r;
    long left, kind, len, at;
    double from[3], to[3], now[3];
} gen;

static void next_force(gen *g, float f[3])
{
    if (g->left <= 0) {
        g->kind = (long)tf_rng_below(&g->r, 4);
        g->len = g->kind == 1 ? 1 + (long)tf_rng_below(&g->r, 8) : 1 + (long)tf_rng_below(&g->r, 2000);
        g->left = g->kind == 1 ? g->len + 200 + (long)tf_rng_below(&g->r, 2000) : g->len;
        g->at = 0;
        for (int c = 0; c < 3; ++c) {
            g->from[c] = g->now[c];
            g->to[c] = tf_rng_range(&g->r, -0.26, 0.26);
        }
    }
    const double s = g->kind == 0 ? 0.0
                     : g->kind == 1 ? (g->at < g->len ? 1.0 : 0.0)
                                    : 0.5 * (1 - cos(3.14159265358979 * fmin(1.0, (double)g->at / (double)g->len)));
    for (int c = 0; c < 3; ++c) {
        g->now[c] = g->kind == 1 ? (s > 0 ? g->to[c] : g->from[c])
                                 : g->from[c] + s * (g->to[c] - g->from[c]);
        f[c] = (float)g->now[c];
    }
    g->at++;
    g->left--;
}

int main(int argc, char **argv)
{
    const long ticks = argc > 1 ? strtol(argv[1], NULL, 10) : 1000000;
    const double wts[] = {1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.3, 1.0, 1.5};
    const double zetas[] = {0.005, 0.05, 0.3};
    printf("one resonant mode, weight 1, %ld ticks: float32 device against the double "
           "recursion\n\n| omega T | zeta | 1 - |F_float|_2 | host | largest error / peak |\n"
           "|---|---|---|---|---|\n",
           ticks);
    for (size_t a = 0; a < sizeof wts / sizeof *wts; ++a) {
        for (size_t b = 0; b < sizeof zetas / sizeof *zetas; ++b) {
            tf_model *m = one_mode(wts[a], zetas[b]);
            tf_ctx ctx;
            tf_ctx_init(&ctx);
            const int ok = tf_resonant_params_check(&ctx, wts[a] / 1e-3, zetas[b], 1e-3) == 0;
            double F[4], Ff[4];
            tf_resonant_transition(wts[a], zetas[b], F);
            for (int i = 0; i < 4; ++i) {
                Ff[i] = (float)F[i];
            }
            const double margin = 1 - tf_resonant_norm2(Ff);
            float st[TFIT_RESONANT_MAX_STATE], out[3];
            tf_stateful_reset(m, st);
            gen g = {{0x5eed + a * 16 + b}, 0, 0, 0, 0, {0}, {0}, {0}};
            double s[3] = {0, 0, 0}, v[3] = {0, 0, 0}, prev[3] = {0, 0, 0}, worst = 0, peak = 0;
            for (long n = 0; n < ticks; ++n) {
                float f[3];
                next_force(&g, f);
                (void)tf_stateful_step(m, st, f, out, NULL);
                for (int c = 0; c < 3; ++c) {
                    const double e1 = s[c] - ((double)f[c] - prev[c]);
                    s[c] = F[0] * e1 + F[1] * v[c];
                    v[c] = F[2] * e1 + F[3] * v[c];
                    prev[c] = f[c];
                    const double y = (double)f[c] + s[c];
                    const double y_dev = (double)f[c] + (double)st[3 + c]; /* s of the mode */
                    worst = fmax(worst, fabs(y_dev - y));
                    peak = fmax(peak, fabs(y));
                }
            }
            printf("| %g | %g | %.2e | %s | %.1e |\n", wts[a], zetas[b], margin,
                   ok ? "accepted" : "refused", worst / peak);
            tf_model_free(m);
        }
    }
    return 0;
}
