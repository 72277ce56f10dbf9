/*
 * test_zhou2017.c — the seed-000 fitter on synthetic surfaces: a field
 * the model can hold (separable polynomial in x and y, linear in the force)
 * is recovered with the right orders chosen by cross-validation and
 * superposes exactly for combined forces; a non-separable field is not;
 * non-flat outputs and an off-centre envelope are refused.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "fitting/families/family.h"
#include "fitting/families/zhou2017.h"
#include "fitting/force_samples.h"

#define G 11
#define NOUT (G * G)
#define NA 30 /* cases per axis */
#define NC 40 /* combined cases */

static double rest[NOUT][3];
static uint32_t ids[NOUT];
static double af[3][NA][3], acontact[3][NA][3], au[3][NA][3 * NOUT];
static double cf[NC][3], ccontact[NC][3], cu[NC][3 * NOUT];
static int cross_term;

/* Displacement component c at (X, Y) per unit force along axis a. */
static double green(int a, int c, double x, double y)
{
    double v = (1 + a) * 0.3 - 0.2 * c + (0.5 + 0.1 * a) * x * x - 0.25 * y * y * y +
               0.1 * (a - c) * y;
    return cross_term ? v + 0.4 * x * y : v;
}

static void response(const double f[3], double *u, double contact[3])
{
    for (int j = 0; j < NOUT; ++j) {
        double x = (rest[j][0] - 24) / 24, y = (rest[j][1] - 24) / 24;
        for (int c = 0; c < 3; ++c) {
            u[3 * j + c] = 0;
            for (int a = 0; a < 3; ++a) {
                u[3 * j + c] += f[a] * green(a, c, x, y);
            }
        }
    }
    for (int a = 0; a < 3; ++a) {
        contact[a] = (2.0 + 9.0 * (a == 2)) * f[a];
    }
}

static void build(tf_fitdata axis[3], tf_fitdata *combined)
{
    for (int j = 0; j < NOUT; ++j) {
        rest[j][0] = 4.8 * (j % G);
        rest[j][1] = 4.8 * (j / G);
        rest[j][2] = 6.0;
        ids[j] = (uint32_t)j + 1;
    }
    for (int a = 0; a < 3; ++a) {
        for (int i = 0; i < NA; ++i) {
            memset(af[a][i], 0, sizeof af[a][i]);
            af[a][i][a] = -1.0 + 2.0 * i / (NA - 1);
            response(af[a][i], au[a][i], acontact[a][i]);
        }
        axis[a] = (tf_fitdata){.n_cases = NA, .force = (const double(*)[3])af[a],
                               .u = &au[a][0][0], .contact = (const double(*)[3])acontact[a],
                               .n_out = NOUT, .node_ids = ids, .rest = (const double(*)[3])rest,
                               .radius = 1.0};
    }
    const double zero[3] = {0, 0, 0};
    double ho[1][3];
    tf_force_samples(zero, 1.0, NC, 1, 9, cf, ho);
    for (int i = 0; i < NC; ++i) {
        response(cf[i], cu[i], ccontact[i]);
    }
    *combined = (tf_fitdata){.n_cases = NC, .force = (const double(*)[3])cf, .u = &cu[0][0],
                             .contact = (const double(*)[3])ccontact, .n_out = NOUT,
                             .node_ids = ids, .rest = (const double(*)[3])rest, .radius = 1.0};
}

static void recovers_a_separable_field(void **state)
{
    (void)state;
    tf_fitdata axis[3], combined;
    cross_term = 0;
    build(axis, &combined);
    const tf_fitdata *ax[3] = {&axis[0], &axis[1], &axis[2]};
    tf_zhou_orders o;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_zhou_applicable(&ctx, &axis[0]), 0);
    assert_int_equal(tf_zhou_select(&ctx, ax, 5, 1, &o, NULL), 0);
    for (int a = 0; a < 3; ++a) {
        assert_int_equal(o.lambda[a], 1); /* linear contact law */
    }
    for (int pair = 0; pair < 9; ++pair) {
        assert_int_equal(o.a[pair], 2); /* x^2 */
        assert_int_equal(o.b[pair], 3); /* y^3 */
        assert_int_equal(o.k[pair], 1); /* p linear in t */
    }
    tf_model *m = tf_zhou_fit(&ctx, ax, &o, "z");
    assert_non_null(m);
    double max;
    tf_family_errors(m, &combined, NULL, NC, &max, NULL, NULL); /* superposed forces */
    assert_true(max < 1e-5);
    tf_model_free(m);
}

static void cannot_hold_a_cross_term(void **state)
{
    (void)state;
    tf_fitdata axis[3], combined;
    cross_term = 1;
    build(axis, &combined);
    const tf_fitdata *ax[3] = {&axis[0], &axis[1], &axis[2]};
    tf_zhou_orders o;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_zhou_select(&ctx, ax, 5, 1, &o, NULL), 0);
    tf_model *m = tf_zhou_fit(&ctx, ax, &o, "z");
    double max;
    tf_family_errors(m, &combined, NULL, NC, &max, NULL, NULL);
    assert_true(max > 0.1); /* separable surfaces miss x*y */
    tf_model_free(m);
}

static void refuses_what_it_cannot_model(void **state)
{
    (void)state;
    tf_fitdata axis[3], combined;
    cross_term = 0;
    build(axis, &combined);
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    rest[5][2] = 5.0;
    assert_int_equal(tf_zhou_applicable(&ctx, &axis[0]), -1);
    assert_non_null(strstr(ctx.err, "one plane"));
    rest[5][2] = 6.0;
    axis[0].centre[2] = -0.5;
    assert_int_equal(tf_zhou_applicable(&ctx, &axis[0]), -1);
    assert_non_null(strstr(ctx.err, "centred at zero"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(recovers_a_separable_field),
        cmocka_unit_test(cannot_hold_a_cross_term),
        cmocka_unit_test(refuses_what_it_cannot_model),
    };
    return cmocka_run_group_tests_name("fit_zhou2017", tests, NULL, NULL);
}
