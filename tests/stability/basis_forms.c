/*
 * basis_forms.c — see basis_forms.h.
 */
#include "basis_forms.h"

#include <float.h>
#include <math.h>

#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "the float32 evaluation needs float arithmetic evaluated in float"
#endif
#if LDBL_MANT_DIG < 64
#error "the exact conversions need a long double with at least 64 significand bits"
#endif

/* a_j = 24^-j sum_{i >= j} binom(i, j) (-1)^(i-j) b_i, from X^i = (x/24 - 1)^i. */
static void to_raw(int k, const double *b, long double *a)
{
    for (int j = 0; j <= k; ++j) {
        long double sum = 0, binom = 1; /* binom(i, j), from i = j up */
        for (int i = j; i <= k; ++i) {
            if (i > j) {
                binom = binom * i / (i - j);
            }
            sum += ((i - j) % 2 ? -binom : binom) * (long double)b[i];
        }
        a[j] = sum / powl((long double)STAB_HALF, (long double)j);
    }
}

/* X^n = 2^(1-n) sum_{m <= n/2} binom(n, m) T_(n-2m), the T_0 term halved. */
static void to_chebyshev(int k, const double *b, long double *c)
{
    for (int j = 0; j <= k; ++j) {
        c[j] = 0;
    }
    for (int n = 0; n <= k; ++n) {
        long double binom = 1; /* binom(n, m) */
        for (int m = 0; 2 * m <= n; ++m) {
            if (m > 0) {
                binom = binom * (n - m + 1) / m;
            }
            long double w = ldexpl(binom, 1 - n);
            if (n == 2 * m) {
                w /= 2;
            }
            c[n - 2 * m] += w * (long double)b[n];
        }
    }
}

void stab_convert(stab_basis s, int k, const double *b, long double *out)
{
    if (s == STAB_RAW) {
        to_raw(k, b, out);
    } else if (s == STAB_CHEBYSHEV) {
        to_chebyshev(k, b, out);
    } else {
        for (int j = 0; j <= k; ++j) {
            out[j] = b[j];
        }
    }
}

double stab_coordinate(stab_basis s, double x_normalised)
{
    return s == STAB_RAW ? STAB_CENTRE + STAB_HALF * x_normalised : x_normalised;
}

/* Horner and Clenshaw for one type; T is float, double or long double, and
 * C's rules round every operation to T (FLT_EVAL_METHOD 0, no contraction). */
#define DEFINE_EVAL(NAME, T)                                   \
    static T NAME##_horner(const T *c, int k, T x)             \
    {                                                          \
        T h = c[k];                                            \
        for (int i = k - 1; i >= 0; --i) {                     \
            h = h * x + c[i];                                  \
        }                                                      \
        return h;                                              \
    }                                                          \
    static T NAME##_clenshaw(const T *c, int k, T x)           \
    {                                                          \
        T b1 = 0, b2 = 0;                                      \
        for (int j = k; j >= 1; --j) {                         \
            const T t = c[j] + (x + x) * b1 - b2;              \
            b2 = b1;                                           \
            b1 = t;                                            \
        }                                                      \
        return c[0] + x * b1 - b2;                             \
    }

DEFINE_EVAL(f, float)
DEFINE_EVAL(d, double)
DEFINE_EVAL(ld, long double)

float stab_eval_float(stab_basis s, const float *c, int k, float t)
{
    return s == STAB_CHEBYSHEV ? f_clenshaw(c, k, t) : f_horner(c, k, t);
}

double stab_eval_double(stab_basis s, const double *c, int k, double t)
{
    return s == STAB_CHEBYSHEV ? d_clenshaw(c, k, t) : d_horner(c, k, t);
}

long double stab_eval_long(stab_basis s, const long double *c, int k, long double t)
{
    return s == STAB_CHEBYSHEV ? ld_clenshaw(c, k, t) : ld_horner(c, k, t);
}

long double stab_term_sum(stab_basis s, const long double *c, int k, long double t)
{
    long double sum = 0, prev = 1, cur = t, power = 1; /* T_0, T_1; t^0 */
    for (int j = 0; j <= k; ++j) {
        if (s == STAB_CHEBYSHEV) {
            const long double tj = j == 0 ? 1 : j == 1 ? t : 2 * t * cur - prev;
            if (j >= 2) {
                prev = cur;
                cur = tj;
            }
            sum += fabsl(c[j] * tj);
        } else {
            sum += fabsl(c[j]) * power;
            power *= fabsl(t);
        }
    }
    return sum;
}
