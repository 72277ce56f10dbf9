/*
 * structure_study.c — where to put the exponential terms (docs/fitting.md
 * §7): on the input of the static map (the prony family: the force filtered,
 * then the relaxed static response, a Wiener model) or on its outputs (the
 * relaxed static response of the force, then filtered: a Hammerstein
 * model).  Measured at one material point of seed 001's nonlinear Kelvin
 * law under stress control, where the closed form is
 *
 *     N(eps(t)) = int J(t - s) dsigma(s),   N(eps) = eps + k eps^2,
 *     J(t) = 1/k1 - k2 / (k1 (k1 + k2)) exp(-t / tau_c),  tau_c = eta (k1 + k2) / (k1 k2)
 *
 * (docs/solver.md, "Seed 001's Kelvin law"; tests/unit/materials/
 * test_material_uniaxial.c checks host/materials/kelvin.c against it).
 * Both candidates get the same relaxed static map eps_inf(sigma) =
 * N^-1(sigma / k1) and K terms fitted by prony_terms.c on 12 training
 * stress histories (press, hold, release at random levels and times);
 * the table gives their largest error over 6 held-out histories, relative
 * to the largest strain there, for k = 0 (linear), 2 and 5.
 *
 *   structure_study
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/rng.h"
#include "fitting/prony_terms.h"

#define K1 0.2   /* MPa */
#define K2 0.12  /* MPa */
#define ETA 0.3  /* MPa s */
#define TICK 1e-3
#define N_TICKS 6000
#define N_TRAIN 12
#define N_HELD 6
#define SIGMA_MAX 0.08 /* MPa: strains to about 25 % at k = 0 */

static double n_inverse(double k, double y)
{
    return k == 0 ? y : (-1 + sqrt(1 + 4 * k * y)) / (2 * k);
}

/* A press-hold-release stress history, linear ramps between ticks. */
static void history(tf_rng *r, double *sigma)
{
    const double level = tf_rng_range(r, 0.2, 1.0) * SIGMA_MAX;
    const long t0 = (long)tf_rng_range(r, 0, 300), up = (long)tf_rng_range(r, 20, 500);
    const long hold = (long)tf_rng_range(r, 1000, 3500), down = (long)tf_rng_range(r, 20, 500);
    for (long n = 0; n < N_TICKS; ++n) {
        double s = 0;
        if (n >= t0 && n < t0 + up) {
            s = (double)(n - t0) / (double)up;
        } else if (n >= t0 + up && n < t0 + up + hold) {
            s = 1;
        } else if (n >= t0 + up + hold && n < t0 + up + hold + down) {
            s = 1 - (double)(n - t0 - up - hold) / (double)down;
        }
        sigma[n] = level * s;
    }
}

/* The strain of the law under sigma (exact for stress linear between ticks). */
static void strain(double k, const double *sigma, double *eps)
{
    const double tau_c = ETA * (K1 + K2) / (K1 * K2), w = K2 / (K1 + K2);
    const double r = TICK / tau_c, a = exp(-r), gain = -expm1(-r) / r;
    double e = 0, prev = 0;
    for (long n = 0; n < N_TICKS; ++n) {
        e = a * e + gain * (sigma[n] - prev);
        prev = sigma[n];
        eps[n] = n_inverse(k, (sigma[n] - w * e) / K1);
    }
}

typedef struct candidate {
    double *g, *target; /* 3 per tick, axis 0 used */
    double scale;       /* of the data, to the unit interval */
} candidate;

/* The largest error of the fitted candidate on histories [first, first + n)
 * in strain, and the largest strain there. */
static double error_of(const tf_prony_data *d, const tf_prony_terms *t, size_t first, size_t n,
                       double k, int wiener, double scale, const double *eps_true, double *peak)
{
    double worst = 0;
    for (size_t h = first; h < first + n; ++h) {
        double e[TFIT_PRONY_MAX_TERMS] = {0}, prev = 0;
        for (size_t i = 0; i < N_TICKS; ++i) {
            const double g = d->g[3 * (h * N_TICKS + i)];
            double out = g;
            for (int j = 0; j < t->n; ++j) {
                const double r = TICK / t->tau[j];
                e[j] = exp(-r) * e[j] + (-expm1(-r) / r) * (g - prev);
                out -= t->w[j] * e[j];
            }
            prev = g;
            const double eps = wiener ? n_inverse(k, out * scale / K1) : out * scale;
            const double truth = eps_true[h * N_TICKS + i];
            worst = fmax(worst, fabs(eps - truth));
            *peak = fmax(*peak, fabs(truth));
        }
    }
    return worst;
}

int main(void)
{
    const size_t n = N_TRAIN + N_HELD, ticks = n * N_TICKS;
    double *sigma = malloc(ticks * sizeof *sigma), *eps = malloc(ticks * sizeof *eps);
    double *g = calloc(3 * ticks, sizeof *g), *target = calloc(3 * ticks, sizeof *target);
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    printf("# Wiener (terms on the static map's input: the prony family) against Hammerstein\n"
           "# (terms on its output) at a material point of [EFG-Kelvin]'s Kelvin law under stress,\n"
           "# k1 = %g MPa, k2 = %g MPa, eta = %g MPa s, stress to %g MPa; %d training and %d\n"
           "# held-out press-hold-release histories of %d ticks of %g ms.  Largest held-out\n"
           "# strain error relative to the largest strain, K terms fitted by prony_terms.c\n",
           K1, K2, ETA, SIGMA_MAX, N_TRAIN, N_HELD, N_TICKS, 1e3 * TICK);
    printf("%-4s %-3s %-12s %-12s\n", "k", "K", "wiener", "hammerstein");
    const double ks[3] = {0, 2, 5};
    for (int kk = 0; kk < 3; ++kk) {
        const double k = ks[kk];
        tf_rng r = {2014};
        for (size_t h = 0; h < n; ++h) {
            history(&r, sigma + h * N_TICKS);
            strain(k, sigma + h * N_TICKS, eps + h * N_TICKS);
        }
        for (int K = 1; K <= 3; ++K) {
            double rel[2];
            for (int wiener = 1; wiener >= 0; --wiener) {
                /* Wiener: g = sigma, target = the effective stress k1 N(eps);
                 * Hammerstein: g = eps_inf(sigma), target = eps; both over a scale */
                const double scale = wiener ? SIGMA_MAX : n_inverse(k, SIGMA_MAX / K1);
                for (size_t i = 0; i < ticks; ++i) {
                    const double e = eps[i];
                    g[3 * i] = (wiener ? sigma[i] : n_inverse(k, sigma[i] / K1)) / scale;
                    target[3 * i] = (wiener ? K1 * (e + k * e * e) : e) / scale;
                }
                const tf_prony_data d = {.n_hist = n, .n_ticks = N_TICKS, .g = g,
                                         .target = target, .g_rest = {0, 0, 0}, .tick = TICK};
                size_t train[N_TRAIN];
                for (size_t h = 0; h < N_TRAIN; ++h) {
                    train[h] = h;
                }
                tf_prony_terms t;
                if (tf_prony_fit_terms(&ctx, &d, train, N_TRAIN, K, TICK, N_TICKS * TICK, &t) !=
                    0) {
                    fprintf(stderr, "structure_study: %s\n", ctx.err);
                    return 1;
                }
                double peak = 0;
                rel[wiener] = error_of(&d, &t, N_TRAIN, N_HELD, k, wiener, scale, eps, &peak) / peak;
            }
            printf("%-4g %-3d %-12.3g %-12.3g\n", k, K, rel[1], rel[0]);
        }
    }
    free(sigma);
    free(eps);
    free(g);
    free(target);
    return 0;
}
