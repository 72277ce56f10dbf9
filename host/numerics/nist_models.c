/*
 * nist_models.c — the 19 distinct model functions of the 27 NIST StRD
 * nonlinear problems, with their derivatives (see nist_models.h).  The
 * formulas are those printed in the files; the derivatives are worked out
 * by hand and checked against central differences in tests/unit/numerics/test_lm_nist.c.
 */
#include "numerics/nist_models.h"

#include <math.h>
#include <string.h>

/* y = b1*(1-exp[-b2*x])  (Misra1a, BoxBOD) */
static double exp_rise(const double *b, const double *x, double *g)
{
    double e = exp(-b[1] * x[0]);
    if (g) {
        g[0] = 1 - e;
        g[1] = b[0] * x[0] * e;
    }
    return b[0] * (1 - e);
}

/* y = exp[-b1*x]/(b2+b3*x)  (Chwirut1, Chwirut2) */
static double chwirut(const double *b, const double *x, double *g)
{
    double e = exp(-b[0] * x[0]), d = b[1] + b[2] * x[0];
    if (g) {
        g[0] = -x[0] * e / d;
        g[1] = -e / (d * d);
        g[2] = -x[0] * e / (d * d);
    }
    return e / d;
}

/* y = b1*exp(-b2*x) + b3*exp(-b4*x) + b5*exp(-b6*x)  (Lanczos1-3) */
static double lanczos(const double *b, const double *x, double *g)
{
    double y = 0;
    for (int k = 0; k < 6; k += 2) {
        double e = exp(-b[k + 1] * x[0]);
        if (g) {
            g[k] = e;
            g[k + 1] = -x[0] * b[k] * e;
        }
        y += b[k] * e;
    }
    return y;
}

/* b_a * exp(-(x-b_c)**2 / b_w**2) and its derivatives into g[a], g[c], g[w]. */
static double gauss_peak(const double *b, double x, int a, int c, int w, double *g)
{
    double d = x - b[c], e = exp(-d * d / (b[w] * b[w]));
    if (g) {
        g[a] = e;
        g[c] = b[a] * e * 2 * d / (b[w] * b[w]);
        g[w] = b[a] * e * 2 * d * d / (b[w] * b[w] * b[w]);
    }
    return b[a] * e;
}

/* y = b1*exp(-b2*x) + b3*exp(-(x-b4)**2/b5**2) + b6*exp(-(x-b7)**2/b8**2)
 * (Gauss1-3) */
static double gauss(const double *b, const double *x, double *g)
{
    double e = exp(-b[1] * x[0]);
    if (g) {
        g[0] = e;
        g[1] = -x[0] * b[0] * e;
    }
    return b[0] * e + gauss_peak(b, x[0], 2, 3, 4, g) + gauss_peak(b, x[0], 5, 6, 7, g);
}

/* y = b1*x**b2  (DanWood) */
static double danwood(const double *b, const double *x, double *g)
{
    double p = pow(x[0], b[1]);
    if (g) {
        g[0] = p;
        g[1] = b[0] * p * log(x[0]);
    }
    return b[0] * p;
}

/* y = b1 * (1-(1+b2*x/2)**(-2))  (Misra1b) */
static double misra1b(const double *b, const double *x, double *g)
{
    double u = 1 + b[1] * x[0] / 2;
    if (g) {
        g[0] = 1 - 1 / (u * u);
        g[1] = b[0] * x[0] / (u * u * u);
    }
    return b[0] * (1 - 1 / (u * u));
}

/* Rational: (sum_{k<nn} b_k x^k) / (1 + sum_{k=1..nd} b_{nn+k-1} x^k). */
static double rational(const double *b, double x, int nn, int nd, double *g)
{
    double num = 0, den = 1, xk = 1;
    for (int k = 0; k < nn; ++k, xk *= x) {
        num += b[k] * xk;
    }
    xk = x;
    for (int k = 0; k < nd; ++k, xk *= x) {
        den += b[nn + k] * xk;
    }
    if (g) {
        xk = 1;
        for (int k = 0; k < nn; ++k, xk *= x) {
            g[k] = xk / den;
        }
        xk = x;
        for (int k = 0; k < nd; ++k, xk *= x) {
            g[nn + k] = -num * xk / (den * den);
        }
    }
    return num / den;
}

/* y = (b1 + b2*x + b3*x**2) / (1 + b4*x + b5*x**2)  (Kirby2) */
static double kirby2(const double *b, const double *x, double *g)
{
    return rational(b, x[0], 3, 2, g);
}

/* y = (b1+b2*x+b3*x**2+b4*x**3) / (1+b5*x+b6*x**2+b7*x**3)  (Hahn1, Thurber) */
static double cubic_cubic(const double *b, const double *x, double *g)
{
    return rational(b, x[0], 4, 3, g);
}

/* log[y] = b1 - b2*x1 * exp[-b3*x2]  (Nelson; the response is log y) */
static double nelson(const double *b, const double *x, double *g)
{
    double e = exp(-b[2] * x[1]);
    if (g) {
        g[0] = 1;
        g[1] = -x[0] * e;
        g[2] = b[1] * x[0] * x[1] * e;
    }
    return b[0] - b[1] * x[0] * e;
}

/* y = b1 + b2*exp[-x*b4] + b3*exp[-x*b5]  (MGH17) */
static double mgh17(const double *b, const double *x, double *g)
{
    double e4 = exp(-x[0] * b[3]), e5 = exp(-x[0] * b[4]);
    if (g) {
        g[0] = 1;
        g[1] = e4;
        g[2] = e5;
        g[3] = -x[0] * b[1] * e4;
        g[4] = -x[0] * b[2] * e5;
    }
    return b[0] + b[1] * e4 + b[2] * e5;
}

/* y = b1 * (1-(1+2*b2*x)**(-.5))  (Misra1c) */
static double misra1c(const double *b, const double *x, double *g)
{
    double u = 1 + 2 * b[1] * x[0], s = 1 / sqrt(u);
    if (g) {
        g[0] = 1 - s;
        g[1] = b[0] * x[0] * s / u;
    }
    return b[0] * (1 - s);
}

/* y = b1*b2*x*((1+b2*x)**(-1))  (Misra1d) */
static double misra1d(const double *b, const double *x, double *g)
{
    double u = 1 + b[1] * x[0];
    if (g) {
        g[0] = b[1] * x[0] / u;
        g[1] = b[0] * x[0] / (u * u);
    }
    return b[0] * b[1] * x[0] / u;
}

/* y = b1 - b2*x - arctan[b3/(x-b4)]/pi  (Roszman1; atan, not atan2, as the
 * certified b1 requires: ../shared/reference/nist-strd/README.md) */
static double roszman1(const double *b, const double *x, double *g)
{
    double d = x[0] - b[3], t = b[2] / d;
    if (g) {
        double c = 1 / (M_PI * (1 + t * t));
        g[0] = 1;
        g[1] = -x[0];
        g[2] = -c / d;
        g[3] = -c * b[2] / (d * d);
    }
    return b[0] - b[1] * x[0] - atan(t) / M_PI;
}

/* b_c cos(a) + b_s sin(a), a = 2 pi x / period, derivatives into g. */
static double harmonic(const double *b, double x, double period, int c, int s, double *g)
{
    double a = 2 * M_PI * x / period, ca = cos(a), sa = sin(a);
    if (g) {
        g[c] = ca;
        g[s] = sa;
    }
    return b[c] * ca + b[s] * sa;
}

/* d/dT of b_c cos(2 pi x/T) + b_s sin(2 pi x/T) at T = b[t]. */
static double harmonic_period(const double *b, double x, int t, int c, int s)
{
    double a = 2 * M_PI * x / b[t];
    return (-b[c] * sin(a) + b[s] * cos(a)) * (-a / b[t]);
}

/* y = b1 + b2*cos(2*pi*x/12) + b3*sin(2*pi*x/12) + b5*cos(2*pi*x/b4)
 *   + b6*sin(2*pi*x/b4) + b8*cos(2*pi*x/b7) + b9*sin(2*pi*x/b7)  (ENSO) */
static double enso(const double *b, const double *x, double *g)
{
    double y = b[0] + harmonic(b, x[0], 12, 1, 2, g) + harmonic(b, x[0], b[3], 4, 5, g) +
               harmonic(b, x[0], b[6], 7, 8, g);
    if (g) {
        g[0] = 1;
        g[3] = harmonic_period(b, x[0], 3, 4, 5);
        g[6] = harmonic_period(b, x[0], 6, 7, 8);
    }
    return y;
}

/* y = b1*(x**2+x*b2) / (x**2+x*b3+b4)  (MGH09) */
static double mgh09(const double *b, const double *x, double *g)
{
    double n = x[0] * x[0] + x[0] * b[1], d = x[0] * x[0] + x[0] * b[2] + b[3];
    if (g) {
        g[0] = n / d;
        g[1] = b[0] * x[0] / d;
        g[2] = -b[0] * n * x[0] / (d * d);
        g[3] = -b[0] * n / (d * d);
    }
    return b[0] * n / d;
}

/* y = b1 / (1+exp[b2-b3*x])  (Rat42) */
static double rat42(const double *b, const double *x, double *g)
{
    double e = exp(b[1] - b[2] * x[0]), u = 1 + e;
    if (g) {
        g[0] = 1 / u;
        g[1] = -b[0] * e / (u * u);
        g[2] = b[0] * x[0] * e / (u * u);
    }
    return b[0] / u;
}

/* y = b1 * exp[b2/(x+b3)]  (MGH10) */
static double mgh10(const double *b, const double *x, double *g)
{
    double d = x[0] + b[2], e = exp(b[1] / d);
    if (g) {
        g[0] = e;
        g[1] = b[0] * e / d;
        g[2] = -b[0] * e * b[1] / (d * d);
    }
    return b[0] * e;
}

/* y = (b1/b2) * exp[-0.5*((x-b3)/b2)**2]  (Eckerle4) */
static double eckerle4(const double *b, const double *x, double *g)
{
    double z = (x[0] - b[2]) / b[1], e = exp(-0.5 * z * z);
    if (g) {
        g[0] = e / b[1];
        g[1] = b[0] * e * (z * z - 1) / (b[1] * b[1]);
        g[2] = b[0] * e * z / (b[1] * b[1]);
    }
    return b[0] / b[1] * e;
}

/* y = b1 / ((1+exp[b2-b3*x])**(1/b4))  (Rat43) */
static double rat43(const double *b, const double *x, double *g)
{
    double e = exp(b[1] - b[2] * x[0]), u = 1 + e, p = pow(u, -1 / b[3]);
    if (g) {
        g[0] = p;
        g[1] = -b[0] * p * e / (b[3] * u);
        g[2] = b[0] * p * x[0] * e / (b[3] * u);
        g[3] = b[0] * p * log(u) / (b[3] * b[3]);
    }
    return b[0] * p;
}

/* y = b1 * (b2+x)**(-1/b3)  (Bennett5) */
static double bennett5(const double *b, const double *x, double *g)
{
    double u = b[1] + x[0], p = pow(u, -1 / b[2]);
    if (g) {
        g[0] = p;
        g[1] = -b[0] * p / (b[2] * u);
        g[2] = b[0] * p * log(u) / (b[2] * b[2]);
    }
    return b[0] * p;
}

static const tf_nist_model models[] = {
    {"y=b1*(1-exp(-b2*x))", 2, 1, 0, exp_rise},
    {"y=exp(-b1*x)/(b2+b3*x)", 3, 1, 0, chwirut},
    {"y=b1*exp(-b2*x)+b3*exp(-b4*x)+b5*exp(-b6*x)", 6, 1, 0, lanczos},
    {"y=b1*exp(-b2*x)+b3*exp(-(x-b4)**2/b5**2)+b6*exp(-(x-b7)**2/b8**2)", 8, 1, 0, gauss},
    {"y=b1*x**b2", 2, 1, 0, danwood},
    {"y=b1*(1-(1+b2*x/2)**(-2))", 2, 1, 0, misra1b},
    {"y=(b1+b2*x+b3*x**2)/(1+b4*x+b5*x**2)", 5, 1, 0, kirby2},
    {"y=(b1+b2*x+b3*x**2+b4*x**3)/(1+b5*x+b6*x**2+b7*x**3)", 7, 1, 0, cubic_cubic},
    {"log(y)=b1-b2*x1*exp(-b3*x2)", 3, 2, 1, nelson},
    {"y=b1+b2*exp(-x*b4)+b3*exp(-x*b5)", 5, 1, 0, mgh17},
    {"y=b1*(1-(1+2*b2*x)**(-.5))", 2, 1, 0, misra1c},
    {"y=b1*b2*x*((1+b2*x)**(-1))", 2, 1, 0, misra1d},
    {"pi=3.141592653589793238462643383279E0"
     "y=b1-b2*x-arctan(b3/(x-b4))/pi",
     4, 1, 0, roszman1},
    {"y=b1+b2*cos(2*pi*x/12)+b3*sin(2*pi*x/12)+b5*cos(2*pi*x/b4)+b6*sin(2*pi*x/b4)"
     "+b8*cos(2*pi*x/b7)+b9*sin(2*pi*x/b7)",
     9, 1, 0, enso},
    {"y=b1*(x**2+x*b2)/(x**2+x*b3+b4)", 4, 1, 0, mgh09},
    {"y=b1/(1+exp(b2-b3*x))", 3, 1, 0, rat42},
    {"y=b1*exp(b2/(x+b3))", 3, 1, 0, mgh10},
    {"y=(b1/b2)*exp(-0.5*((x-b3)/b2)**2)", 3, 1, 0, eckerle4},
    {"y=b1/((1+exp(b2-b3*x))**(1/b4))", 4, 1, 0, rat43},
    {"y=b1*(b2+x)**(-1/b3)", 3, 1, 0, bennett5},
};

const tf_nist_model *tf_nist_model_find(const char *text)
{
    for (size_t i = 0; i < sizeof models / sizeof models[0]; ++i) {
        if (strcmp(models[i].text, text) == 0) {
            return &models[i];
        }
    }
    return NULL;
}

const tf_nist_model *tf_nist_models(size_t *count)
{
    *count = sizeof models / sizeof models[0];
    return models;
}

const char *const *tf_nist_suite(size_t *count)
{
    static const char *const names[] = {
        "Misra1a", "Chwirut2", "Chwirut1", "Lanczos3", "Gauss1",   "Gauss2",  "DanWood",
        "Misra1b", "Kirby2",   "Hahn1",    "Nelson",   "MGH17",    "Lanczos1", "Lanczos2",
        "Gauss3",  "Misra1c",  "Misra1d",  "Roszman1", "ENSO",     "MGH09",   "Thurber",
        "BoxBOD",  "Rat42",    "MGH10",    "Eckerle4", "Rat43",    "Bennett5",
    };
    *count = sizeof names / sizeof names[0];
    return names;
}
