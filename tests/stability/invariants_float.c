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

double stab_float_reach(const stab_float *c, const double v[3])
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
    for (uint32_t o = 0; o < 3 * c->m->n_out; ++o) {
        dev = max_nan(dev, fabs((double)y[o] - (double)y_ref[o]));
    }
    return dev / (FLT_EPSILON * c->scale);
}

/* The output magnitude the ulps are counted in: the largest |output| at
 * the boundary points x0 + v / |W v| for the 26 directions v to a cube's
 * faces, edges and corners.  A per-comparison |y_b| would make a deviation
 * look large wherever the outputs happen to cancel; this is the scale of
 * the model's outputs on its envelope. */
static double boundary_scale(stab_float *c)
{
    double s = 0;
    for (int a = -1; a <= 1; ++a) {
        for (int b = -1; b <= 1; ++b) {
            for (int d = -1; d <= 1; ++d) {
                const double v[3] = {a, b, d};
                double r = stab_float_reach(c, v);
                if (r == 0) {
                    continue;
                }
                float x[3];
                for (int j = 0; j < 3; ++j) {
                    x[j] = (float)(c->x0[j] + v[j] / r);
                }
                stab_float_eval(c, x, c->y);
                s = max_nan(s, inf_norm(c->y, 3 * c->m->n_out));
            }
        }
    }
    return s > 0 ? s : FLT_MIN;
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
    if (c->y == NULL || c->y_b == NULL) {
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
    c->y = c->y_b = NULL;
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

/* The clamped result against the result at x0 + (x - x0) / r. */
static int check_boundary(stab_float *c, const float x[3], double r)
{
    float xb[3];
    for (int j = 0; j < 3; ++j) {
        xb[j] = (float)(c->x0[j] + ((double)x[j] - c->x0[j]) / r);
    }
    stab_float_eval(c, xb, c->y_b);
    const double dev = stab_float_deviation(c, c->y, c->y_b);
    if (dev > c->st.worst) {
        c->st.worst = dev;
        for (int j = 0; j < 3; ++j) {
            c->st.worst_in[j] = bits(x[j]);
        }
    }
    if (!(dev <= STAB_FLOAT_TOL_ULPS)) {
        char what[160];
        snprintf(what, sizeof what, "clamped result %.3g ulps from the boundary result (tolerance %g)",
                 dev, STAB_FLOAT_TOL_ULPS);
        return fail(c, x, what);
    }
    return 0;
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
        n += check_boundary(c, x, r);
    } else {
        n += fail(c, x, "finite input gave an error status");
    }
    return n;
}
