/*
 * invariants_float.c — the float32 invariants of invariants.h.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "invariants.h"

#define U ((double)FLT_EPSILON / 2) /* unit roundoff of float */

static uint32_t bits(float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static int finite_bits(float x)
{
    return (bits(x) & 0x7f800000u) != 0x7f800000u;
}

tfit_status stab_float_eval(const stab_float *c, const float x[3], float *y)
{
    if (c->m->family == TFIT_FAMILY_CONTACT) {
        return tfit_contact_force(c->m, x, y);
    }
    return tfit_displacements(c->m, x, y);
}

/* |W v|: the input offset v / |W v| reaches the boundary. */
static double reach(const stab_float *c, const double v[3])
{
    double s = 0;
    for (int i = 0; i < 3; ++i) {
        double gi = c->w[3 * i] * v[0] + c->w[3 * i + 1] * v[1] + c->w[3 * i + 2] * v[2];
        s += gi * gi;
    }
    return sqrt(s);
}

/* max(a, b) that keeps a NaN from either side (fmax would drop it). */
static double max_nan(double a, double b)
{
    return isnan(a) || a >= b ? a : b;
}

static double inf_norm(const float *y, uint32_t n)
{
    double a = 0;
    for (uint32_t o = 0; o < n; ++o) {
        a = max_nan(a, fabs((double)y[o]));
    }
    return a;
}

double stab_float_deviation(const stab_float *c, const float *y, const float *y_ref)
{
    double dev = 0;
    const uint32_t n = 3 * c->m->n_out;
    for (uint32_t o = 0; o < n; ++o) {
        dev = max_nan(dev, fabs((double)y[o] - (double)y_ref[o]));
    }
    return dev / (FLT_EPSILON * fmax(c->scale, inf_norm(y_ref, n)));
}

void stab_float_along(const stab_float *c, const double v[3], double t, float x[3])
{
    double s = t / reach(c, v);
    const double big = fmax(fmax(fabs(v[0]), fabs(v[1])), fabs(v[2])) * s;
    if (big > FLT_MAX / 2) {
        s *= FLT_MAX / 2 / big;
    }
    for (int j = 0; j < 3; ++j) {
        x[j] = (float)(c->x0[j] + s * v[j]);
    }
}

void stab_cube_direction(int i, double v[3])
{
    const int k = i < 13 ? i : i + 1; /* skip the centre (1, 1, 1) */
    v[0] = k % 3 - 1;
    v[1] = k / 3 % 3 - 1;
    v[2] = k / 9 - 1;
}

/* The model's output magnitude on its envelope: the largest |output| on
 * the boundary in the 26 cube directions.  Deviations are counted in ulps
 * of this or of the reference result's own magnitude, whichever is larger:
 * the reference alone would make a deviation look large wherever outputs
 * happen to cancel, the model scale alone where they are much larger than
 * in the cube directions. */
static double boundary_scale(stab_float *c)
{
    double s = 0;
    for (int i = 0; i < 26; ++i) {
        double v[3];
        float x[3];
        stab_cube_direction(i, v);
        stab_float_along(c, v, 1.0, x);
        stab_float_eval(c, x, c->y);
        s = max_nan(s, inf_norm(c->y, 3 * c->m->n_out));
    }
    return s > 0 ? s : FLT_MIN;
}

/* The model's own sensitivity at x (whose result is y): the largest
 * deviation, in ulps, that moving one input component by one ulp causes. */
static double local_sensitivity(stab_float *c, const float x[3], const float *y)
{
    double worst = 0;
    for (int j = 0; j < 6; ++j) {
        float xn[3] = {x[0], x[1], x[2]};
        xn[j / 2] = nextafterf(xn[j / 2], j % 2 ? INFINITY : -INFINITY);
        stab_float_eval(c, xn, c->y_n);
        worst = max_nan(worst, stab_float_deviation(c, c->y_n, y));
    }
    return worst;
}

int stab_float_init(stab_float *c, const tfit_model *m, const char *label)
{
    memset(c, 0, sizeof *c);
    c->m = m;
    c->label = label;
    for (int j = 0; j < 3; ++j) {
        c->x0[j] = m->coef[j];
    }
    for (int k = 0; k < 9; ++k) {
        c->w[k] = m->coef[3 + k];
    }
    c->y = malloc(3 * m->n_out * sizeof *c->y);
    c->y_b = malloc(3 * m->n_out * sizeof *c->y_b);
    c->y_n = malloc(3 * m->n_out * sizeof *c->y_n);
    if (c->y == NULL || c->y_b == NULL || c->y_n == NULL) {
        stab_float_free(c);
        return -1;
    }
    c->scale = boundary_scale(c);
    return 0;
}

void stab_float_free(stab_float *c)
{
    free(c->y);
    free(c->y_b);
    free(c->y_n);
    c->y = c->y_b = c->y_n = NULL;
}

static int fail(stab_float *c, const float x[3], const char *what)
{
    fprintf(stderr, "%s: input {%a, %a, %a} (bits %08x %08x %08x): %s\n", c->label, (double)x[0],
            (double)x[1], (double)x[2], bits(x[0]), bits(x[1]), bits(x[2]), what);
    c->st.failures++;
    return 1;
}

/* NaN/Inf input: TFIT_ERR_INPUT and +0.0f in every word. */
static int check_bad(stab_float *c, const float x[3], tfit_status s)
{
    int n = 0;
    c->st.bad_input++;
    if (s != TFIT_ERR_INPUT) {
        n += fail(c, x, "NaN/Inf input did not give TFIT_ERR_INPUT");
    }
    for (uint32_t o = 0; o < 3 * c->m->n_out; ++o) {
        if (bits(c->y[o]) != 0) {
            n += fail(c, x, "NaN/Inf input left an output word that is not +0.0f");
            break;
        }
    }
    return n;
}

/* Where x lies: |W (x - x0)| in double (its own error, ~1e-16 relative, is
 * negligible here) and a bound on how far the float map's rounding can
 * move it: d = x - x0 rounds once, each row of W d rounds three times,
 * the squared norm three times more; 8 u per term covers all of it. */
static double where(const stab_float *c, const float x[3], double *margin)
{
    double d[3], s = 0, a2 = 0;
    for (int j = 0; j < 3; ++j) {
        d[j] = (double)x[j] - c->x0[j];
    }
    for (int i = 0; i < 3; ++i) {
        double g = 0, a = 0;
        for (int j = 0; j < 3; ++j) {
            g += c->w[3 * i + j] * d[j];
            a += fabs(c->w[3 * i + j]) * (fabs((double)x[j]) + fabs(c->x0[j]));
        }
        s += g * g;
        a2 += a * a;
    }
    *margin = 8 * U * (sqrt(a2) + 1);
    return sqrt(s);
}

/* The clamped result against the result at x0 + (x - x0) / |W (x - x0)|: within
 * STAB_FLOAT_TOL_ULPS, or else within STAB_FLOAT_TOL_SENSITIVITY times what
 * one ulp of the boundary input itself changes (an ill-conditioned model:
 * the two inputs' roundings put their projections a few such steps apart). */
static int check_boundary(stab_float *c, const float x[3])
{
    const double d[3] = {(double)x[0] - c->x0[0], (double)x[1] - c->x0[1],
                         (double)x[2] - c->x0[2]};
    float xb[3];
    stab_float_along(c, d, 1.0, xb);
    stab_float_eval(c, xb, c->y_b);
    const double dev = stab_float_deviation(c, c->y, c->y_b);
    if (dev > c->st.worst) {
        c->st.worst = dev;
        for (int j = 0; j < 3; ++j) {
            c->st.worst_in[j] = bits(x[j]);
        }
    }
    if (dev <= STAB_FLOAT_TOL_ULPS) {
        return 0;
    }
    const double sens = local_sensitivity(c, xb, c->y_b);
    if (dev <= STAB_FLOAT_TOL_SENSITIVITY * sens) {
        c->st.sensitive++;
        return 0;
    }
    char what[200];
    snprintf(what, sizeof what,
             "clamped result %.3g ulps from the boundary result (tolerance %g, or %g x the "
             "sensitivity there, %.3g ulps per input ulp)",
             dev, STAB_FLOAT_TOL_ULPS, STAB_FLOAT_TOL_SENSITIVITY, sens);
    return fail(c, x, what);
}

int stab_float_check(stab_float *c, const float x[3])
{
    const tfit_status s = stab_float_eval(c, x, c->y);
    int n = 0;
    c->st.n++;
    for (uint32_t o = 0; o < 3 * c->m->n_out; ++o) {
        if (!finite_bits(c->y[o])) {
            n += fail(c, x, "an output is NaN or Inf");
            break;
        }
    }
    if (!finite_bits(x[0]) || !finite_bits(x[1]) || !finite_bits(x[2])) {
        return n + check_bad(c, x, s);
    }
    double margin;
    const double r = where(c, x, &margin);
    if (s == TFIT_OK) {
        c->st.ok++;
        if (r > 1 + margin) {
            n += fail(c, x, "TFIT_OK outside the envelope");
        }
    } else if (s == TFIT_CLAMPED) {
        c->st.clamped++;
        if (r < 1 - margin) {
            n += fail(c, x, "TFIT_CLAMPED inside the envelope");
        }
        n += check_boundary(c, x);
    } else {
        n += fail(c, x, "finite input gave an error status");
    }
    return n;
}
