/*
 * oscillator.c — see oscillator.h.
 */
#include "model/oscillator.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>
#include <math.h>
#include <stdio.h>

#define PI 3.14159265358979323846

void tf_resonant_transition(double omega_t, double zeta, double f[4])
{
    double a[4] = {0, omega_t, -omega_t, -2 * zeta * omega_t}, e[4];
    gsl_matrix_view av = gsl_matrix_view_array(a, 2, 2);
    gsl_matrix_view ev = gsl_matrix_view_array(e, 2, 2);
    /* 2 x 2, finite entries: GSL's only failures (not square, bad length)
     * cannot happen; its default handler would abort rather than return */
    (void)gsl_linalg_exponential_ss(&av.matrix, &ev.matrix, GSL_PREC_DOUBLE);
    for (int i = 0; i < 4; ++i) {
        f[i] = e[i];
    }
}

double tf_resonant_norm2(const double f[4])
{
    const double fro = f[0] * f[0] + f[1] * f[1] + f[2] * f[2] + f[3] * f[3];
    const double det = f[0] * f[3] - f[1] * f[2];
    const double disc = fro * fro - 4 * det * det;
    return sqrt(0.5 * (fro + sqrt(disc > 0 ? disc : 0)));
}

/* The norm of F rounded to float. */
static double rounded_norm(double omega_t, double zeta)
{
    double f[4];
    tf_resonant_transition(omega_t, zeta, f);
    for (int i = 0; i < 4; ++i) {
        f[i] = (float)f[i];
    }
    return tf_resonant_norm2(f);
}

/* A tick (s) at which the mode's rounded F contracts by 1.25 times the
 * margin (the rounding of F moves 1 - |F|_2 by a few per cent: the
 * suggestion must pass): bisection in log T over
 * [T, TF_RESONANT_MAX_WT / omega] (the margin grows with omega T), then
 * rounded up to three digits. */
static double tick_needed(double omega, double zeta, double tick)
{
    double lo = tick, hi = TF_RESONANT_MAX_WT / omega;
    const double want = 1.25 * TF_RESONANT_MIN_MARGIN;
    if (1 - rounded_norm(omega * hi, zeta) < want) {
        return NAN;
    }
    for (int it = 0; it < 60; ++it) {
        const double mid = sqrt(lo * hi);
        if (1 - rounded_norm(omega * mid, zeta) >= want) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    const double scale = pow(10.0, floor(log10(hi)) - 2);
    return ceil(hi / scale) * scale;
}

int tf_resonant_params_check(tf_ctx *ctx, double omega, double zeta, double tick)
{
    const double wt = omega * tick, hz = omega / (2 * PI);
    if (!(omega > 0) || !(zeta > 0) || !(zeta <= TF_RESONANT_MAX_ZETA)) {
        tf_fail(ctx,
                "resonant: mode at %.6g Hz with damping ratio %.4g is outside the family's "
                "limits (omega > 0, 0 < zeta <= %g)",
                hz, zeta, TF_RESONANT_MAX_ZETA);
        return 1;
    }
    if (wt > TF_RESONANT_MAX_WT) {
        tf_fail(ctx,
                "resonant: mode at %.6g Hz is %.3g ticks per period of %.6g s: the tick does not "
                "resolve it (omega T <= %g, docs/fitting.md §8); fit with a tick of at most "
                "%.3g us",
                hz, 2 * PI / wt, tick, TF_RESONANT_MAX_WT, 1e6 * TF_RESONANT_MAX_WT / omega);
        return 1;
    }
    const double margin = 1 - rounded_norm(wt, zeta);
    if (!(margin >= TF_RESONANT_MIN_MARGIN)) {
        const double need = tick_needed(omega, zeta, tick);
        tf_fail(ctx,
                "resonant: mode at %.6g Hz with damping ratio %.4g at a %.6g s tick: its float "
                "transition matrix contracts by %.3g per tick, below 2^-20 (the float32 "
                "recursion would drift or grow, docs/fitting.md §8); fit with a tick of at "
                "least %.3g us",
                hz, zeta, tick, margin, 1e6 * need);
        return 1;
    }
    return 0;
}

int tf_resonant_floats_check(tf_ctx *ctx, const float pt[7], const char *name, uint32_t k)
{
    double f[4];
    for (int i = 0; i < 4; ++i) {
        f[i] = pt[i];
    }
    int bad = !(fabs(f[0]) <= 1 && fabs(f[1]) <= 1 && fabs(f[2]) <= 1 && fabs(f[3]) <= 1);
    for (int i = 4; i < 7; ++i) {
        bad |= !(fabs((double)pt[i]) <= 0x1p10);
    }
    const double margin = 1 - tf_resonant_norm2(f);
    if (bad || !(margin >= TF_RESONANT_MIN_MARGIN)) {
        tf_fail(ctx,
                "model '%s': resonant mode %u has F = [%g %g; %g %g], weights %g %g %g "
                "(|F_ij| <= 1, 1 - |F|_2 >= 2^-20 and |w| <= 2^10 keep the state finite)",
                name, k, f[0], f[1], f[2], f[3], (double)pt[4], (double)pt[5], (double)pt[6]);
        return 1;
    }
    return 0;
}
