/*
 * mgh_problems.c — the 18 least-squares problems of Moré, Garbow &
 * Hillstrom (ACM TOMS 7(1) 1981, §3), written from the paper's
 * definitions: residuals f_i(x), their Jacobians (derived by hand, checked
 * against differences by tests/unit/numerics/test_lm_mgh.c), standard starting
 * points, and the minimal sums of squares the paper reports.  Indices in
 * the comments are the paper's (1-based); the code's are 0-based.
 */
#include "numerics/mgh_problems.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846

typedef void (*residual_fn)(size_t m, size_t n, const double *x, double *f);
typedef void (*jacobian_fn)(size_t m, size_t n, const double *x, double *jac);

/* ------------------------------------------------------------------------ */
/* 1. Linear function, full rank: f_i = x_i - (2/m) sum_j x_j - 1 (i <= n),
 *    f_i = -(2/m) sum_j x_j - 1 (i > n).  Minimum m - n at x = -1. */

static void linear_full(size_t m, size_t n, const double *x, double *f)
{
    double s = 0;
    for (size_t j = 0; j < n; ++j) {
        s += x[j];
    }
    double c = 2 * s / (double)m + 1;
    for (size_t i = 0; i < m; ++i) {
        f[i] = (i < n ? x[i] : 0) - c;
    }
}

static void linear_full_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)x;
    for (size_t j = 0; j < n; ++j) {
        for (size_t i = 0; i < m; ++i) {
            jac[i + j * m] = (i == j) - 2 / (double)m;
        }
    }
}

/* 2. Linear function, rank 1: f_i = i (sum_j j x_j) - 1. */

static void linear_rank1(size_t m, size_t n, const double *x, double *f)
{
    double s = 0;
    for (size_t j = 0; j < n; ++j) {
        s += (double)(j + 1) * x[j];
    }
    for (size_t i = 0; i < m; ++i) {
        f[i] = (double)(i + 1) * s - 1;
    }
}

static void linear_rank1_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)x;
    for (size_t j = 0; j < n; ++j) {
        for (size_t i = 0; i < m; ++i) {
            jac[i + j * m] = (double)(i + 1) * (double)(j + 1);
        }
    }
}

/* 3. Linear function, rank 1 with zero columns and rows:
 *    f_i = (i - 1) (sum_{j=2}^{n-1} j x_j) - 1 for 2 <= i <= m - 1,
 *    f_1 = f_m = -1. */

static int zero_row_or_column(size_t m, size_t n, size_t i, size_t j)
{
    return i == 0 || i == m - 1 || j == 0 || j == n - 1;
}

static void linear_rank1_zero(size_t m, size_t n, const double *x, double *f)
{
    double s = 0;
    for (size_t j = 1; j + 1 < n; ++j) {
        s += (double)(j + 1) * x[j];
    }
    for (size_t i = 0; i < m; ++i) {
        f[i] = (i == 0 || i == m - 1 ? 0 : (double)i * s) - 1;
    }
}

static void linear_rank1_zero_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)x;
    for (size_t j = 0; j < n; ++j) {
        for (size_t i = 0; i < m; ++i) {
            jac[i + j * m] = zero_row_or_column(m, n, i, j) ? 0 : (double)i * (double)(j + 1);
        }
    }
}

/* 4. Rosenbrock: f_1 = 10 (x_2 - x_1^2), f_2 = 1 - x_1. */

static void rosenbrock(size_t m, size_t n, const double *x, double *f)
{
    (void)m, (void)n;
    f[0] = 10 * (x[1] - x[0] * x[0]);
    f[1] = 1 - x[0];
}

static void rosenbrock_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)m, (void)n;
    jac[0] = -20 * x[0];
    jac[1] = -1;
    jac[2] = 10;
    jac[3] = 0;
}

/* 5. Helical valley: f_1 = 10 (x_3 - 10 theta), f_2 = 10 (sqrt(x_1^2 +
 *    x_2^2) - 1), f_3 = x_3, with 2 pi theta = arctan(x_2 / x_1) for
 *    x_1 > 0 and arctan(x_2 / x_1) + pi for x_1 < 0 (at x_1 = 0 the
 *    limit, +-1/4 by the sign of x_2). */

static double helix_theta(double x1, double x2)
{
    if (x1 > 0) {
        return atan(x2 / x1) / (2 * PI);
    }
    if (x1 < 0) {
        return atan(x2 / x1) / (2 * PI) + 0.5;
    }
    return x2 >= 0 ? 0.25 : -0.25;
}

static void helical(size_t m, size_t n, const double *x, double *f)
{
    (void)m, (void)n;
    f[0] = 10 * (x[2] - 10 * helix_theta(x[0], x[1]));
    f[1] = 10 * (hypot(x[0], x[1]) - 1);
    f[2] = x[2];
}

/* d theta / d x_1 = -x_2 / (2 pi r^2), d theta / d x_2 = x_1 / (2 pi r^2). */
static void helical_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)m, (void)n;
    double r2 = x[0] * x[0] + x[1] * x[1], r = sqrt(r2), c = 100 / (2 * PI * r2);
    jac[0] = c * x[1];
    jac[1] = 10 * x[0] / r;
    jac[2] = 0;
    jac[3] = -c * x[0];
    jac[4] = 10 * x[1] / r;
    jac[5] = 0;
    jac[6] = 10;
    jac[7] = 0;
    jac[8] = 1;
}

/* 6. Powell singular: f_1 = x_1 + 10 x_2, f_2 = sqrt 5 (x_3 - x_4),
 *    f_3 = (x_2 - 2 x_3)^2, f_4 = sqrt 10 (x_1 - x_4)^2.  Minimum 0 at 0,
 *    where the Jacobian is singular. */

static void powell_singular(size_t m, size_t n, const double *x, double *f)
{
    (void)m, (void)n;
    double a = x[1] - 2 * x[2], b = x[0] - x[3];
    f[0] = x[0] + 10 * x[1];
    f[1] = sqrt(5.0) * (x[2] - x[3]);
    f[2] = a * a;
    f[3] = sqrt(10.0) * b * b;
}

static void powell_singular_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)m, (void)n;
    double a = x[1] - 2 * x[2], b = x[0] - x[3];
    double col[4][4] = {
        {1, 0, 0, 2 * sqrt(10.0) * b},
        {10, 0, 2 * a, 0},
        {0, sqrt(5.0), -4 * a, 0},
        {0, -sqrt(5.0), 0, -2 * sqrt(10.0) * b},
    };
    memcpy(jac, col, sizeof col);
}

/* 7. Freudenstein and Roth: f_1 = -13 + x_1 + ((5 - x_2) x_2 - 2) x_2,
 *    f_2 = -29 + x_1 + ((x_2 + 1) x_2 - 14) x_2. */

static void freudenstein_roth(size_t m, size_t n, const double *x, double *f)
{
    (void)m, (void)n;
    double y = x[1];
    f[0] = -13 + x[0] + ((5 - y) * y - 2) * y;
    f[1] = -29 + x[0] + ((y + 1) * y - 14) * y;
}

static void freudenstein_roth_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)m, (void)n;
    double y = x[1];
    jac[0] = 1;
    jac[1] = 1;
    jac[2] = (10 - 3 * y) * y - 2;
    jac[3] = (3 * y + 2) * y - 14;
}

/* 8. Bard: f_i = y_i - (x_1 + u_i / (v_i x_2 + w_i x_3)), u_i = i,
 *    v_i = 16 - i, w_i = min(u_i, v_i), m = 15. */

static const double bard_y[15] = {0.14, 0.18, 0.22, 0.25, 0.29, 0.32, 0.35, 0.39,
                                  0.37, 0.58, 0.73, 0.96, 1.34, 2.10, 4.39};

static void bard_uvw(size_t i, double *u, double *v, double *w)
{
    *u = (double)(i + 1);
    *v = (double)(15 - i);
    *w = fmin(*u, *v);
}

static void bard(size_t m, size_t n, const double *x, double *f)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double u, v, w;
        bard_uvw(i, &u, &v, &w);
        f[i] = bard_y[i] - (x[0] + u / (v * x[1] + w * x[2]));
    }
}

static void bard_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double u, v, w;
        bard_uvw(i, &u, &v, &w);
        double d = v * x[1] + w * x[2], d2 = d * d;
        jac[i] = -1;
        jac[i + m] = u * v / d2;
        jac[i + 2 * m] = u * w / d2;
    }
}

/* 9. Kowalik and Osborne: f_i = y_i - x_1 (u_i^2 + u_i x_2) /
 *    (u_i^2 + u_i x_3 + x_4), m = 11. */

static const double kowalik_y[11] = {0.1957, 0.1947, 0.1735, 0.1600, 0.0844, 0.0627,
                                     0.0456, 0.0342, 0.0323, 0.0235, 0.0246};
static const double kowalik_u[11] = {4,     2,     1,      0.5,    0.25,  0.167,
                                     0.125, 0.100, 0.0833, 0.0714, 0.0625};

static void kowalik_osborne(size_t m, size_t n, const double *x, double *f)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double u = kowalik_u[i];
        f[i] = kowalik_y[i] - x[0] * (u * u + u * x[1]) / (u * u + u * x[2] + x[3]);
    }
}

static void kowalik_osborne_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double u = kowalik_u[i], a = u * u + u * x[1], b = u * u + u * x[2] + x[3];
        jac[i] = -a / b;
        jac[i + m] = -x[0] * u / b;
        jac[i + 2 * m] = x[0] * a * u / (b * b);
        jac[i + 3 * m] = x[0] * a / (b * b);
    }
}

/* 10. Meyer: f_i = x_1 exp(x_2 / (t_i + x_3)) - y_i, t_i = 45 + 5 i,
 *     m = 16. */

static const double meyer_y[16] = {34780, 28610, 23650, 19630, 16370, 13720, 11540, 9744,
                                   8261,  7030,  6005,  5147,  4427,  3820,  3307,  2872};

static void meyer(size_t m, size_t n, const double *x, double *f)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double t = 45 + 5 * (double)(i + 1);
        f[i] = x[0] * exp(x[1] / (t + x[2])) - meyer_y[i];
    }
}

static void meyer_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double d = 45 + 5 * (double)(i + 1) + x[2], e = exp(x[1] / d);
        jac[i] = e;
        jac[i + m] = x[0] * e / d;
        jac[i + 2 * m] = -x[0] * e * x[1] / (d * d);
    }
}

/* 11. Watson: t_i = i / 29, f_i = sum_{j=2}^n (j - 1) x_j t_i^{j-2} -
 *     (sum_{j=1}^n x_j t_i^{j-1})^2 - 1 for 1 <= i <= 29, f_30 = x_1,
 *     f_31 = x_2 - x_1^2 - 1; m = 31. */

static double watson_sum(size_t n, const double *x, double t)
{
    double s = 0, tj = 1;
    for (size_t j = 0; j < n; ++j, tj *= t) {
        s += x[j] * tj;
    }
    return s;
}

static void watson(size_t m, size_t n, const double *x, double *f)
{
    (void)m;
    for (size_t i = 0; i < 29; ++i) {
        double t = (double)(i + 1) / 29, s1 = 0, tj = 1;
        for (size_t j = 1; j < n; ++j, tj *= t) {
            s1 += (double)j * x[j] * tj;
        }
        double s2 = watson_sum(n, x, t);
        f[i] = s1 - s2 * s2 - 1;
    }
    f[29] = x[0];
    f[30] = x[1] - x[0] * x[0] - 1;
}

static void watson_jac(size_t m, size_t n, const double *x, double *jac)
{
    for (size_t i = 0; i < 29; ++i) {
        double t = (double)(i + 1) / 29, s2 = watson_sum(n, x, t), tj = 1, tjm1 = 0;
        for (size_t j = 0; j < n; ++j) {
            /* d f_i / d x_j = (j - 1) t^{j-2} - 2 s2 t^{j-1} (paper's j) */
            jac[i + j * m] = (double)j * tjm1 - 2 * s2 * tj;
            tjm1 = tj;
            tj *= t;
        }
    }
    for (size_t j = 0; j < n; ++j) {
        jac[29 + j * m] = j == 0;
        jac[30 + j * m] = j == 0 ? -2 * x[0] : j == 1;
    }
}

/* 12. Box three-dimensional: f_i = exp(-t_i x_1) - exp(-t_i x_2) -
 *     x_3 (exp(-t_i) - exp(-10 t_i)), t_i = 0.1 i. */

static void box3d(size_t m, size_t n, const double *x, double *f)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double t = 0.1 * (double)(i + 1);
        f[i] = exp(-t * x[0]) - exp(-t * x[1]) - x[2] * (exp(-t) - exp(-10 * t));
    }
}

static void box3d_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double t = 0.1 * (double)(i + 1);
        jac[i] = -t * exp(-t * x[0]);
        jac[i + m] = t * exp(-t * x[1]);
        jac[i + 2 * m] = -(exp(-t) - exp(-10 * t));
    }
}

/* 13. Jennrich and Sampson: f_i = 2 + 2 i - (exp(i x_1) + exp(i x_2)). */

static void jennrich_sampson(size_t m, size_t n, const double *x, double *f)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double k = (double)(i + 1);
        f[i] = 2 + 2 * k - (exp(k * x[0]) + exp(k * x[1]));
    }
}

static void jennrich_sampson_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double k = (double)(i + 1);
        jac[i] = -k * exp(k * x[0]);
        jac[i + m] = -k * exp(k * x[1]);
    }
}

/* 14. Brown and Dennis: f_i = (x_1 + t_i x_2 - exp t_i)^2 +
 *     (x_3 + x_4 sin t_i - cos t_i)^2, t_i = i / 5. */

static void brown_dennis(size_t m, size_t n, const double *x, double *f)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double t = (double)(i + 1) / 5;
        double a = x[0] + t * x[1] - exp(t), b = x[2] + x[3] * sin(t) - cos(t);
        f[i] = a * a + b * b;
    }
}

static void brown_dennis_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double t = (double)(i + 1) / 5;
        double a = x[0] + t * x[1] - exp(t), b = x[2] + x[3] * sin(t) - cos(t);
        jac[i] = 2 * a;
        jac[i + m] = 2 * a * t;
        jac[i + 2 * m] = 2 * b;
        jac[i + 3 * m] = 2 * b * sin(t);
    }
}

/* 15. Chebyquad: f_i = (1/n) sum_j T_i(x_j) - integral_0^1 T_i, with T_i
 *     the Chebyshev polynomial shifted to [0, 1], T_i(x) = C_i(2x - 1);
 *     the integral is 0 for odd i and -1 / (i^2 - 1) for even i.
 *     C_{k+1} = 2 y C_k - C_{k-1}, and C'_{k+1} = 2 C_k + 2 y C'_k -
 *     C'_{k-1}; d T_i / d x = 2 C'_i(2x - 1). */

static void chebyquad(size_t m, size_t n, const double *x, double *f)
{
    memset(f, 0, m * sizeof *f);
    for (size_t j = 0; j < n; ++j) {
        double y = 2 * x[j] - 1, prev = 1, cur = y;
        for (size_t i = 0; i < m; ++i) {
            f[i] += cur;
            double next = 2 * y * cur - prev;
            prev = cur;
            cur = next;
        }
    }
    for (size_t i = 0; i < m; ++i) {
        double k = (double)(i + 1);
        f[i] = f[i] / (double)n + ((i + 1) % 2 == 0 ? 1 / (k * k - 1) : 0);
    }
}

static void chebyquad_jac(size_t m, size_t n, const double *x, double *jac)
{
    for (size_t j = 0; j < n; ++j) {
        double y = 2 * x[j] - 1, prev = 1, cur = y, dprev = 0, dcur = 1;
        for (size_t i = 0; i < m; ++i) {
            jac[i + j * m] = 2 * dcur / (double)n;
            double next = 2 * y * cur - prev, dnext = 2 * cur + 2 * y * dcur - dprev;
            prev = cur;
            cur = next;
            dprev = dcur;
            dcur = dnext;
        }
    }
}

/* 16. Brown almost-linear: f_i = x_i + sum_j x_j - (n + 1) for i < n,
 *     f_n = prod_j x_j - 1; m = n. */

static void brown_almost_linear(size_t m, size_t n, const double *x, double *f)
{
    (void)m;
    double s = 0, p = 1;
    for (size_t j = 0; j < n; ++j) {
        s += x[j];
        p *= x[j];
    }
    for (size_t i = 0; i + 1 < n; ++i) {
        f[i] = x[i] + s - (double)(n + 1);
    }
    f[n - 1] = p - 1;
}

/* The last row, prod_{k != j} x_k, from prefix and suffix products (no
 * division, so exact zeros are fine). */
static void brown_almost_linear_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)m;
    for (size_t j = 0; j < n; ++j) {
        for (size_t i = 0; i + 1 < n; ++i) {
            jac[i + j * n] = 1 + (i == j);
        }
    }
    double prefix = 1;
    for (size_t j = 0; j < n; ++j) {
        jac[n - 1 + j * n] = prefix;
        prefix *= x[j];
    }
    double suffix = 1;
    for (size_t j = n; j-- > 0;) {
        jac[n - 1 + j * n] *= suffix;
        suffix *= x[j];
    }
}

/* 17. Osborne 1: f_i = y_i - (x_1 + x_2 exp(-t_i x_4) + x_3 exp(-t_i
 *     x_5)), t_i = 10 (i - 1), m = 33. */

static const double osborne1_y[33] = {
    0.844, 0.908, 0.932, 0.936, 0.925, 0.908, 0.881, 0.850, 0.818, 0.784, 0.751,
    0.718, 0.685, 0.658, 0.628, 0.603, 0.580, 0.558, 0.538, 0.522, 0.506, 0.490,
    0.478, 0.467, 0.457, 0.448, 0.438, 0.431, 0.424, 0.420, 0.414, 0.411, 0.406};

static void osborne1(size_t m, size_t n, const double *x, double *f)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double t = 10 * (double)i;
        f[i] = osborne1_y[i] - (x[0] + x[1] * exp(-t * x[3]) + x[2] * exp(-t * x[4]));
    }
}

static void osborne1_jac(size_t m, size_t n, const double *x, double *jac)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double t = 10 * (double)i, e4 = exp(-t * x[3]), e5 = exp(-t * x[4]);
        jac[i] = -1;
        jac[i + m] = -e4;
        jac[i + 2 * m] = -e5;
        jac[i + 3 * m] = t * x[1] * e4;
        jac[i + 4 * m] = t * x[2] * e5;
    }
}

/* 18. Osborne 2: f_i = y_i - (x_1 exp(-t_i x_5) + x_2 exp(-(t_i - x_9)^2
 *     x_6) + x_3 exp(-(t_i - x_10)^2 x_7) + x_4 exp(-(t_i - x_11)^2 x_8)),
 *     t_i = (i - 1) / 10, m = 65. */

static const double osborne2_y[65] = {
    1.366, 1.191, 1.112, 1.013, 0.991, 0.885, 0.831, 0.847, 0.786, 0.725, 0.746, 0.679, 0.608,
    0.655, 0.616, 0.606, 0.602, 0.626, 0.651, 0.724, 0.649, 0.649, 0.694, 0.644, 0.624, 0.661,
    0.612, 0.558, 0.533, 0.495, 0.500, 0.423, 0.395, 0.375, 0.372, 0.391, 0.396, 0.405, 0.428,
    0.429, 0.523, 0.562, 0.607, 0.653, 0.672, 0.708, 0.633, 0.668, 0.645, 0.632, 0.591, 0.559,
    0.597, 0.625, 0.739, 0.710, 0.729, 0.720, 0.636, 0.581, 0.428, 0.292, 0.162, 0.098, 0.054};

/* Gaussian k (1..3, 0-based x): exp(-(t - x[k+7])^2 x[k+4]). */
static double osborne2_gauss(const double *x, size_t k, double t)
{
    double d = t - x[k + 7];
    return exp(-d * d * x[k + 4]);
}

static void osborne2(size_t m, size_t n, const double *x, double *f)
{
    (void)n;
    for (size_t i = 0; i < m; ++i) {
        double t = (double)i / 10, v = x[0] * exp(-t * x[4]);
        for (size_t k = 1; k <= 3; ++k) {
            v += x[k] * osborne2_gauss(x, k, t);
        }
        f[i] = osborne2_y[i] - v;
    }
}

static void osborne2_jac(size_t m, size_t n, const double *x, double *jac)
{
    memset(jac, 0, m * n * sizeof *jac);
    for (size_t i = 0; i < m; ++i) {
        double t = (double)i / 10, e = exp(-t * x[4]);
        jac[i] = -e;
        jac[i + 4 * m] = t * x[0] * e;
        for (size_t k = 1; k <= 3; ++k) {
            double g = osborne2_gauss(x, k, t), d = t - x[k + 7];
            jac[i + k * m] = -g;
            jac[i + (k + 4) * m] = x[k] * d * d * g;
            jac[i + (k + 7) * m] = -2 * x[k] * x[k + 4] * d * g;
        }
    }
}

/* ------------------------------------------------------------------------ */

typedef struct problem {
    const char *name;
    residual_fn f;
    jacobian_fn jac;
    const double *x0; /* NULL: filled by start_value() */
} mgh_def;

static const double x0_rosenbrock[] = {-1.2, 1};
static const double x0_helical[] = {-1, 0, 0};
static const double x0_powell[] = {3, -1, 0, 1};
static const double x0_freudenstein[] = {0.5, -2};
static const double x0_bard[] = {1, 1, 1};
static const double x0_kowalik[] = {0.25, 0.39, 0.415, 0.39};
static const double x0_meyer[] = {0.02, 4000, 250};
static const double x0_box[] = {0, 10, 20};
static const double x0_jennrich[] = {0.3, 0.4};
static const double x0_brown_dennis[] = {25, 5, -5, -1};
static const double x0_osborne1[] = {0.5, 1.5, -1, 0.01, 0.02};
static const double x0_osborne2[] = {1.3, 0.65, 0.65, 0.7, 0.6, 3, 5, 7, 2, 4.5, 5.5};

static const mgh_def problems[TF_MGH_PROBLEMS] = {
    {"Linear, full rank", linear_full, linear_full_jac, NULL},
    {"Linear, rank 1", linear_rank1, linear_rank1_jac, NULL},
    {"Linear, rank 1, zero rows/cols", linear_rank1_zero, linear_rank1_zero_jac, NULL},
    {"Rosenbrock", rosenbrock, rosenbrock_jac, x0_rosenbrock},
    {"Helical valley", helical, helical_jac, x0_helical},
    {"Powell singular", powell_singular, powell_singular_jac, x0_powell},
    {"Freudenstein-Roth", freudenstein_roth, freudenstein_roth_jac, x0_freudenstein},
    {"Bard", bard, bard_jac, x0_bard},
    {"Kowalik-Osborne", kowalik_osborne, kowalik_osborne_jac, x0_kowalik},
    {"Meyer", meyer, meyer_jac, x0_meyer},
    {"Watson", watson, watson_jac, NULL},
    {"Box 3-D", box3d, box3d_jac, x0_box},
    {"Jennrich-Sampson", jennrich_sampson, jennrich_sampson_jac, x0_jennrich},
    {"Brown-Dennis", brown_dennis, brown_dennis_jac, x0_brown_dennis},
    {"Chebyquad", chebyquad, chebyquad_jac, NULL},
    {"Brown almost-linear", brown_almost_linear, brown_almost_linear_jac, NULL},
    {"Osborne 1", osborne1, osborne1_jac, x0_osborne1},
    {"Osborne 2", osborne2, osborne2_jac, x0_osborne2},
};

/* MINPACK's lmder driver: (problem, n, m, number of starts 1, 10, 100). */
static const tf_mgh_run runs[] = {
    {1, 5, 10, 1},    {1, 5, 50, 1},    {2, 5, 10, 1},    {2, 5, 50, 1},    {3, 5, 10, 1},
    {3, 5, 50, 1},    {4, 2, 2, 1},     {4, 2, 2, 10},    {4, 2, 2, 100},   {5, 3, 3, 1},
    {5, 3, 3, 10},    {5, 3, 3, 100},   {6, 4, 4, 1},     {6, 4, 4, 10},    {6, 4, 4, 100},
    {7, 2, 2, 1},     {7, 2, 2, 10},    {7, 2, 2, 100},   {8, 3, 15, 1},    {8, 3, 15, 10},
    {8, 3, 15, 100},  {9, 4, 11, 1},    {9, 4, 11, 10},   {9, 4, 11, 100},  {10, 3, 16, 1},
    {10, 3, 16, 10},  {11, 6, 31, 1},   {11, 6, 31, 10},  {11, 6, 31, 100}, {11, 9, 31, 1},
    {11, 9, 31, 10},  {11, 9, 31, 100}, {11, 12, 31, 1},  {11, 12, 31, 10}, {11, 12, 31, 100},
    {12, 3, 10, 1},   {13, 2, 10, 1},   {14, 4, 20, 1},   {14, 4, 20, 10},  {14, 4, 20, 100},
    {15, 1, 8, 1},    {15, 1, 8, 10},   {15, 1, 8, 100},  {15, 8, 8, 1},    {15, 9, 9, 1},
    {15, 10, 10, 1},  {16, 10, 10, 1},  {16, 10, 10, 10}, {16, 10, 10, 100}, {16, 30, 30, 1},
    {16, 40, 40, 1},  {17, 5, 33, 1},   {18, 11, 65, 1},
};

const tf_mgh_run *tf_mgh_runs(size_t *count)
{
    *count = sizeof runs / sizeof runs[0];
    return runs;
}

static const mgh_def *lookup(int k)
{
    return k >= 1 && k <= TF_MGH_PROBLEMS ? &problems[k - 1] : NULL;
}

const char *tf_mgh_name(int problem)
{
    const mgh_def *p = lookup(problem);
    return p != NULL ? p->name : "unknown";
}

/* Standard starts not given as a table: 1 (linear), 0 (Watson),
 * j / (n + 1) (Chebyquad), 1/2 (Brown almost-linear). */
static double start_value(int problem, size_t j, size_t n)
{
    switch (problem) {
    case 11:
        return 0;
    case 15:
        return (double)(j + 1) / (double)(n + 1);
    case 16:
        return 0.5;
    default:
        return 1;
    }
}

void tf_mgh_start(const tf_mgh_run *r, double *x)
{
    const mgh_def *p = lookup(r->problem);
    for (size_t j = 0; j < r->n; ++j) {
        double v = p->x0 != NULL ? p->x0[j] : start_value(r->problem, j, r->n);
        x[j] = r->problem == 11 && r->factor != 1 ? r->factor : r->factor * v;
    }
}

void tf_mgh_residual(const tf_mgh_run *r, const double *x, double *f)
{
    lookup(r->problem)->f(r->m, r->n, x, f);
}

void tf_mgh_jacobian(const tf_mgh_run *r, const double *x, double *jac)
{
    lookup(r->problem)->jac(r->m, r->n, x, jac);
}

/* Watson's minima for n = 6, 9, 12 (the paper). */
static double watson_min(size_t n)
{
    return n == 6 ? 2.28767e-3 : n == 9 ? 1.39976e-6 : 4.72238e-10;
}

/* Chebyquad's minima for n = m = 8, 9, 10 (the paper); for n = 1, m = 8,
 * which the paper does not list, found here by golden-section search of
 * the one-variable function: 3.0665272324 at x = 0.40897 and 0.59103
 * (symmetric about 1/2), the smallest on [-0.25, 1.25], and a local
 * minimum 3.5503912977 at x = 0.98173 (where MINPACK's driver ends from
 * 10 x0 and 100 x0, final norm 1.8842482).  tests/unit/numerics/test_lm_mgh.c
 * checks both. */
static size_t chebyquad_minima(size_t n, double *f)
{
    if (n == 1) {
        f[0] = 3.0665272324, f[1] = 3.5503912977;
        return 2;
    }
    f[0] = n == 8 ? 3.51687e-3 : n == 9 ? 0 : 6.50395e-3;
    return 1;
}

size_t tf_mgh_minima(const tf_mgh_run *r, double *f)
{
    const double m = (double)r->m, n = (double)r->n;
    switch (r->problem) {
    case 1:
        f[0] = m - n;
        return 1;
    case 2:
        f[0] = m * (m - 1) / (2 * (2 * m + 1));
        return 1;
    case 3:
        f[0] = (m * m + 3 * m - 6) / (2 * (2 * m - 3));
        return 1;
    case 7: /* 0 at (5, 4); a local minimum near (11.41, -0.8968) */
        f[0] = 0, f[1] = 48.9842;
        return 2;
    case 8: /* the second at (0.8406, -inf, -inf) */
        f[0] = 8.21487e-3, f[1] = 17.4286;
        return 2;
    case 9: /* the second at (+inf, -14.07, -inf, -inf); the third near
             * (0.2254, -0.4148, -0.02445, -0.1780), not in the paper */
        f[0] = 3.07505e-4, f[1] = 1.02734e-3, f[2] = 4.23675e-4;
        return 3;
    case 10:
        f[0] = 87.9458;
        return 1;
    case 11:
        f[0] = watson_min(r->n);
        return 1;
    case 13: /* m = 10 */
        f[0] = 124.362;
        return 1;
    case 14: /* m = 20 */
        f[0] = 85822.2;
        return 1;
    case 15:
        return chebyquad_minima(r->n, f);
    case 16: /* 1 at (0, ..., 0, n + 1) */
        f[0] = 0, f[1] = 1;
        return 2;
    case 17:
        f[0] = 5.46489e-5;
        return 1;
    case 18:
        f[0] = 4.01377e-2;
        return 1;
    default: /* 4, 5, 6, 12: zero residual */
        f[0] = 0;
        return 1;
    }
}
