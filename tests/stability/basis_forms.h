/*
 * basis_forms.h — one polynomial in three 1-D bases, for the basis
 * conditioning study (basis_study.c):
 *
 *   raw         P = sum a_j x^j, x in millimetres, [0, 48] (seed 000's form)
 *   normalised  P = sum b_j X^j, X = (x - 24) / 24 in [-1, 1] (tissuefit's)
 *   Chebyshev   P = sum c_j T_j(X), the target's basis since API version 3
 *
 * The polynomial is defined by its normalised coefficients b (doubles); the
 * others are exact conversions carried out in long double (64-bit
 * significand or more), so their own error (~2^-60 relative) is far below
 * the float64 rounding of the coefficients they are rounded to.
 */
#ifndef STAB_BASIS_FORMS_H
#define STAB_BASIS_FORMS_H

#define STAB_MAX_ORDER 8
#define STAB_CENTRE 24.0 /* mm: X = (x - STAB_CENTRE) / STAB_HALF */
#define STAB_HALF 24.0

typedef enum stab_basis { STAB_RAW, STAB_NORMALISED, STAB_CHEBYSHEV, STAB_N_BASES } stab_basis;

/* Coefficients of the order-k polynomial with normalised coefficients b
 * in basis s (for STAB_NORMALISED: b itself). */
void stab_convert(stab_basis s, int k, const double *b, long double *out);

/* The basis' own coordinate at X: x in mm for raw, X otherwise. */
double stab_coordinate(stab_basis s, double x_normalised);

/* Evaluation of order-k coefficients c in basis s at coordinate t, every
 * operation rounded to the type: Horner for the monomial bases (as the
 * target's API-2 tfit_horner), Clenshaw's recurrence for Chebyshev.  In
 * float the Chebyshev series is evaluated by the target's own code
 * (tfit_cheb, target/src/tfit_internal.h: zhou2017's form). */
float stab_eval_float(stab_basis s, const float *c, int k, float t);

/* The same Chebyshev series in the target's nodal form: tfit_basis() at
 * g = (t, 0, 0), then the row sum (tfit_row) over every term of degree
 * <= k, the coefficients of T_j(g0) at their places and zeros elsewhere. */
float stab_eval_float_nodal(const float *c, int k, float t);
double stab_eval_double(stab_basis s, const double *c, int k, double t);
long double stab_eval_long(stab_basis s, const long double *c, int k, long double t);

/* Evaluation condition number at t: sum |c_j| |basis_j(t)|, the size of
 * the terms the evaluation adds up (|T_j| <= 1 on [-1, 1]). */
long double stab_term_sum(stab_basis s, const long double *c, int k, long double t);

#endif /* STAB_BASIS_FORMS_H */
