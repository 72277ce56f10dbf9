/*
 * recursion_study.c — how accurate is one prony term's float32 update over
 * 10^6 ticks, as a function of r = T / tau (docs/fitting.md, "Tick period
 * bounds").  The device's own step (libtfit, tfit_prony_step) runs a
 * one-point model whose static map is the identity (out = h), driven on one
 * axis by
 *   press:  ramps over 100 ticks to 0.9, holds, releases, rests (holds of
 *           max(1000, 5/r) ticks, so that the creep develops fully);
 *   random: ramps of random length to random forces in [-0.9, 0.9] and
 *           holds, from the haptic test sequence (tests/support/force_sequence.h);
 * and compared at every tick with the same recursion in double precision:
 *   arithmetic  the float coefficients a, D the device holds, in double:
 *               the error of float32 arithmetic alone;
 *   total       the exact first-order hold of the requested tau and weight:
 *               adds the rounding of a and D to float (which moves the
 *               realised time constant by up to 2^-25 / r relative).
 * The weight is 1 (all the creep in this term, the worst case), so the
 * errors are relative to the peak response.  Prints one row per r.
 *
 *   recursion_study [TICKS]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "force_sequence.h"
#include "model/model.h"
#include "model/forms/prony.h"
#include "model/target_view.h"
#include "tfit.h"

#define TICK 1e-3 /* s; only r = T / tau matters */

typedef struct errors {
    double arith, total;
} errors;

/* Input of tick n: the press cycle or the random history (axis 0). */
static double press(long n, long hold)
{
    const long period = 2 * (100 + hold), k = n % period;
    if (k < 100) {
        return 0.9 * (double)k / 100;
    }
    if (k < 100 + hold) {
        return 0.9;
    }
    if (k < 200 + hold) {
        return 0.9 * (double)(200 + hold - k) / 100;
    }
    return 0.0;
}

static errors run(double r, long ticks, int random_input)
{
    const uint32_t dims[TFIT_PRONY_DIMS] = {1, 0, 1, 1000000};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = tf_model_new(&ctx, "s", TFIT_FAMILY_PRONY, 1, dims, TFIT_PRONY_DIMS);
    const double tau = TICK / r;
    tf_prony_set_term(m, 0, tau, 1.0);
    float *rows = tf_model_tables(m) + 2;
    rows[1] = rows[4 + 2] = rows[8 + 3] = 1.0f; /* out = h */
    tfit_model t;
    tf_target_view(m, &t);
    if (tfit_model_check(&t) != TFIT_OK) { /* a too close to 1: refused on the device */
        tf_model_free(m);
        return (errors){NAN, NAN};
    }
    const float a = m->coef[TFIT_INPUT_MAP_FLOATS], d = m->coef[TFIT_INPUT_MAP_FLOATS + 1];
    /* the exact first-order hold of the requested tau (prony.h) */
    const double a_exact = exp(-r), d_exact = -expm1(-r) / r;
    float st[TFIT_PRONY_MAX_STATE], out[3];
    tfit_prony_reset(&t, st);
    double e_arith = 0, e_total = 0, g_prev = 0;
    errors worst = {0, 0};
    tf_force_seq q;
    tf_seq_init(&q, 12345u);
    const long hold = (long)fmax(1000.0, 5.0 / r);
    for (long n = 0; n < ticks; ++n) {
        double g;
        if (random_input) {
            int32_t v[3];
            (void)tf_seq_tick(&q, v);
            g = fmax(-0.9, fmin(0.9, ldexp((double)v[0], -22) * 0.9));
        } else {
            g = press(n, hold);
        }
        const float f[3] = {(float)g, 0.0f, 0.0f};
        g = (double)f[0];
        tfit_prony_step(&t, st, f, out);
        e_arith = (double)a * e_arith + (double)d * (g - g_prev);
        e_total = a_exact * e_total + d_exact * (g - g_prev);
        g_prev = g;
        worst.arith = fmax(worst.arith, fabs((double)out[0] - (g - e_arith)));
        worst.total = fmax(worst.total, fabs((double)out[0] - (g - e_total)));
    }
    tf_model_free(m);
    return worst;
}

int main(int argc, char **argv)
{
    const long ticks = argc > 1 ? strtol(argv[1], NULL, 10) : 1000000;
    printf("# one prony term, weight 1, float32 step against double over %ld ticks\n", ticks);
    printf("# columns: r = T/tau, tau/T, then the largest |error| relative to the peak:\n");
    printf("#   press-hold-release (arithmetic, total), random history (arithmetic, total)\n");
    printf("%-10s %-10s %-11s %-11s %-11s %-11s\n", "T/tau", "tau/T", "press-arith", "press-total",
           "rand-arith", "rand-total");
    for (int k = -4; k <= 28; ++k) {
        const double r = pow(10.0, -(double)k / 4);
        errors p = run(r, ticks, 0), q = run(r, ticks, 1);
        if (isnan(p.arith)) {
            printf("%-10.3g %-10.3g refused by tfit_model_check (a > 1 - 2^-20)\n", r, 1 / r);
            break;
        }
        printf("%-10.3g %-10.3g %-11.3g %-11.3g %-11.3g %-11.3g\n", r, 1 / r, p.arith / 0.9,
               p.total / 0.9, q.arith / 0.9, q.total / 0.9);
        fflush(stdout);
    }
    return 0;
}
