/*
 * invariants_q31.c — the Q31 invariants of invariants.h.  The integer map
 * (docs/q31-format.md §3) is re-read from the table in double: x0h, W and
 * H in q[0..12], then per output row its shift s_o and T(p) coefficients.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "invariants.h"

#define MAP_WORDS TFIT_Q31_MAP_WORDS

static uint32_t terms(uint32_t p)
{
    return (p + 1) * (p + 2) * (p + 3) / 6;
}

/* The first output row: after a prony model's K and terms
 * (q31-format.md §8). */
static const int32_t *first_row(const tfit_model_q31 *m)
{
    return m->family == TFIT_FAMILY_PRONY ? m->q + MAP_WORDS + 1 + 2 * m->q[MAP_WORDS]
                                          : m->q + MAP_WORDS;
}

/* A prony model is evaluated as one tick from rest (its reset state), as
 * the float invariants do from their state. */
tfit_status stab_q31_eval(const stab_q31 *c, const int32_t x[3], int32_t *y)
{
    if (c->m->family == TFIT_FAMILY_PRONY) {
        int32_t state[TFIT_PRONY_Q31_STATE_WORDS(TFIT_PRONY_MAX_TERMS)];
        tfit_prony_reset_q31(c->m, state);
        return tfit_prony_step_q31(c->m, state, x, y);
    }
    if (c->m->family == TFIT_FAMILY_CONTACT) {
        return tfit_contact_force_q31(c->m, x, y);
    }
    return tfit_displacements_q31(c->m, x, y);
}

int32_t stab_q31_word(double v)
{
    if (!(v < 2147483647.0)) { /* NaN saturates high: no caller passes one */
        return INT32_MAX;
    }
    if (v < -2147483648.0) {
        return INT32_MIN;
    }
    return (int32_t)llround(v);
}

/* g in units of the envelope (1 on its boundary) for a difference v from
 * the centre in input words: the map halves the input first (step 1). */
static void map(const stab_q31 *c, const double v[3], double g[3])
{
    for (int i = 0; i < 3; ++i) {
        g[i] = (c->w[3 * i] * v[0] + c->w[3 * i + 1] * v[1] + c->w[3 * i + 2] * v[2]) / 2 /
               0x1p32 / c->unit;
    }
}

static double reach(const stab_q31 *c, const double v[3])
{
    double g[3];
    map(c, v, g);
    return sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
}

void stab_q31_along(const stab_q31 *c, const double v[3], double t, int32_t x[3])
{
    const double s = t / reach(c, v);
    for (int j = 0; j < 3; ++j) {
        x[j] = stab_q31_word(2 * c->x0h[j] + s * v[j]);
    }
}

/* The range proof's bound on each output word (q31-format.md §6):
 * |phi| <= 2^30 + 2^14, so |y_o| <= sum |c_o| (2^30 + 2^14) / 2^s_o,
 * plus one for the rounding. */
static void row_bounds(stab_q31 *c)
{
    const uint32_t t = terms(c->m->degree);
    double largest = 0;
    for (uint32_t o = 0; o < 3 * c->m->n_out; ++o) {
        const int32_t *row = first_row(c->m) + o * (t + 1);
        double sum = 0;
        for (uint32_t k = 0; k < t; ++k) {
            sum += fabs((double)row[1 + k]);
        }
        c->bound[o] = ldexp(sum * (0x1p30 + 0x1p14), -row[0]) + 1;
        largest = c->bound[o] > largest ? c->bound[o] : largest;
    }
    /* Two inputs in the same direction project to points at most
     * 2^(H-29) + 2^-28 apart on the unit sphere: each near-boundary gh
     * rounds by sqrt(3)/2 units of Q(30-H), the boundary word itself by
     * less than a fifth of one, and the projection and the basis round
     * by a few units of Q30.  A Chebyshev row of degree p whose bound is
     * B moves by at most p^2 B per unit of g (Markov: |T_k'| <= k^2 on
     * [-1, 1], and a term T_a T_b T_c moves by a^2 + b^2 + c^2 <= p^2
     * times the largest component's move); each output rounds once. */
    const double p = c->m->degree;
    c->tol = 2 + p * p * largest * (ldexp(1, c->h - 29) + 0x1p-28);
}

int stab_q31_init(stab_q31 *c, const tfit_model_q31 *m, const char *label)
{
    memset(c, 0, sizeof *c);
    c->m = m;
    c->label = label;
    for (int j = 0; j < 3; ++j) {
        c->x0h[j] = m->q[j];
    }
    for (int k = 0; k < 9; ++k) {
        c->w[k] = m->q[3 + k];
    }
    c->h = m->q[12];
    c->unit = ldexp(1, 30 - c->h);
    c->y = malloc(3 * m->n_out * sizeof *c->y);
    c->y_b = malloc(3 * m->n_out * sizeof *c->y_b);
    c->bound = malloc(3 * m->n_out * sizeof *c->bound);
    if (c->y == NULL || c->y_b == NULL || c->bound == NULL) {
        stab_q31_free(c);
        return -1;
    }
    row_bounds(c);
    return 0;
}

void stab_q31_free(stab_q31 *c)
{
    free(c->y);
    free(c->y_b);
    free(c->bound);
    c->y = c->y_b = NULL;
    c->bound = NULL;
}

static int fail(stab_q31 *c, const int32_t x[3], const char *what)
{
    fprintf(stderr, "%s: input {%d, %d, %d}: %s\n", c->label, x[0], x[1], x[2], what);
    c->st.failures++;
    return 1;
}

/* The difference from the centre in input words, as the map sees it: the
 * halved input (floor) minus x0h, doubled back. */
static void offset(const stab_q31 *c, const int32_t x[3], double v[3])
{
    for (int j = 0; j < 3; ++j) {
        v[j] = 2 * (floor(x[j] / 2.0) - c->x0h[j]);
    }
}

double stab_q31_deviation(const stab_q31 *c, const int32_t *y, const int32_t *y_ref)
{
    int64_t dev = 0;
    for (uint32_t o = 0; o < 3 * c->m->n_out; ++o) {
        const int64_t d = llabs((int64_t)y[o] - (int64_t)y_ref[o]);
        dev = d > dev ? d : dev;
    }
    return (double)dev;
}

/* The clamped result against the result at the boundary word in the
 * direction v of the input's offset from the centre. */
static int check_boundary(stab_q31 *c, const int32_t x[3], const double v[3])
{
    int32_t xb[3];
    stab_q31_along(c, v, 1.0, xb);
    stab_q31_eval(c, xb, c->y_b);
    const double dev = stab_q31_deviation(c, c->y, c->y_b);
    if (dev > c->st.worst) {
        c->st.worst = dev;
        memcpy(c->st.worst_in, x, sizeof c->st.worst_in);
    }
    if (!(dev <= c->tol)) {
        char what[160];
        snprintf(what, sizeof what, "clamped result %.0f LSB from the boundary result (tolerance %.3g)",
                 dev, c->tol);
        return fail(c, x, what);
    }
    return 0;
}

int stab_q31_check(stab_q31 *c, const int32_t x[3])
{
    const tfit_status s = stab_q31_eval(c, x, c->y);
    int n = 0;
    c->st.n++;
    for (uint32_t o = 0; o < 3 * c->m->n_out; ++o) {
        if (fabs((double)c->y[o]) > c->bound[o]) {
            n += fail(c, x, "an output word exceeds its row's range-proof bound");
            break;
        }
    }
    double v[3];
    offset(c, x, v);
    const double r = reach(c, v);
    /* gh rounds to the nearest unit of Q(30 - H): |g| moves by at most
     * sqrt(3)/2 units; two units of margin. */
    const double margin = 2 / c->unit;
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
        n += check_boundary(c, x, v);
    } else {
        n += fail(c, x, "an int32 input gave an error status");
    }
    return n;
}
