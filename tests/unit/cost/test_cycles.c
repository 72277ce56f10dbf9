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
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    uint32_t dims[2] = {p, r};
    tf_model *m = tf_model_new(&ctx, "shape", f, n_out, dims, f == TFIT_FAMILY_MODAL ? 2 : 1);
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
    assert_int_equal(tf_insn_mix_parse("branch=2 nbranch=3", &m), 0);
    assert_int_equal(tf_insn_mix_count(&m), 5); /* taken and fall-through branches */
    assert_int_equal(tf_insn_mix_parse("alu=1 vfoo=2", &m), -1);
    assert_int_equal(tf_insn_mix_parse("alu", &m), -1);
}

/* Degree 1 (tfit_degree1_armv7em.c).  One more pair of output points of a
 * p = 1 nodal model runs the remainder loop once more: VLDM of 24 words,
 * 18 VMUL + 18 VADD, VSTM of 6 words, SUBS, a taken BNE.  Cortex-M4 TRM:
 * VLDM/VSTM 1 + N, FPU 1, ALU 1, taken branch 1 + P with P = 1..3 ->
 * 25 + 36 + 7 + 1 + 4 = 73 cycles, 71 with P = 1.  Sixteen more points run
 * the main loop once more: 8 pairs (25 + 36 + 7 each), SUB, SUBS, BNE ->
 * 544 + 2 + 4 = 550 cycles (548 with P = 1). */
static void pair_cost_is_the_trm_sum(void **state)
{
    (void)state;
    tf_model *a = shape(TFIT_FAMILY_NODAL, 121, 1, 0), *b = shape(TFIT_FAMILY_NODAL, 123, 1, 0);
    tf_model *c = shape(TFIT_FAMILY_NODAL, 137, 1, 0);
    tf_cycles ca = tf_model_cycles(a, TF_CORE_M4F), cb = tf_model_cycles(b, TF_CORE_M4F);
    tf_cycles cc = tf_model_cycles(c, TF_CORE_M4F);
    assert_int_equal(cb.instructions - ca.instructions, 40);
    assert_true(fabs(cb.cycles - ca.cycles - 73.0) < 1e-9);
    assert_true(fabs(cb.cycles_low - ca.cycles_low - 71.0) < 1e-9);
    assert_int_equal(cc.instructions - ca.instructions, 8 * 38 + 3);
    assert_true(fabs(cc.cycles - ca.cycles - 550.0) < 1e-9);
    assert_true(fabs(cc.cycles_low - ca.cycles_low - 548.0) < 1e-9);
    /* block48's full surface (1,464 coefficients) on the M4F: at most 3
     * cycles per coefficient at the upper bound (issue 20) */
    assert_true(ca.cycles <= 3.0 * (12 + 121 * 12));
    tf_model_free(a);
    tf_model_free(b);
    tf_model_free(c);
}

/* The lower bound charges a taken branch 2 cycles (1 + P, P >= 1) and one
 * that falls through 1 (Cortex-M4 TRM): a model whose every branch were
 * counted at 1 would be lower still, so the minimum is a true bound. */
static void minimum_charges_taken_branches_two(void **state)
{
    (void)state;
    tf_insn_mix taken = {{0}}, through = {{0}};
    taken.n[TF_INSN_BRANCH] = 1;
    through.n[TF_INSN_NBRANCH] = 1;
    assert_true(fabs(tf_cycles_of_mix(&taken, TF_CORE_M4F).cycles_low - 2.0) < 1e-9);
    assert_true(fabs(tf_cycles_of_mix(&taken, TF_CORE_M4F).cycles - 4.0) < 1e-9);
    assert_true(fabs(tf_cycles_of_mix(&through, TF_CORE_M4F).cycles_low - 1.0) < 1e-9);
    assert_true(fabs(tf_cycles_of_mix(&through, TF_CORE_M4F).cycles - 1.0) < 1e-9);
    /* every shape's minimum counts its taken branches twice */
    for (uint32_t p = 0; p <= 3; ++p) {
        tf_model *m = shape(TFIT_FAMILY_NODAL, 5, p, 0);
        tf_insn_mix mix;
        tf_model_insn_mix(m, TF_CORE_M4F, &mix);
        tf_insn_mix one = mix;
        one.n[TF_INSN_NBRANCH] += one.n[TF_INSN_BRANCH];
        one.n[TF_INSN_BRANCH] = 0;
        assert_true(mix.n[TF_INSN_BRANCH] > 0);
        assert_true(fabs(tf_cycles_of_mix(&mix, TF_CORE_M4F).cycles_low -
                         tf_cycles_of_mix(&one, TF_CORE_M4F).cycles_low -
                         mix.n[TF_INSN_BRANCH]) < 1e-9);
        tf_model_free(m);
    }
}

/* Any p: per output point the node loop (29 instructions) plus T-1 term
 * passes (13 each); p = 0 skips the term loop's 5-instruction set-up. */
static void counts_follow_the_loop_structure(void **state)
{
    (void)state;
    for (uint32_t p = 0; p <= TFIT_MAX_DEGREE; ++p) {
        if (p == 1) {
            continue;
        }
        tf_model *a = shape(TFIT_FAMILY_NODAL, 5, p, 0), *b = shape(TFIT_FAMILY_NODAL, 6, p, 0);
        uint64_t per_node = tf_model_cycles(b, TF_CORE_M4F).instructions -
                            tf_model_cycles(a, TF_CORE_M4F).instructions;
        assert_int_equal(per_node, 29 + 13 * (tf_terms(p) - 1) - (p == 0 ? 5 : 0));
        tf_model_free(a);
        tf_model_free(b);
    }
    /* modal: one more mode costs one amplitude row (12 instructions and 9
     * terms of 7), and per output point 3 VMUL + 3 VADD in the assembly
     * rows (ranks <= 8: its words come with the same VLDM), or a 12-
     * instruction pass of the C mode loop above rank 8 */
    tf_model *a = shape(TFIT_FAMILY_MODAL, 4, 2, 3), *b = shape(TFIT_FAMILY_MODAL, 4, 2, 4);
    uint64_t per_mode = tf_model_cycles(b, TF_CORE_M4F).instructions -
                        tf_model_cycles(a, TF_CORE_M4F).instructions;
    assert_int_equal(per_mode, 12 + 9 * 7 + 4 * 6);
    tf_model_free(a);
    tf_model_free(b);
    a = shape(TFIT_FAMILY_MODAL, 4, 2, 9);
    b = shape(TFIT_FAMILY_MODAL, 4, 2, 10);
    per_mode = tf_model_cycles(b, TF_CORE_M4F).instructions -
               tf_model_cycles(a, TF_CORE_M4F).instructions;
    assert_int_equal(per_mode, 12 + 9 * 7 + 4 * 12);
    tf_model_free(a);
    tf_model_free(b);
    /* p != 1: both entry points tail-call the shared evaluator; the contact
     * one tests family and degree (15 instructions), the forward one the
     * degree-1 fast path, then the family range (22): 7 fewer */
    tf_model *c = shape(TFIT_FAMILY_CONTACT, 1, 2, 0), *n = shape(TFIT_FAMILY_NODAL, 1, 2, 0);
    assert_int_equal(tf_model_cycles(n, TF_CORE_M4F).instructions -
                         tf_model_cycles(c, TF_CORE_M4F).instructions,
                     7);
    /* p = 1: the one-point routine skips the pair loops' set-up (ldr n_out,
     * vpush/vpop, 9 loop tests) and its entry is 3 instructions shorter */
    tf_model *c1 = shape(TFIT_FAMILY_CONTACT, 1, 1, 0), *n1 = shape(TFIT_FAMILY_NODAL, 1, 1, 0);
    assert_int_equal(tf_model_cycles(n1, TF_CORE_M4F).instructions -
                         tf_model_cycles(c1, TF_CORE_M4F).instructions,
                     15);
    tf_model_free(c1);
    tf_model_free(n1);
    /* the M7 model is faster per cycle, and not slower in time */
    tf_cycles m4 = tf_model_cycles(n, TF_CORE_M4F), m7 = tf_model_cycles(n, TF_CORE_M7);
    assert_true(m7.cycles < m4.cycles);
    assert_true(m7.cycles_low <= m7.cycles && m4.cycles_low <= m4.cycles);
    tf_model_free(c);
    tf_model_free(n);
}

static void header_carries_the_estimate(void **state)
{
    (void)state;
    char dir[] = "/tmp/tfit_cycles_XXXXXX", path[300], gpath[300], want[160];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/budget.h", dir);
    tf_model *m = shape(TFIT_FAMILY_NODAL, 121, 1, 0);
    snprintf(m->name, sizeof m->name, "block_forward");
    const tf_emit_info info = {.source = "test", .golden_seed = 1};
    assert_int_equal(tf_emit_header(&ctx, path, &m, 1, &info), 0);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    static char text[1 << 20];
    size_t len = fread(text, 1, sizeof text - 1, f);
    text[len] = '\0';
    fclose(f);
    tf_cycles c4 = tf_model_cycles(m, TF_CORE_M4F), c7 = tf_model_cycles(m, TF_CORE_M7);
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
        cmocka_unit_test(pair_cost_is_the_trm_sum),
        cmocka_unit_test(minimum_charges_taken_branches_two),
        cmocka_unit_test(counts_follow_the_loop_structure),
        cmocka_unit_test(header_carries_the_estimate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
