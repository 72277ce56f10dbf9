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

/* A prony model is evaluated as one tick from c->state, on a copy (the
 * state is the same for the input and its boundary point, so every
 * invariant below holds as for a stateless model); stab_float_check then
 * advances c->state with the checked input. */
static tfit_status eval_entry(const stab_float *c, const tfit_model *m, const float x[3], float *y)
{
    if (m->family == TFIT_FAMILY_PRONY || m->family == TFIT_FAMILY_RESONANT) {
        float state[sizeof c->state / sizeof c->state[0]];
        memcpy(state, c->state, sizeof state);
        return m->family == TFIT_FAMILY_PRONY ? tfit_prony_step(m, state, x, y)
                                              : tfit_resonant_step(m, state, x, y);
    }
    if (m->family == TFIT_FAMILY_CUT) { /* halfway along the incision */
        return tfit_displacements_cut(m, x, 0.5f, y);
    }
    if (m->family == TFIT_FAMILY_CONTACT) {
        return tfit_contact_force(m, x, y);
    }
    return tfit_displacements(m, x, y);
}

tfit_status stab_float_eval(const stab_float *c, const float x[3], float *y)
{
    return eval_entry(c, c->m, x, y);
}

/* The model's result at the projected point g itself (c->in_g). */
static void stab_float_eval_g(const stab_float *c, const float g[3], float *y)
{
    eval_entry(c, &c->in_g, g, y);
}

/* g = W v in double; returns |W v|. */
static double apply_w(const stab_float *c, const double v[3], double g[3])
{
    double s = 0;
    for (int i = 0; i < 3; ++i) {
        g[i] = c->w[3 * i] * v[0] + c->w[3 * i + 1] * v[1] + c->w[3 * i + 2] * v[2];
        s += g[i] * g[i];
    }
    return sqrt(s);
}

/* |W v|: the input offset v / |W v| reaches the boundary. */
static double reach(const stab_float *c, const double v[3])
{
    double g[3];
    return apply_w(c, v, g);
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

/* The model's slope in g at the boundary point u (|u| = 1), in ulps of
 * output per unit of g, as a 2-norm over the three components: for each
 * component the larger one-sided difference, step h, around the point
 * (1 - 2h) u, so that every probe stays inside the ball and is evaluated
 * unprojected.  |y(g) - y(g')| <= slope |g - g'| to first order. */
static double slope_in_g(stab_float *c, const double u[3])
{
    const double h = STAB_FLOAT_G_STEP;
    float gc[3];
    for (int i = 0; i < 3; ++i) {
        gc[i] = (float)((1 - 2 * h) * u[i]);
    }
    stab_float_eval_g(c, gc, c->y_g);
    double s2 = 0;
    for (int i = 0; i < 3; ++i) {
        double d = 0;
        for (int side = -1; side <= 1; side += 2) {
            float gn[3] = {gc[0], gc[1], gc[2]};
            gn[i] = (float)((double)gn[i] + side * h);
            stab_float_eval_g(c, gn, c->y_n);
            d = max_nan(d, stab_float_deviation(c, c->y_n, c->y_g) / h);
        }
        s2 += d * d;
    }
    return sqrt(s2);
}

/* How far apart, in g (2-norm), the clamped input x and the boundary input
 * xb can land after the target's projection; both should land on u =
 * W d / |W d|, d = x - x0.  For each path, first-order bounds in the unit
 * roundoff U:
 *   clamped   the target scales x by a power of two sigma (step 3, exact
 *             but for an underflow of at most 2^-150), forms d' = x sigma -
 *             x0 (one rounding) and W d' (two more): each component is off
 *             by at most 3 U sum_j |W_ij| (|x_j sigma| + |x0_j|) plus the
 *             direction change (sigma - 1) W x0 that scaling x alone
 *             makes; dividing by |g| = |W d'| turns this into a distance
 *             on the sphere (v / |v| is 1/|v|-Lipschitz);
 *   boundary  xb is x0 + d / |W d| rounded to float (U |xb_j| per
 *             component), then the same three roundings, and |W (xb_exact
 *             - x0)| = 1; when the rounded point lies outside, its
 *             projection onto the ball is non-expansive;
 *   both      the normalisation g / |g| adds at most NORMALISE_U units:
 *             the squared norm rounds three times (1.5 U on 1/|g|), the
 *             last Newton step y (3 - s y y) / 2 about three (its earlier
 *             errors are squared away), the product by y once; measured on
 *             the target's projection with the identity map, 3.8 U at most
 *             over 5e7 random points outside the ball. */
#define NORMALISE_U 6.0

/* One path's bound before normalising, component by component, as a
 * 2-norm: `roundings` units on sum_j |W_ij| (|x_j sigma| + |x0_j|) (3 for
 * the clamped input; 4 for the boundary input, whose own rounding to float
 * is one more), and the scaling's direction change (sigma = 1 for the
 * boundary input, which the target never scales). */
static double map_error(const stab_float *c, const double x[3], double sigma, double roundings)
{
    double e2 = 0;
    for (int i = 0; i < 3; ++i) {
        double a = 0, b = 0;
        for (int j = 0; j < 3; ++j) {
            a += fabs(c->w[3 * i + j]) * (fabs(x[j] * sigma) + fabs(c->x0[j]) + 0x1p-150);
            b += c->w[3 * i + j] * c->x0[j];
        }
        const double e = roundings * U * a + fabs(sigma - 1) * fabs(b);
        e2 += e * e;
    }
    return sqrt(e2);
}

/* The power of two the target's step 3 applies to x (1 up to 2^64). */
static double input_scale(const float x[3])
{
    const double big = fmax(fmax(fabs((double)x[0]), fabs((double)x[1])), fabs((double)x[2]));
    int e;
    frexp(big, &e); /* big in [2^(e-1), 2^e) */
    return big > 0x1p64 ? ldexp(1.0, 65 - e) : 1.0;
}

static double projection_gap(const stab_float *c, const float x[3], const float xb[3])
{
    const double sigma = input_scale(x);
    double xs[3], xbd[3], d[3];
    for (int j = 0; j < 3; ++j) {
        xs[j] = (double)x[j];
        xbd[j] = (double)xb[j];
        d[j] = xs[j] * sigma - c->x0[j];
    }
    const double clamped = map_error(c, xs, sigma, 3) / reach(c, d);
    const double boundary = map_error(c, xbd, 1.0, 4);
    return clamped + boundary + 2 * NORMALISE_U * U;
}

/* Beyond STAB_FLOAT_TOL_ULPS, the deviation the projection can explain at
 * this input: the gap in g times the slope in g (invariants.h). */
static double projection_allowance(stab_float *c, const float x[3], const float xb[3])
{
    const double d[3] = {(double)x[0] - c->x0[0], (double)x[1] - c->x0[1],
                         (double)x[2] - c->x0[2]};
    double u[3];
    const double n = apply_w(c, d, u);
    for (int i = 0; i < 3; ++i) {
        u[i] /= n;
    }
    return STAB_FLOAT_SLOPE_SAFETY * slope_in_g(c, u) * projection_gap(c, x, xb);
}

/* A modal_q15 model's outputs are integer sums of its truncated amplitudes
 * times S (header-format.md section 5.9): the clamped input and the
 * boundary input, a projection's rounding apart, may truncate an amplitude
 * to neighbouring integers, a step of S |q[o][k]| in output o.  The largest
 * such step of an output with every amplitude moved by one, in the ulps of
 * stab_float_deviation (over the envelope's scale, which the deviation's
 * own denominator is never below).  0 for every other family. */
static double q15_quantum(const stab_float *c)
{
    const tfit_model *m = c->m;
    if (m->family != TFIT_FAMILY_MODAL_Q15) {
        return 0;
    }
    const uint32_t p = m->dims[0], n_terms = (p + 1) * (p + 2) * (p + 3) / 6; /* monomials */
    const float s = m->coef[TFIT_INPUT_MAP_FLOATS + TFIT_MODAL_Q15_RANK * (n_terms + 1)];
    const float *rows = m->coef + (m->n_coef - 3u * TFIT_MODAL_Q15_WORDS * m->n_out);
    double worst = 0;
    for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
        double sum = 0;
        for (uint32_t j = 0; j < TFIT_MODAL_Q15_WORDS; ++j) {
            const uint32_t w = bits(rows[TFIT_MODAL_Q15_WORDS * o + j]);
            sum += fabs((double)(int16_t)(w & 0xffffu)) +
                   fabs((double)(int16_t)(w >> 16) - 16384.0);
        }
        worst = fmax(worst, sum);
    }
    return worst * fabs((double)s) / (FLT_EPSILON * c->scale);
}

/* A modal_q15 model whose amplitude bound B_k |v_k| exceeds the 14-bit
 * range (B_k = sum_t |At[t][k]|, header-format.md section 5.9) can saturate
 * inside its envelope, which no fit of the host does (it picks S so that
 * none can).  Such a model (the random test models that exercise SSAT) is
 * steep on scales far below the slope probe's step: the clamped result,
 * its input rounded 1e-7 from the boundary's, may sit tens of truncation
 * steps away.  Its boundary continuity is not asserted; every other
 * invariant is. */
static int q15_saturates(const tfit_model *m)
{
    if (m->family != TFIT_FAMILY_MODAL_Q15) {
        return 0;
    }
    const uint32_t p = m->dims[0], n_terms = (p + 1) * (p + 2) * (p + 3) / 6;
    const float *at = m->coef + TFIT_INPUT_MAP_FLOATS, *v = at + TFIT_MODAL_Q15_RANK * n_terms;
    for (uint32_t k = 0; k < TFIT_MODAL_Q15_RANK; ++k) {
        double b = 0;
        for (uint32_t t = 0; t < n_terms; ++t) {
            b += fabs((double)at[t * TFIT_MODAL_Q15_RANK + k]);
        }
        if (b * fabs((double)v[k]) > 8191.0) {
            return 1;
        }
    }
    return 0;
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
    c->y_g = malloc(3 * m->n_out * sizeof *c->y_g);
    c->coef_g = malloc(m->n_coef * sizeof *c->coef_g);
    if (c->y == NULL || c->y_b == NULL || c->y_n == NULL || c->y_g == NULL || c->coef_g == NULL) {
        stab_float_free(c);
        return -1;
    }
    memcpy(c->coef_g, m->coef, m->n_coef * sizeof *c->coef_g);
    for (int k = 0; k < 12; ++k) { /* x0 = 0, W = I */
        c->coef_g[k] = (k >= 3 && (k - 3) % 4 == 0) ? 1.0f : 0.0f;
    }
    c->in_g = *m;
    c->in_g.coef = c->coef_g;
    if (m->family == TFIT_FAMILY_PRONY) {
        tfit_prony_reset(m, c->state);
    } else if (m->family == TFIT_FAMILY_RESONANT) {
        tfit_resonant_reset(m, c->state);
    }
    c->scale = boundary_scale(c);
    c->quantum = q15_quantum(c);
    c->saturates = q15_saturates(m);
    return 0;
}

void stab_float_free(stab_float *c)
{
    free(c->y);
    free(c->y_b);
    free(c->y_n);
    free(c->y_g);
    free(c->coef_g);
    c->y = c->y_b = c->y_n = c->y_g = NULL;
    c->coef_g = NULL;
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
 * STAB_FLOAT_TOL_ULPS, or else within that plus the projection allowance
 * (a model steep at its boundary: the two inputs' roundings put their
 * projected points slightly apart, invariants.h). */
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
    if (c->saturates) {
        c->st.unasserted++;
        return 0;
    }
    const double allow = projection_allowance(c, x, xb) + c->quantum;
    c->st.worst_ratio = max_nan(c->st.worst_ratio, dev / (STAB_FLOAT_TOL_ULPS + allow));
    if (dev <= STAB_FLOAT_TOL_ULPS + allow) {
        c->st.sensitive++;
        return 0;
    }
    char what[200];
    snprintf(what, sizeof what,
             "clamped result %.3g ulps from the boundary result (tolerance %g + the "
             "projection allowance there and any Q15 truncation step, %.3g)",
             dev, STAB_FLOAT_TOL_ULPS, allow);
    return fail(c, x, what);
}

static int check_one(stab_float *c, const float x[3]);

int stab_float_check(stab_float *c, const float x[3])
{
    const int n = check_one(c, x);
    const int prony = c->m->family == TFIT_FAMILY_PRONY;
    if (prony || c->m->family == TFIT_FAMILY_RESONANT) { /* the next input meets the state this one leaves */
        const uint32_t words = prony ? TFIT_PRONY_STATE_WORDS(c->m->dims[2])
                                     : TFIT_RESONANT_STATE_WORDS(c->m->dims[2]);
        if (prony) {
            tfit_prony_step(c->m, c->state, x, c->y);
        } else {
            tfit_resonant_step(c->m, c->state, x, c->y);
        }
        for (uint32_t w = 0; w < words; ++w) {
            if (!finite_bits(c->state[w])) {
                return n + fail(c, x, "a state word is NaN or Inf");
            }
        }
    }
    return n;
}

static int check_one(stab_float *c, const float x[3])
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
