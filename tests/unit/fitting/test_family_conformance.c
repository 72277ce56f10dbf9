/*
 * test_family_conformance.c — what every registered family
 * (fitting/families/registry.c) must do, through the registry only, on the
 * load cases of block48 (GUIDE §5):
 *
 *   entry         id, name and kind are its own (found by name and by id),
 *                 every operation but the optional forms is there;
 *   order search  select() gives a valid model of the family's id and kind;
 *                 where it searched degrees, the chosen one is within 2 %
 *                 (plus 1e-6) of the best cross-validated error;
 *   exact data    cases made from the model's own predictions are fitted
 *                 again at its orders to float precision (1e-5 of the
 *                 largest value);
 *   CV            on those cases the cross-validated error is at float
 *                 precision too (for a family whose fit takes a selection
 *                 of cases; one that does not must refuse a selection and
 *                 its order search must find exact orders);
 *   Q31 form      where declared, the quantised model adds at most 8 units
 *                 in the last place of its output words (a few roundings;
 *                 measured about 1); where not, the header says so;
 *   cost          the cost operation agrees with the reference evaluator's
 *                 own operation count and with the emitted header's macros.
 *
 * A new family is tested by registering it: nothing here names one.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "base/context.h"
#include "emit/emit_header.h"
#include "fitting/cases.h"
#include "fitting/cut_progress.h"
#include "fitting/families/family.h"
#include "fitting/histories.h"
#include "model/q31.h"
#include "model/ref_eval.h"
#include "scene/scene.h"
#include "solvers/solver.h"

/* block48 and its solved cases, shared by every test.  The cases carry
 * force histories of block48 as a linear viscoelastic body (seed 001's
 * Kelvin solid with k1 = E, k2 = 0.6 k1, eta = k2 s: an illustrative
 * creep, histories.h), so that a time-dependent family (prony) applies,
 * and the responses of block48 with block48_cut's incision at a few cut
 * progress values (cut_progress.h), so that the cut family applies; the
 * others ignore them. */
typedef struct fixture {
    tf_ctx ctx;
    tf_scene *scene, *cut_scene;
    tf_solver *solver;
    tf_fit_plan plan;
    tf_cases cases;
    tf_histories hist;
    tf_cut_cases cut;
} fixture;

/* The cut cases: block48 with a 20 mm incision, s = 0, 1/2, 1, the two
 * midpoints and two held-out values. */
static int cut_cases(fixture *x)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const char *sets[] = {"cuts=[{path: [[18, 14], [18, 34]], depth: 3}]"};
    x->cut_scene = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", sets, 1);
    if (x->cut_scene == NULL) {
        print_error("%s\n", ctx.err);
        return -1;
    }
    tf_fit_plan plan = x->plan;
    plan.cut_intervals = 2;
    plan.cut_heldout = 2;
    if (tf_cut_cases_solve(&x->cut_scene->problem, x->solver, &plan, &x->cut) != 0) {
        print_error("%s\n", x->ctx.err);
        return -1;
    }
    x->cases.cut = &x->cut;
    return 0;
}

static int setup(void **state)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    fixture *x = calloc(1, sizeof *x);
    tf_ctx_init(&x->ctx);
    x->ctx.level = TF_LOG_ERROR;
    x->scene = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", NULL, 0);
    if (x->scene == NULL) {
        print_error("%s\n", ctx.err);
        return -1;
    }
    x->plan = x->scene->fit;
    x->solver = tf_solver_create(&x->scene->problem, NULL, &x->ctx);
    if (x->solver == NULL ||
        tf_cases_build(&x->scene->problem, x->solver, &x->plan, &x->cases) != 0) {
        print_error("%s\n", x->ctx.err);
        return -1;
    }
    const tf_creep creep = tf_creep_kelvin(0.32, 0.192, 0.192);
    if (tf_histories_linear_creep(&ctx, &x->cases, &creep, 1000000, 8, 4, 1500, x->plan.seed,
                                  &x->hist) != 0) {
        print_error("%s\n", ctx.err);
        return -1;
    }
    x->cases.hist = &x->hist;
    if (cut_cases(x) != 0) {
        return -1;
    }
    *state = x;
    return 0;
}

static int teardown(void **state)
{
    fixture *x = *state;
    tf_histories_free(&x->hist);
    tf_cut_cases_free(&x->cut);
    tf_scene_free(x->cut_scene);
    tf_cases_free(&x->cases);
    tf_solver_destroy(x->solver);
    tf_scene_free(x->scene);
    free(x);
    return 0;
}

/* The family's model of block48 by its own order search. */
static tf_model *selected(const fixture *x, const tf_family *f, tf_family_result *r)
{
    memset(r, 0, sizeof *r);
    r->family = f;
    for (int p = 0; p <= TFIT_MAX_DEGREE; ++p) {
        r->cv[p] = INFINITY;
    }
    for (int k = 0; k <= TF_FAMILY_MAX_RANK; ++k) {
        r->cv_rank[k] = r->heldout_rank[k] = INFINITY;
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_fit_plan plan = x->plan; /* asked for by name (the resonant family applies only so) */
    plan.family = f->kind == TF_FAMILY_FORWARD ? f : plan.family;
    if (f->applicable(&ctx, &x->cases, &plan) != 0) {
        fail_msg("%s does not apply to block48: %s", f->name, ctx.err);
    }
    if (f->select(&ctx, &x->cases, &plan, r) != 0) {
        fail_msg("%s: %s", f->name, ctx.err);
    }
    return r->model;
}

static void entries_are_complete(void **state)
{
    (void)state;
    assert_true(tf_family_count() > 0);
    for (size_t i = 0; i < tf_family_count(); ++i) {
        const tf_family *f = tf_family_at(i);
        assert_non_null(f->name);
        assert_ptr_equal(tf_family_find(f->name), f);
        assert_ptr_equal(tf_family_of(f->id), f);
        assert_true(f->kind == TF_FAMILY_FORWARD || f->kind == TF_FAMILY_INVERSE);
        assert_non_null(f->applicable);
        assert_non_null(f->select);
        assert_non_null(f->fit);
        assert_non_null(f->candidates);
        assert_non_null(f->orders_text);
        assert_non_null(f->cost);
        /* a family fitted from a contact region (check-cli, check-region)
         * refuses load cases with a message */
        if (f->region != NULL) {
            tf_ctx ctx;
            tf_ctx_init(&ctx);
            assert_int_not_equal(f->applicable(&ctx, NULL, NULL), 0);
            assert_true(ctx.err[0] != '\0');
        }
    }
}

static void order_search_gives_a_valid_model(void **state)
{
    fixture *x = *state;
    for (size_t i = 0; i < tf_family_count(); ++i) {
        const tf_family *f = tf_family_at(i);
        if (f->region != NULL) { /* fitted from a contact region, not from cases */
            continue;
        }
        tf_family_result r;
        tf_model *m = selected(x, f, &r);
        char orders[256];
        tf_ctx ctx;
        tf_ctx_init(&ctx);
        if (tf_model_validate(&ctx, m) != 0) {
            fail_msg("%s: %s", f->name, ctx.err);
        }
        assert_int_equal(m->family, f->id);
        assert_int_equal(m->n_out, f->kind == TF_FAMILY_INVERSE ? 1 : x->cases.train.n_out);
        f->orders_text(m, TF_ORDERS_FULL, orders, sizeof orders);
        assert_true(orders[0] != '\0');
        double best = INFINITY;
        for (int p = 0; p <= TFIT_MAX_DEGREE; ++p) {
            best = fmin(best, r.cv[p]);
        }
        if (isfinite(best)) { /* it searched a degree: dims[0] */
            assert_true(r.cv[m->dims[0]] <= 1.02 * best + 1e-6);
        }
        print_message("%-9s orders %s; CV best %.3g\n", f->name, orders, best);
        tf_model_free(m);
    }
}

/* Cases whose data are m's own predictions (float32, as the target gives
 * them) at the same inputs: the outputs for a forward model, the forces
 * for an inverse one.  Returns the largest value; *c shares everything
 * else with base; free the arrays with free_exact. */
static double exact_cases(const tf_cases *base, const tf_model *m, int inverse, tf_cases *c)
{
    *c = *base;
    tf_fitdata *sets[5] = {&c->train, &c->heldout, &c->axis[0], &c->axis[1], &c->axis[2]};
    const size_t rows = 3 * (size_t)m->n_out;
    float *out = malloc(rows * sizeof *out);
    double big = 0;
    for (int s = 0; s < 5; ++s) {
        tf_fitdata *d = sets[s];
        double *u = inverse ? NULL : malloc(d->n_cases * rows * sizeof *u);
        double(*force)[3] = inverse ? malloc(d->n_cases * sizeof *force) : NULL;
        for (size_t i = 0; i < d->n_cases; ++i) {
            const double *in = inverse ? d->contact[i] : d->force[i];
            const float g[3] = {(float)in[0], (float)in[1], (float)in[2]};
            assert_int_equal(tf_ref_eval(m, g, out, NULL), TFIT_OK);
            for (size_t o = 0; o < rows; ++o) {
                if (inverse) {
                    force[i][o] = (double)out[o];
                } else {
                    u[i * rows + o] = (double)out[o];
                }
                big = fmax(big, fabs((double)out[o]));
            }
        }
        if (inverse) {
            d->force = (const double(*)[3])force;
        } else {
            d->u = u;
        }
    }
    free(out);
    return big;
}

static void free_exact(tf_cases *c, int inverse)
{
    tf_fitdata *sets[5] = {&c->train, &c->heldout, &c->axis[0], &c->axis[1], &c->axis[2]};
    for (int s = 0; s < 5; ++s) {
        free(inverse ? (void *)sets[s]->force : (void *)sets[s]->u);
    }
}

static void exact_data_is_reproduced_and_cross_validated(void **state)
{
    fixture *x = *state;
    for (size_t i = 0; i < tf_family_count(); ++i) {
        const tf_family *f = tf_family_at(i);
        if (f->region != NULL) { /* fitted from a contact region, not from cases */
            continue;
        }
        const int inverse = f->kind == TF_FAMILY_INVERSE;
        tf_family_result r;
        tf_model *m = selected(x, f, &r);
        tf_cases c;
        tf_ctx ctx;
        tf_ctx_init(&ctx);
        const double big = exact_cases(&x->cases, m, inverse, &c);
        /* a family that stores its model in integers reproduces to its
         * quantisation: modal_q15's 8 amplitudes of 13 bits each
         * (header-format.md §5.9), 8 / 8191 of the largest value */
        const double tol = f->id == TFIT_FAMILY_MODAL_Q15 ? 8.0 / 8191.0 : 1e-5;
        tf_model *again = f->fit(&ctx, &c, NULL, 0, m->dims);
        if (again == NULL) {
            fail_msg("%s: refit on its own predictions: %s", f->name, ctx.err);
        }
        double fit_max, cv_rms;
        tf_family_errors(again, &c.train, NULL, c.train.n_cases, &fit_max, NULL, NULL);
        print_message("%-9s refit on its own predictions: max error %.3g of the largest value\n",
                      f->name, fit_max / big);
        assert_true(fit_max <= tol * big);
        size_t half[50];
        for (size_t k = 0; k < 50; ++k) {
            half[k] = 2 * k;
        }
        tf_model *part = f->fit(&ctx, &c, half, 50, m->dims);
        if (part != NULL) { /* a fit on a selection: k-fold CV applies */
            assert_int_equal(tf_family_cv_error(&ctx, f, &c, m->dims, x->plan.folds, x->plan.seed,
                                                &cv_rms, NULL),
                             0);
            print_message("%-9s CV on its own predictions: RMS %.3g of the largest value\n",
                          f->name, cv_rms / big);
            assert_true(cv_rms <= tol * big);
            tf_model_free(part);
        } else { /* refused: its own order search must find exact orders */
            tf_family_result rr;
            memset(&rr, 0, sizeof rr);
            rr.family = f;
            assert_int_equal(f->select(&ctx, &c, &x->plan, &rr), 0);
            tf_family_errors(rr.model, &c.train, NULL, c.train.n_cases, &fit_max, NULL, NULL);
            print_message("%-9s no fit on a selection; its order search on its own "
                          "predictions: max error %.3g of the largest value\n",
                          f->name, fit_max / big);
            assert_true(fit_max <= tol * big);
            tf_model_free(rr.model);
        }
        tf_model_free(again);
        free_exact(&c, inverse);
        tf_model_free(m);
    }
}

static char *slurp(const char *path)
{
    FILE *fp = fopen(path, "rb");
    assert_non_null(fp);
    fseek(fp, 0, SEEK_END);
    long n = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    char *s = calloc((size_t)n + 1, 1);
    assert_int_equal(fread(s, 1, (size_t)n, fp), (size_t)n);
    fclose(fp);
    return s;
}

/* The value of "#define TFIT_CONF_<name> value" in a header. */
static unsigned long long macro(const char *h, const char *name)
{
    char key[128];
    snprintf(key, sizeof key, "#define TFIT_CONF_%s ", name);
    const char *at = strstr(h, key);
    if (at == NULL) {
        fail_msg("the header has no %s", key);
    }
    return strtoull(at + strlen(key), NULL, 10);
}

static void q31_form_and_cost_match_the_header(void **state)
{
    fixture *x = *state;
    char dir[] = "/tmp/tf_family_XXXXXX";
    assert_non_null(mkdtemp(dir));
    for (size_t i = 0; i < tf_family_count(); ++i) {
        const tf_family *f = tf_family_at(i);
        if (f->region != NULL) { /* fitted from a contact region, not from cases */
            continue;
        }
        tf_family_result r;
        tf_model *m = selected(x, f, &r);
        char path[64], golden[80];
        tf_ctx ctx;
        tf_ctx_init(&ctx);
        snprintf(m->name, sizeof m->name, "conf");
        snprintf(path, sizeof path, "%s/conf.h", dir);
        const tf_emit_info info = {.source = "test", .notes = NULL, .golden_seed = 1};
        tf_model *one[1] = {m};
        assert_int_equal(tf_emit_header(&ctx, path, one, 1, &info), 0);
        char *h = slurp(path);
        tf_family_cost cost;
        f->cost(m, &cost);
        assert_int_equal(macro(h, "OPS_ADD"), cost.ops.add);
        assert_int_equal(macro(h, "OPS_MUL"), cost.ops.mul);
        assert_int_equal(macro(h, "OPS_DIV"), cost.ops.div);
        assert_int_equal(macro(h, "TABLE_BYTES"), cost.table_bytes);
        assert_int_equal(macro(h, "INSNS_ARMV7EM"), cost.m4f.instructions);
        tf_opcount counted = {0, 0, 0};
        const float centre[3] = {m->coef[0], m->coef[1], m->coef[2]};
        float *out = malloc(3 * (size_t)m->n_out * sizeof *out);
        assert_int_equal(tf_ref_eval(m, centre, out, &counted), TFIT_OK);
        assert_int_equal(counted.add, cost.ops.add);
        assert_int_equal(counted.mul, cost.ops.mul);
        assert_int_equal(counted.div, cost.ops.div);
        free(out);
        if (f->q31 != NULL) {
            tf_q31 *q = f->q31(&ctx, m);
            if (q == NULL) {
                fail_msg("%s declares a Q31 form: %s", f->name, ctx.err);
            }
            tf_q31_measure(q, m, 7, 2000);
            const double lsb = ldexp(1, q->out_exp - 31);
            print_message("%-9s Q31 form adds %.3g = %.2f output LSB (float32 path %.3g)\n",
                          f->name, q->added_error, q->added_error / lsb, q->float_error);
            assert_true(q->added_error <= 8 * lsb);
            assert_non_null(strstr(h, "extern const tfit_model_q31 tfit_conf_q31;"));
            tf_q31_free(q);
        } else {
            assert_non_null(strstr(h, "no Q31 form"));
            assert_null(strstr(h, "tfit_conf_q31"));
        }
        free(h);
        unlink(path);
        assert_int_equal(tf_golden_path(path, golden, sizeof golden), 0);
        unlink(golden);
        tf_model_free(m);
    }
    rmdir(dir);
}

int main(void)
{
    char forward[256], inverse[256];
    tf_family_names(TF_FAMILY_FORWARD, forward, sizeof forward);
    tf_family_names(TF_FAMILY_INVERSE, inverse, sizeof inverse);
    print_message("family conformance: %zu registered: forward %s; inverse %s\n",
                  tf_family_count(), forward, inverse);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(entries_are_complete),
        cmocka_unit_test(order_search_gives_a_valid_model),
        cmocka_unit_test(exact_data_is_reproduced_and_cross_validated),
        cmocka_unit_test(q31_form_and_cost_match_the_header),
    };
    return cmocka_run_group_tests_name("family_conformance", tests, setup, teardown);
}
