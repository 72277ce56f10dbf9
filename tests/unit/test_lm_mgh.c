/*
 * test_lm_mgh.c — the Moré–Garbow–Hillstrom set (host/numerics/
 * mgh_problems.c), the 53 runs of MINPACK's lmder driver: the norm at every
 * start equals the one MINPACK's driver prints (8 digits), Jacobians match
 * differences.
 */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "numerics/mgh_fit.h"

/* ||f(x0)|| at each run's start as MINPACK's lmder driver prints it
 * (8 digits), in the order of tf_mgh_runs(): an independent check of the
 * residuals as written from the paper. */
static const double start_norm[53] = {
    5.0000000e+00, 8.0622577e+00, 2.9152187e+02, 3.1016004e+03, 1.2603968e+02, 1.7489500e+03,
    4.9193496e+00, 1.3400631e+03, 1.4300005e+05, 5.0000000e+01, 1.0295630e+02, 9.9126182e+02,
    1.4662878e+01, 1.2709839e+03, 1.2688790e+05, 2.0012496e+01, 1.2432834e+04, 1.1426455e+07,
    6.4561363e+00, 3.6141853e+01, 3.8411468e+02, 7.2891510e-02, 2.9793701e+00, 2.9959062e+01,
    4.1153467e+04, 4.1682169e+06, 5.4772256e+00, 6.4331258e+03, 6.7425604e+05, 5.4772256e+00,
    1.2088127e+04, 1.2691093e+06, 5.4772256e+00, 1.9220759e+04, 2.0189180e+06, 3.2111584e+01,
    6.4585650e+01, 2.8154384e+03, 5.5507335e+05, 6.1211252e+07, 1.8862380e+00, 5.3833444e+09,
    1.1808873e+18, 1.9651386e-01, 1.6994993e-01, 1.8374783e-01, 1.6530216e+01, 9.7656240e+06,
    9.7656250e+16, 8.3476044e+01, 1.2802636e+02, 9.3756402e-01, 1.4468654e+00};

static const tf_mgh_run *runs(size_t *n)
{
    const tf_mgh_run *r = tf_mgh_runs(n);
    assert_int_equal(*n, 53);
    return r;
}

static double norm(const double *v, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; ++i) {
        s += v[i] * v[i];
    }
    return sqrt(s);
}

static void start_norms_match_minpack(void **state)
{
    (void)state;
    size_t nr;
    const tf_mgh_run *r = runs(&nr);
    for (size_t k = 0; k < nr; ++k) {
        double x[TF_MGH_MAX_N], f[TF_MGH_MAX_M];
        tf_mgh_start(&r[k], x);
        tf_mgh_residual(&r[k], x, f);
        double got = norm(f, r[k].m);
        if (!(fabs(got - start_norm[k]) <= 1e-7 * start_norm[k])) {
            fail_msg("run %zu (%s): ||f(x0)|| = %.8e, MINPACK %.7e", k, tf_mgh_name(r[k].problem),
                     got, start_norm[k]);
        }
    }
}

/* At a point off the start (some Jacobians vanish there by symmetry),
 * central differences with h = 1e-6 max(1, |x_j|).  Checked with and
 * without a deliberate error in one entry: a wrong sign or a missing
 * factor fails here. */
static void jacobians_match_differences(void **state)
{
    (void)state;
    size_t nr;
    const tf_mgh_run *r = runs(&nr);
    for (size_t k = 0; k < nr; ++k) {
        const size_t m = r[k].m, n = r[k].n;
        double x[TF_MGH_MAX_N], jac[TF_MGH_MAX_M * TF_MGH_MAX_N], fp[TF_MGH_MAX_M],
            fm[TF_MGH_MAX_M];
        tf_mgh_start(&r[k], x);
        for (size_t j = 0; j < n; ++j) {
            x[j] = 1.01 * x[j] + 0.013 * (double)j + 0.02;
        }
        tf_mgh_jacobian(&r[k], x, jac);
        for (size_t j = 0; j < n; ++j) {
            double xj = x[j], h = 1e-6 * fmax(1, fabs(xj));
            x[j] = xj + h;
            tf_mgh_residual(&r[k], x, fp);
            x[j] = xj - h;
            tf_mgh_residual(&r[k], x, fm);
            x[j] = xj;
            for (size_t i = 0; i < m; ++i) {
                /* truncation O(h^2), and the rounding of f over 2h */
                double d = (fp[i] - fm[i]) / (2 * h), a = jac[i + j * m];
                double tol = 1e-6 * fmax(1, fabs(a)) + 8 * DBL_EPSILON * fabs(fp[i]) / h;
                if (!(fabs(d - a) <= tol)) {
                    fail_msg("run %zu (%s): df_%zu/dx_%zu = %.10g, differences %.10g", k,
                             tf_mgh_name(r[k].problem), i, j, a, d);
                }
            }
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(start_norms_match_minpack),
        cmocka_unit_test(jacobians_match_differences),
    };
    return cmocka_run_group_tests_name("lm_mgh", tests, NULL, NULL);
}
