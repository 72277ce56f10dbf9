/*
 * basis_forms.c — see basis_forms.h.
 */
#include "basis_forms.h"

#include <float.h>
#include <math.h>

#include "../../target/src/tfit_internal.h" /* tfit_cheb: the target's own Clenshaw */

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
 * C's rules round every operation to T (FLT_EVAL_METHOD 0, no contraction).
 * Clenshaw follows docs/header-format.md §5.4's order (b_k = ((2x b_{k+1})
 * - b_{k+2}) + c_k, result ((x b_1) - b_2) + c_0) so that the double
 * column measures the same algorithm; float32 does not use it but the
 * target's tfit_cheb itself (stab_eval_float). */
#define DEFINE_HORNER(NAME, T)                                 \
    static T NAME##_horner(const T *c, int k, T x)             \
    {                                                          \
        T h = c[k];                                            \
        for (int i = k - 1; i >= 0; --i) {                     \
            h = h * x + c[i];                                  \
        }                                                      \
        return h;                                              \
    }
#define DEFINE_CLENSHAW(NAME, T)                               \
    static T NAME##_clenshaw(const T *c, int k, T x)           \
    {                                                          \
        T b1 = 0, b2 = 0;                                      \
        for (int j = k; j >= 1; --j) {                         \
            const T t = ((x + x) * b1 - b2) + c[j];            \
            b2 = b1;                                           \
            b1 = t;                                            \
        }                                                      \
        return (x * b1 - b2) + c[0];                           \
    }

DEFINE_HORNER(f, float)
DEFINE_HORNER(d, double)
DEFINE_HORNER(ld, long double)
DEFINE_CLENSHAW(d, double)
DEFINE_CLENSHAW(ld, long double)

float stab_eval_float(stab_basis s, const float *c, int k, float t)
{
    return s == STAB_CHEBYSHEV ? tfit_cheb(c, (uint32_t)k, t) : f_horner(c, k, t);
}

float stab_eval_float_nodal(const float *c, int k, float t)
{
    /* A nodal row whose only nonzero coefficients are those of T_j(g0),
     * term index j(j+1)(j+2)/6 (a = j, b = c = 0). */
    float row[TFIT_MAX_TERMS] = {0};
    float phi[TFIT_MAX_TERMS];
    const float g[3] = {t, 0.0f, 0.0f};
    for (int j = 0; j <= k; ++j) {
        row[j * (j + 1) * (j + 2) / 6] = c[j];
    }
    tfit_basis((uint32_t)k, g, phi);
    return tfit_row(row, phi, TFIT_TERMS((uint32_t)k));
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
