/*
 * invariants.h — the output invariants of issue 7 ("stability at the
 * extremes"), checked on one input at a time through the public target API,
 * for a float32 model (tfit.h) or its Q31 form (tfit_q31.h):
 *
 *   float  every output is finite (a prony model's state too: each input is
 *          a tick from the state the inputs before it left); a NaN/Inf input gives TFIT_ERR_INPUT and
 *          +0.0f in every output word; a finite input gives TFIT_OK inside
 *          the envelope and TFIT_CLAMPED outside it (the status is predicted
 *          from x0 and W in double, with a margin for float rounding); a
 *          clamped result equals the result at the boundary point in the
 *          same direction, x0 + (x - x0) / |W (x - x0)|, within a tolerance
 *          in ulps of the output magnitude (below).
 *   Q31    every int32 input is valid: TFIT_OK inside, TFIT_CLAMPED
 *          outside (predicted from the integer table, with a margin for
 *          the rounding of gh); every output word within its row's bound
 *          from the range proof (q31-format.md §6); a clamped result
 *          equals the result at the boundary word in the same direction
 *          within a tolerance in output words (LSB) that follows from the
 *          projection's resolution: gh has 30 - H fractional bits, so the
 *          two projected points may differ by about 2^(H - 30) in g, and an
 *          output by its sensitivity to g times that (stab_q31_init).
 *
 * A violation prints the model, the input bits and what failed, and is
 * counted; the worst clamped-vs-boundary deviation is kept, with its input,
 * so that a test can report the measured worst case beside its tolerance.
 */
#ifndef STAB_INVARIANTS_H
#define STAB_INVARIANTS_H

#include <stdint.h>

#include "tfit.h"
#include "tfit_q31.h"

/* Clamped against boundary, float: |y - y_b|_inf <= STAB_FLOAT_TOL_ULPS
 * ulps (FLT_EPSILON) of the output magnitude (the larger of |y_b|_inf and
 * the largest |output| at 26 boundary points) plus, for a model steep at
 * its boundary, the projection allowance: the bound on how far apart the
 * two inputs' projected points g can lie (the rounding of W (x - x0), of
 * the boundary input itself and of g / |g|, invariants_float.c) times the
 * model's slope in g there, measured by one-sided differences in g with
 * step STAB_FLOAT_G_STEP, and times STAB_FLOAT_SLOPE_SAFETY for the
 * curvature over that step.  Both are first-order error bounds; nothing in
 * them is fitted to the observed deviations. */
#define STAB_FLOAT_TOL_ULPS 64.0
#define STAB_FLOAT_G_STEP 0x1p-12
#define STAB_FLOAT_SLOPE_SAFETY 2.0

typedef struct stab_stats {
    uint64_t n;        /* inputs checked */
    uint64_t ok, clamped, bad_input;
    uint64_t failures; /* invariant violations */
    uint64_t sensitive; /* float clamps beyond STAB_FLOAT_TOL_ULPS, within the projection allowance */
    uint64_t unasserted; /* float clamps beyond it of a saturating modal_q15 (not asserted) */
    double worst;      /* largest deviation: ulps (float) or LSB (Q31) */
    double worst_ratio; /* float, beyond STAB_FLOAT_TOL_ULPS: largest deviation / (that + allowance) */
    uint32_t worst_in[3]; /* its input (float bits or int32 words) */
} stab_stats;

/* A float32 model under test; y, y_b, y_n, y_g are work arrays of 3 n_out.
 * in_g is m with the identity input map (x0 = 0, W = I): evaluated at g,
 * it gives the model's result at the projected point g, which is how the
 * slope in g is measured. */
typedef struct stab_float {
    const tfit_model *m;
    const char *label;
    double x0[3], w[9]; /* the input map, from coef[0..11] */
    double scale;       /* output magnitude on the envelope (see above) */
    double quantum;     /* modal_q15: ulps one truncation step of every amplitude can move an output */
    int saturates;      /* modal_q15 whose amplitudes can saturate inside the envelope */
    float *y, *y_b, *y_n, *y_g;
    tfit_model in_g;
    float *coef_g;      /* in_g's coefficients */
    float state[TFIT_PRONY_MAX_STATE > TFIT_RESONANT_MAX_STATE ? TFIT_PRONY_MAX_STATE
                                                              : TFIT_RESONANT_MAX_STATE]; /* a prony (or resonant) model's: every input is one tick from
                                        * it, and stab_float_check advances it */
    stab_stats st;
} stab_float;

typedef struct stab_q31 {
    const tfit_model_q31 *m;
    const char *label;
    double x0h[3], w[9]; /* the integer input map */
    int h;               /* headroom H */
    double unit;         /* |g| in Q(30 - H) that is 1: 2^(30 - H) */
    int32_t *y, *y_b;
    double *bound;       /* per output word: the range proof's bound */
    double tol;          /* clamped against boundary, LSB */
    stab_stats st;
} stab_q31;

/* Sets up c for m (allocates the work arrays); 0, or -1 out of memory.
 * Measures the float scale on the envelope boundary; derives the Q31
 * tolerance 2 + p^2 B (2^(H - 29) + 2^-28) LSB, B the largest row bound,
 * p the degree (p^2 B bounds a Chebyshev row's change per unit change of
 * g, by Markov's inequality). */
int stab_float_init(stab_float *c, const tfit_model *m, const char *label);
int stab_q31_init(stab_q31 *c, const tfit_model_q31 *m, const char *label);
void stab_float_free(stab_float *c);
void stab_q31_free(stab_q31 *c);

/* Evaluates x through the model's entry point (tfit_displacements or
 * tfit_contact_force; the Q31 ones likewise) into y. */
tfit_status stab_float_eval(const stab_float *c, const float x[3], float *y);
tfit_status stab_q31_eval(const stab_q31 *c, const int32_t x[3], int32_t *y);

/* Largest |y - y_ref| over the outputs: float in ulps (FLT_EPSILON) of
 * the larger of c->scale and |y_ref|_inf (NaN when an output is NaN), Q31
 * in output words. */
double stab_float_deviation(const stab_float *c, const float *y, const float *y_ref);
double stab_q31_deviation(const stab_q31 *c, const int32_t *y, const int32_t *y_ref);

/* Checks every invariant for input x; returns the number of violations. */
int stab_float_check(stab_float *c, const float x[3]);
int stab_q31_check(stab_q31 *c, const int32_t x[3]);

/* The input at t times the envelope's extent from its centre in the
 * direction v (float: input units; Q31: input words; t = 1: on the
 * boundary).  Float stops where a component would pass FLT_MAX / 2; Q31
 * saturates each word (stab_q31_word). */
void stab_float_along(const stab_float *c, const double v[3], double t, float x[3]);
void stab_q31_along(const stab_q31 *c, const double v[3], double t, int32_t x[3]);

/* Direction i = 0..25 of the 26 from a cube's centre to its faces, edges
 * and corners (components -1, 0, 1). */
void stab_cube_direction(int i, double v[3]);

/* The input word nearest to the real value v (words of the int32 input),
 * saturated at the int32 limits: the conversion q31-format.md §2 asks the
 * firmware to make. */
int32_t stab_q31_word(double v);

/* Prints one line: label, counts, worst deviation against its tolerance,
 * the input that gave it (int32 words when q31, else float bits), and the
 * processor time the checks took. */
void stab_print(int q31, const char *label, const stab_stats *st, double tol, double seconds);

#endif /* STAB_INVARIANTS_H */
