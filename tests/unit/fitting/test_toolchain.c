/*
 * test_toolchain.c — the host library, as host.mk compiles it (-O2), rounds
 * doubles to float where the code says so.  GCC 12.2's SLP vectorizer
 * compiles tf_forces_to_float()'s loop to round only the last element of each
 * row; host.mk turns that pass off, and this test fails if the workaround is
 * lost.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "fitting/force_samples.h"

static void every_element_is_rounded(void **state)
{
    (void)state;
    double rows[4][3];
    for (int i = 0; i < 4; ++i) {
        for (int k = 0; k < 3; ++k) {
            rows[i][k] = 0.1 + 0.01 * (3 * i + k); /* none is a float */
        }
    }
    tf_forces_to_float(rows, 4);
    for (int i = 0; i < 4; ++i) {
        for (int k = 0; k < 3; ++k) {
            assert_true(rows[i][k] == (double)(float)(0.1 + 0.01 * (3 * i + k)));
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(every_element_is_rounded)};
    return cmocka_run_group_tests_name("toolchain", tests, NULL, NULL);
}
