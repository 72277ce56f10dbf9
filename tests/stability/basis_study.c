/*
 * basis_study.c — issue 7 item 1: what the polynomial basis costs in
 * float32 and float64, raw millimetres (seed 000, Tables 1-2: surface
 * polynomials p1 + p2 x + ... + p_k x^k, x in [0, 48] mm) against the
 * normalised monomials in X = (x - 24) / 24 in [-1, 1] (tissuefit's basis
 * up to API version 2) and the Chebyshev polynomials T_j(X) that the target
 * evaluates since API version 3 — in float32 through the target's own code,
 * in both of its forms: zhou2017's Clenshaw (tfit_cheb) and the nodal
 * basis-and-row (tfit_basis, tfit_row).
 *
 * For each order k = 1..8 and each displacement profile along the centre
 * line of the block48 top surface (profile() below):
 *
 *  1. P = the least-squares polynomial of order k through the profile at
 *     the 11 nodes x = 0, 4.8, ..., 48 (QR in double in the normalised
 *     basis, host/numerics/lsq.c).  P is defined by these double coefficients.
 *  2. The same P in the other bases, converted exactly (basis_forms.c).
 *  3. Every coefficient set rounded to float and to double and evaluated in
 *     that precision at the 513 points X = j/256, x = 24 + 24 X.  Both
 *     coordinates are exact there, so only the coefficients' rounding and
 *     the arithmetic differ between bases: the measurement isolates the
 *     basis.
 *  4. error = max |evaluation - P| / max |P| over the points (P in long
 *     double); digits lost = log10(error / u), u = 2^-24 (float) or 2^-53
 *     (double).  Negative: the error is below one rounding of the result.
 *
 * Also the 2-norm condition numbers (LAPACK dgesvd) of the 11 x (k+1)
 * design matrices, and the evaluation condition number
 * kappa = max_X sum |c_j phi_j(X)| / max |P|, which bounds what rounding the
 * coefficients alone costs: log10(kappa) digits.
 *
 *   basis_study [--accept-order K] [--data FILE] [--perturb E]
 *
 * prints the Markdown tables of docs/stability.md, writes the plot's
 * numbers (tests/stability/basis_plot.gp) to FILE, and exits 1 unless the
 * target's Chebyshev basis, in both forms, loses less than one decimal digit
 * in float32 at every order 1..K (default 8, the statement) on every
 * profile.  --perturb E multiplies every float32 coefficient by
 * 1 +- 2^-E (alternating signs) before evaluating: make check runs it with
 * E = 20 and requires the assertion to fail, so that it is known to bite.
 */
#include <float.h>
#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "basis_forms.h"
#include "base/blas_pin.h"
#include "numerics/lsq.h"

#define MAX_ORDER STAB_MAX_ORDER
#define GRID 11
#define SPACING 4.8    /* mm, block48's node spacing */
#define EVAL_STEPS 256 /* evaluation points X = j / EVAL_STEPS */
#define ACCEPT_DIGITS 1.0
#define N_BASES STAB_N_BASES

static int perturb_exp; /* 0: none */

enum { PROFILE_BUMP, PROFILE_INPLANE, PROFILE_PLATE, N_PROFILES };
static const char *const profile_names[N_PROFILES] = {"normal bump", "in-plane", "clamped plate"};

/* Displacement (mm) at x (mm) along the centre line under a 1 N force at
 * the centre node.  The bump and its in-plane companion are the synthetic
 * block48 field of tests/firmware/gen_haptic.c (decay 7 mm, 14.5 mm/N at
 * the centre); the plate is the Kirchhoff deflection of a clamped circular
 * plate of radius 24 mm under a central point load,
 * w ~ 1 - r^2 + 2 r^2 ln r (r = |x - 24| / 24), zero with zero slope at the
 * clamped edges as block48's top surface. */
static double profile(int which, double x)
{
    const double s = x - STAB_CENTRE, w = exp(-s * s / (2 * 7.0 * 7.0));
    const double r = fabs(s) / STAB_HALF;
    switch (which) {
    case PROFILE_BUMP:
        return 14.5 * w;
    case PROFILE_INPLANE:
        return 0.2 * s / 7.0 * w;
    default:
        return 14.5 * (r > 0 ? 1 - r * r + 2 * r * r * log(r) : 1);
    }
}

static double node_x(int i)
{
    return SPACING * i;
}

typedef struct measure {
    double lost[N_BASES][2]; /* [basis][float, double], worst over the profiles */
    double profile_lost[N_PROFILES][N_BASES]; /* float32 */
    double nodal_lost[N_PROFILES];            /* float32, Chebyshev, nodal form */
    double lost_nodal;                        /* worst of them */
    double kappa[N_PROFILES][N_BASES];
    double cond_raw, cond_scaled, cond_norm;
} measure;

/* 2-norm condition number of the GRID x (k+1) design matrix of x^j (raw)
 * or X^j (normalised), optionally with unit-norm columns (as host/numerics/lsq.c
 * factors it). */
static double condition(int k, stab_basis s, int scaled)
{
    double a[GRID * (MAX_ORDER + 1)], sv[MAX_ORDER + 1], superb[MAX_ORDER];
    const int n = k + 1;
    for (int j = 0; j < n; ++j) {
        double norm = 0;
        for (int i = 0; i < GRID; ++i) {
            const double t = stab_coordinate(s, (node_x(i) - STAB_CENTRE) / STAB_HALF);
            a[i + j * GRID] = pow(t, j);
            norm += a[i + j * GRID] * a[i + j * GRID];
        }
        for (int i = 0; scaled && i < GRID; ++i) {
            a[i + j * GRID] /= sqrt(norm);
        }
    }
    if (LAPACKE_dgesvd(LAPACK_COL_MAJOR, 'N', 'N', GRID, n, a, GRID, sv, NULL, 1, NULL, 1,
                       superb) != 0) {
        return NAN;
    }
    return sv[0] / sv[n - 1];
}

/* b[0..k]: the order-k least-squares fit of a profile in X. */
static int fit(int which, int k, double *b)
{
    double a[GRID * (MAX_ORDER + 1)], y[GRID];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    for (int i = 0; i < GRID; ++i) {
        const double t = (node_x(i) - STAB_CENTRE) / STAB_HALF;
        for (int j = 0; j <= k; ++j) {
            a[i + j * GRID] = pow(t, j);
        }
        y[i] = profile(which, node_x(i));
    }
    tf_lsq *f = tf_lsq_factor(&ctx, GRID, (size_t)k + 1, a, GRID, NULL, 0);
    int rc = f == NULL || tf_lsq_solve(&ctx, f, 1, y, GRID, b, (size_t)k + 1, NULL);
    tf_lsq_free(f);
    if (rc != 0) {
        fprintf(stderr, "basis_study: fit of order %d: %s\n", k, ctx.err);
        return -1;
    }
    return 0;
}

/* Relative errors [float, double] of P in basis s, and its kappa; for
 * Chebyshev also the float error of the target's nodal form (*nodal). */
static void errors(stab_basis s, int k, const double *b, double err[2], double *kappa,
                   double *nodal)
{
    long double c[MAX_ORDER + 1];
    float cf[MAX_ORDER + 1];
    double cd[MAX_ORDER + 1];
    stab_convert(s, k, b, c);
    for (int j = 0; j <= k; ++j) {
        cf[j] = (float)c[j];
        cd[j] = (double)c[j];
        if (perturb_exp > 0) {
            cf[j] *= 1.0f + (j % 2 ? -1.0f : 1.0f) * ldexpf(1.0f, -perturb_exp);
        }
    }
    long double bl[MAX_ORDER + 1]; /* P itself, for the reference */
    for (int i = 0; i <= k; ++i) {
        bl[i] = b[i];
    }
    long double worst_f = 0, worst_d = 0, worst_n = 0, size = 0, terms = 0;
    for (int j = -EVAL_STEPS; j <= EVAL_STEPS; ++j) {
        const long double xn = (long double)j / EVAL_STEPS;
        const double t = stab_coordinate(s, (double)xn); /* exact */
        const long double p = stab_eval_long(STAB_NORMALISED, bl, k, xn);
        worst_f = fmaxl(worst_f, fabsl(stab_eval_float(s, cf, k, (float)t) - p));
        worst_d = fmaxl(worst_d, fabsl(stab_eval_double(s, cd, k, t) - p));
        if (s == STAB_CHEBYSHEV) {
            worst_n = fmaxl(worst_n, fabsl(stab_eval_float_nodal(cf, k, (float)t) - p));
        }
        size = fmaxl(size, fabsl(p));
        terms = fmaxl(terms, stab_term_sum(s, c, k, t));
    }
    err[0] = (double)(worst_f / size);
    err[1] = (double)(worst_d / size);
    *nodal = (double)(worst_n / size);
    *kappa = (double)(terms / size);
}

static int study(int k, measure *m)
{
    const double unit[2] = {0x1p-24, 0x1p-53};
    memset(m, 0, sizeof *m);
    for (int s = 0; s < N_BASES; ++s) {
        m->lost[s][0] = m->lost[s][1] = -INFINITY;
    }
    m->lost_nodal = -INFINITY;
    for (int which = 0; which < N_PROFILES; ++which) {
        double b[MAX_ORDER + 1];
        if (fit(which, k, b) != 0) {
            return -1;
        }
        for (int s = 0; s < N_BASES; ++s) {
            double e[2], nodal;
            errors((stab_basis)s, k, b, e, &m->kappa[which][s], &nodal);
            if (s == STAB_CHEBYSHEV) {
                m->nodal_lost[which] = log10(nodal / unit[0]);
                m->lost_nodal = fmax(m->lost_nodal, m->nodal_lost[which]);
            }
            for (int p = 0; p < 2; ++p) {
                m->lost[s][p] = fmax(m->lost[s][p], log10(e[p] / unit[p]));
            }
            m->profile_lost[which][s] = log10(e[0] / unit[0]);
        }
    }
    m->cond_raw = condition(k, STAB_RAW, 0);
    m->cond_scaled = condition(k, STAB_RAW, 1);
    m->cond_norm = condition(k, STAB_NORMALISED, 0);
    return 0;
}

static void print_tables(const measure *ms)
{
    printf("| order | cond raw | cond raw, unit columns | cond normalised | float32 raw "
           "| float32 normalised | float32 Chebyshev (Clenshaw) | float32 Chebyshev (nodal) "
           "| float64 raw | float64 normalised | float64 Chebyshev |\n"
           "|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int k = 1; k <= MAX_ORDER; ++k) {
        const measure *m = &ms[k];
        printf("| %d | %.2g | %.2g | %.2g | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f |\n",
               k, m->cond_raw, m->cond_scaled, m->cond_norm, m->lost[STAB_RAW][0],
               m->lost[STAB_NORMALISED][0], m->lost[STAB_CHEBYSHEV][0], m->lost_nodal,
               m->lost[STAB_RAW][1], m->lost[STAB_NORMALISED][1], m->lost[STAB_CHEBYSHEV][1]);
    }
    printf("\nfloat32 digits lost raw / normalised / Chebyshev Clenshaw / Chebyshev nodal "
           "(kappa raw / normalised / Chebyshev)\n\n| order |");
    for (int w = 0; w < N_PROFILES; ++w) {
        printf(" %s |", profile_names[w]);
    }
    printf("\n|---|---|---|---|\n");
    for (int k = 1; k <= MAX_ORDER; ++k) {
        printf("| %d |", k);
        for (int w = 0; w < N_PROFILES; ++w) {
            const double *l = ms[k].profile_lost[w], *kp = ms[k].kappa[w];
            printf(" %.2f / %.2f / %.2f / %.2f (%.3g / %.3g / %.3g) |", l[STAB_RAW],
                   l[STAB_NORMALISED], l[STAB_CHEBYSHEV], ms[k].nodal_lost[w], kp[STAB_RAW],
                   kp[STAB_NORMALISED], kp[STAB_CHEBYSHEV]);
        }
        printf("\n");
    }
}

static int write_data(const char *path, const measure *ms)
{
    FILE *f = fopen(path, "w");
    if (f == NULL) {
        perror(path);
        return -1;
    }
    fprintf(f, "# order log10(cond raw) log10(cond raw, unit columns) log10(cond normalised) "
               "lost: f32 raw, f32 normalised, f32 Chebyshev, f64 raw, f64 normalised, "
               "f64 Chebyshev, f32 Chebyshev nodal form\n");
    for (int k = 1; k <= MAX_ORDER; ++k) {
        const measure *m = &ms[k];
        fprintf(f, "%d %.4f %.4f %.4f", k, log10(m->cond_raw), log10(m->cond_scaled),
                log10(m->cond_norm));
        for (int p = 0; p < 2; ++p) {
            for (int s = 0; s < N_BASES; ++s) {
                fprintf(f, " %.4f", m->lost[s][p]);
            }
        }
        fprintf(f, " %.4f\n", m->lost_nodal);
    }
    if (fclose(f) != 0) {
        perror(path);
        return -1;
    }
    return 0;
}

static int usage(void)
{
    fprintf(stderr, "usage: basis_study [--accept-order K] [--data FILE] [--perturb E]\n");
    return 2;
}

int main(int argc, char **argv)
{
    tf_blas_pin(argv); /* the fits and condition numbers: same bits everywhere */
    const char *data = NULL;
    int accept = MAX_ORDER;
    for (int a = 1; a < argc; a += 2) {
        if (a + 1 >= argc) {
            return usage();
        } else if (strcmp(argv[a], "--data") == 0) {
            data = argv[a + 1];
        } else if (strcmp(argv[a], "--perturb") == 0) {
            perturb_exp = atoi(argv[a + 1]);
            if (perturb_exp < 1 || perturb_exp > 30) {
                return usage();
            }
        } else if (strcmp(argv[a], "--accept-order") == 0) {
            accept = atoi(argv[a + 1]);
            if (accept < 1 || accept > MAX_ORDER) {
                return usage();
            }
        } else {
            return usage();
        }
    }
    measure ms[MAX_ORDER + 1];
    int failed = 0;
    for (int k = 1; k <= MAX_ORDER; ++k) {
        if (study(k, &ms[k]) != 0) {
            return 1;
        }
        for (int w = 0; k <= accept && w < N_PROFILES; ++w) {
            const double lost[2] = {ms[k].profile_lost[w][STAB_CHEBYSHEV], ms[k].nodal_lost[w]};
            const char *const form[2] = {"Clenshaw (zhou2017)", "nodal"};
            for (int f = 0; f < 2; ++f) {
                if (!(lost[f] < ACCEPT_DIGITS)) {
                    fprintf(stderr, "order %d, %s: the target's Chebyshev basis, %s form, loses "
                            "%.2f digits in float32 (required: < %g)\n", k, profile_names[w],
                            form[f], lost[f], ACCEPT_DIGITS);
                    failed = 1;
                }
            }
        }
    }
    print_tables(ms);
    if (data != NULL && write_data(data, ms) != 0) {
        return 1;
    }
    return failed;
}
