/*
 * test_cycles.c — the cycle model (host/cost/cycles.c) and its header macros.
 *
 * The model's agreement with the compiled code is proved on the device by
 * make check-cycles (objdump loop mixes, QEMU traces).  These tests pin the
 * other half: that the cycles per class are the Cortex-M4 TRM numbers the
 * documentation derives by hand, that counts scale with the model's shape
 * as the loop structure says, and that the header carries the estimate.
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

#include "cost/cycles.h"
#include "emit/emit_header.h"

static tf_model *shape(tfit_family f, uint32_t n_out, uint32_t p, uint32_t r)
{
    char err[256];
    uint32_t dims[2] = {p, r};
    tf_model *m = tf_model_new("shape", f, n_out, dims, f == TFIT_FAMILY_MODAL ? 2 : 1, err,
                               sizeof err);
    assert_non_null(m);
    return m;
}

static void mix_text_round_trip(void **state)
{
    (void)state;
    tf_insn_mix m;
    char buf[256];
    assert_int_equal(tf_insn_mix_parse("alu=7 store=3 fload=12 fadd=9 fmul=9 fmov=3 branch=1", &m),
                     0);
    assert_int_equal(tf_insn_mix_count(&m), 44);
    tf_insn_mix_format(&m, buf, sizeof buf);
    assert_string_equal(buf, "alu=7 store=3 fload=12 fadd=9 fmul=9 fmov=3 branch=1");
    assert_int_equal(tf_insn_mix_parse("ldm=1 words=5", &m), 0);
    assert_int_equal(tf_insn_mix_count(&m), 1); /* words are not instructions */
    assert_int_equal(tf_insn_mix_parse("alu=1 vfoo=2", &m), -1);
    assert_int_equal(tf_insn_mix_parse("alu", &m), -1);
}

/* One more output point of a p = 1 nodal model adds one pass of the
 * compiled node loop: 12 VLDR, 9 VMUL, 9 VADD, 3 VMOV, 3 STR, 7 data
 * processing, 1 taken branch.  Cortex-M4 TRM: VLDR 2, STR 2, FPU 1, ALU 1,
 * branch 1 + P with P <= 3 -> 24 + 18 + 3 + 6 + 7 + 4 = 62 cycles; at the
 * fast end (loads pipelined, P = 1... counted 1) 12 + 18 + 3 + 3 + 7 + 1 = 44. */
static void node_cost_is_the_trm_sum(void **state)
{
    (void)state;
    tf_model *a = shape(TFIT_FAMILY_NODAL, 121, 1, 0), *b = shape(TFIT_FAMILY_NODAL, 122, 1, 0);
    tf_cycles ca = tf_cycles_estimate(a, TF_CORE_M4F), cb = tf_cycles_estimate(b, TF_CORE_M4F);
    assert_int_equal(cb.instructions - ca.instructions, 44);
    assert_true(fabs(cb.cycles - ca.cycles - 62.0) < 1e-9);
    assert_true(fabs(cb.cycles_low - ca.cycles_low - 44.0) < 1e-9);
    /* block48's full surface on the M4F: within the 50 us budget (GUIDE §7) */
    assert_true(ca.cycles / tf_core_mhz(TF_CORE_M4F) <= 50.0);
    tf_model_free(a);
    tf_model_free(b);
}

/* Any p: per output point the node loop (27 instructions) plus T-1 term
 * passes (13 each); p = 0 skips the term loop's 5-instruction set-up. */
static void counts_follow_the_loop_structure(void **state)
{
    (void)state;
    for (uint32_t p = 0; p <= TFIT_MAX_DEGREE; ++p) {
        if (p == 1) {
            continue;
        }
        tf_model *a = shape(TFIT_FAMILY_NODAL, 5, p, 0), *b = shape(TFIT_FAMILY_NODAL, 6, p, 0);
        uint64_t per_node = tf_cycles_estimate(b, TF_CORE_M4F).instructions -
                            tf_cycles_estimate(a, TF_CORE_M4F).instructions;
        assert_int_equal(per_node, 27 + 13 * (tf_terms(p) - 1) - (p == 0 ? 5 : 0));
        tf_model_free(a);
        tf_model_free(b);
    }
    /* modal: one more mode costs one amplitude row and one pass per point */
    tf_model *a = shape(TFIT_FAMILY_MODAL, 4, 2, 3), *b = shape(TFIT_FAMILY_MODAL, 4, 2, 4);
    uint64_t per_mode = tf_cycles_estimate(b, TF_CORE_M4F).instructions -
                        tf_cycles_estimate(a, TF_CORE_M4F).instructions;
    assert_int_equal(per_mode, 10 + 9 * 7 + 4 * 12);
    tf_model_free(a);
    tf_model_free(b);
    /* p != 1: the contact entry point tests the degree, then tail-calls the
     * shared evaluator: 10 instructions more than the forward entry */
    tf_model *c = shape(TFIT_FAMILY_CONTACT, 1, 2, 0), *n = shape(TFIT_FAMILY_NODAL, 1, 2, 0);
    assert_int_equal(tf_cycles_estimate(c, TF_CORE_M4F).instructions -
                         tf_cycles_estimate(n, TF_CORE_M4F).instructions,
                     10);
    /* p = 1: the contact fast path skips the dispatch and the nodal set-up:
     * 31 instructions fewer than the same model through the forward entry */
    tf_model *c1 = shape(TFIT_FAMILY_CONTACT, 1, 1, 0), *n1 = shape(TFIT_FAMILY_NODAL, 1, 1, 0);
    assert_int_equal(tf_cycles_estimate(n1, TF_CORE_M4F).instructions -
                         tf_cycles_estimate(c1, TF_CORE_M4F).instructions,
                     31);
    tf_model_free(c1);
    tf_model_free(n1);
    /* the M7 model is faster per cycle, and not slower in time */
    tf_cycles m4 = tf_cycles_estimate(n, TF_CORE_M4F), m7 = tf_cycles_estimate(n, TF_CORE_M7);
    assert_true(m7.cycles < m4.cycles);
    assert_true(m7.cycles_low <= m7.cycles && m4.cycles_low <= m4.cycles);
    tf_model_free(c);
    tf_model_free(n);
}

static void header_carries_the_estimate(void **state)
{
    (void)state;
    char dir[] = "/tmp/tfit_cycles_XXXXXX", path[300], gpath[300], err[512], want[160];
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/budget.h", dir);
    tf_model *m = shape(TFIT_FAMILY_NODAL, 121, 1, 0);
    snprintf(m->name, sizeof m->name, "block_forward");
    const tf_emit_info info = {.source = "test", .golden_seed = 1};
    assert_int_equal(tf_emit_header(path, &m, 1, &info, err, sizeof err), 0);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    static char text[1 << 20];
    size_t len = fread(text, 1, sizeof text - 1, f);
    text[len] = '\0';
    fclose(f);
    tf_cycles c4 = tf_cycles_estimate(m, TF_CORE_M4F), c7 = tf_cycles_estimate(m, TF_CORE_M7);
    snprintf(want, sizeof want, "#define TFIT_BLOCK_FORWARD_CYCLES_M4F %.0fu", ceil(c4.cycles));
    assert_non_null(strstr(text, want));
    snprintf(want, sizeof want, "#define TFIT_BLOCK_FORWARD_CYCLES_M7 %.0fu", ceil(c7.cycles));
    assert_non_null(strstr(text, want));
    snprintf(want, sizeof want, "#define TFIT_BLOCK_FORWARD_INSNS_ARMV7EM %llu",
             (unsigned long long)c4.instructions);
    assert_non_null(strstr(text, want));
    assert_non_null(strstr(text, "#define TFIT_BLOCK_FORWARD_US_M4F_168MHZ "));
    tf_golden_path(path, gpath, sizeof gpath);
    unlink(gpath);
    unlink(path);
    rmdir(dir);
    tf_model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(mix_text_round_trip),
        cmocka_unit_test(node_cost_is_the_trm_sum),
        cmocka_unit_test(counts_follow_the_loop_structure),
        cmocka_unit_test(header_carries_the_estimate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
