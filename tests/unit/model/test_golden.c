/*
 * test_golden.c — the golden input design of every form covers every class
 * the contract names, and the reference evaluator, run as the golden
 * vectors run, gives each its status.
 */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "model/forms/form.h"
#include "model/golden.h"
#include "model/ref_eval.h"
#include "model/region_layout.h"
#include "random_model.h"

static float float_of(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* The input classes of one form's golden design, and the status the
 * reference gives each input when the design is run as the golden vectors
 * run (each alone, at the cut progress of its index, or one tick sequence
 * from rest). */
static void covers_every_input_class(void **state)
{
    (void)state;
    tf_rng r = {8};
    static const uint32_t cut_s[16] = TFIT_CUT_GOLDEN_S_BITS;
    for (int id = TFIT_FAMILY_FIRST; id <= TFIT_FAMILY_LAST; ++id) {
        const tf_form *f = tf_form_of((tfit_family)id);
        assert_non_null(f); /* every id has its form */
        tf_model *m = tf_random_model(&r, "g", f->id, 1);
        assert_non_null(m);
        float in[TF_GOLDEN_MAX][3];
        int32_t status[TF_GOLDEN_MAX];
        const size_t n = tf_golden_design(m, 77, in), n_out = 3 * (size_t)m->n_out;
        int zero = 0, nan = 0, pinf = 0, ninf = 0, subnormal = 0, huge = 0, on_edge = 0;
        int status_seen[3] = {0, 0, 0}, nonfinite = 0, no_contact = 0;
        /* the input map the inputs go through: a region surface's force
         * map follows its chart and scalars; a region law's tips have none
         * (they are tool-tip positions on a chart: no boundary to test) */
        const int law = f->id == TFIT_FAMILY_REGION;
        tf_model map = *m;
        if (f->id == TFIT_FAMILY_REGION_SURFACE) {
            map.coef = m->coef + TF_REGION_FORCE_MAP;
        }
        float *out = malloc(n * n_out * sizeof *out);
        assert_true(n >= 60 && n <= TF_GOLDEN_MAX);
        tf_ref_run(m, (const float(*)[3])in, n, status, out);
        for (size_t v = 0; v < n; ++v) {
            int bad_input = 0;
            for (int i = 0; i < 3; ++i) {
                float x = in[v][i];
                nan += isnan(x);
                pinf += isinf(x) && x > 0;
                ninf += isinf(x) && x < 0;
                subnormal += fpclassify(x) == FP_SUBNORMAL;
                huge += fabsf(x) >= 1e38f && isfinite(x);
                bad_input |= !isfinite(x);
            }
            zero += in[v][0] == 0 && in[v][1] == 0 && in[v][2] == 0;
            float g[3];
            int clamped, bad;
            tf_ref_input(&map, in[v], g, &clamped, &bad, NULL);
            double gn = sqrt((double)g[0] * g[0] + (double)g[1] * g[1] + (double)g[2] * g[2]);
            on_edge += !law && !bad && fabs(gn - 1.0) < 1e-6;
            const int s = status[v];
            if (s == TFIT_NO_CONTACT) { /* a region law's tip off the surface */
                ++no_contact;
                continue;
            }
            status_seen[s == TFIT_OK ? 0 : (s == TFIT_CLAMPED ? 1 : 2)]++;
            /* NaN/Inf in the input, or in a cut model's progress, and only
             * then: TFIT_ERR_INPUT and +0.0f outputs */
            bad_input |= m->family == TFIT_FAMILY_CUT && !isfinite(float_of(cut_s[v & 15]));
            nonfinite += bad_input;
            assert_int_equal(s == TFIT_ERR_INPUT, bad_input);
            for (size_t o = 0; o < n_out; ++o) {
                assert_true(isfinite(out[v * n_out + o]));
                if (bad_input) {
                    assert_true(out[v * n_out + o] == 0.0f && !signbit(out[v * n_out + o]));
                }
            }
        }
        print_message("%-9s: %zu inputs: %d in, %d clamped, %d rejected, %d not in contact; %d "
                      "on the boundary\n",
                      f->name, n, status_seen[0], status_seen[1], status_seen[2], no_contact,
                      on_edge);
        assert_true(zero >= 1);
        assert_true(nan >= 4);
        /* both infinities (the tick designs have one +Inf among their ticks) */
        assert_true(pinf >= 1 && ninf >= 1 && pinf + ninf >= (law ? 2 : 3));
        assert_true(subnormal >= 3);
        assert_true(huge >= 3);
        if (law) { /* tips above the surface, lifting off, away */
            assert_true(no_contact >= 8);
            assert_true(status_seen[0] >= 10 && status_seen[1] >= 10);
            assert_true(nonfinite >= 6 && status_seen[2] == nonfinite);
            free(out);
            tf_model_free(m);
            continue;
        }
        assert_int_equal(no_contact, 0);
        assert_true(on_edge >= 14);
        /* beyond the envelope: 10x, 1e30x and the largest floats (fewer ticks) */
        assert_true(status_seen[0] >= 20 && status_seen[1] >= (f->golden_inputs == tf_golden_ticks ? 7 : 10));
        assert_true(nonfinite >= 6 && status_seen[2] == nonfinite);
        free(out);
        tf_model_free(m);
    }
}

static void deterministic_for_a_seed(void **state)
{
    (void)state;
    tf_rng r = {9};
    tf_model *m = tf_random_model(&r, "g", TFIT_FAMILY_MODAL, 1);
    float a[TF_GOLDEN_MAX][3], b[TF_GOLDEN_MAX][3];
    size_t na = tf_golden_inputs(m, 5, a), nb = tf_golden_inputs(m, 5, b);
    assert_int_equal(na, nb);
    assert_memory_equal(a, b, na * sizeof a[0]);
    size_t nc = tf_golden_inputs(m, 6, b);
    assert_int_equal(na, nc);
    assert_true(memcmp(a[2], b[2], sizeof a[2]) != 0); /* random part follows the seed */
    tf_model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(covers_every_input_class),
        cmocka_unit_test(deterministic_for_a_seed),
    };
    return cmocka_run_group_tests_name("golden", tests, NULL, NULL);
}
