/*
 * test_sparsity.c — the stiffness pattern (solvers/sparsity.h): a node that
 * no cell holds is refused with a message naming it, rather than sized as
 * a negative number of entries (it overflowed the pattern's buffer when a
 * cut on a graded cloud left a node uncovered).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "solvers/sparsity.h"

/* Two cells over nodes {0, 1, 2} and {1, 2, 3}, with n_nodes nodes. */
static int pattern(tf_ctx *ctx, size_t n_nodes, tf_nodesets *blocks, tf_csc *k)
{
    size_t ptr[] = {0, 3, 6};
    uint32_t nodes[] = {0, 1, 2, 1, 2, 3};
    tf_nodesets cells = {2, ptr, nodes};
    return tf_sparsity(ctx, &cells, n_nodes, 1, blocks, k);
}

static void every_node_covered(void **state)
{
    (void)state;
    tf_nodesets blocks = {0};
    tf_csc k;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(pattern(&ctx, 4, &blocks, &k), 0);
    assert_int_equal(k.n, 12);
    /* node 0: 6 + 9 * 2 (nodes 1, 2); 1: 6 + 9 * 2 (2, 3); 2: 6 + 9; 3: 6 */
    assert_int_equal(k.nnz, 24 + 24 + 15 + 6);
    assert_int_equal(k.p[k.n], (int)k.nnz);
    tf_csc_free(&k);
    tf_nodesets_free(&blocks);
}

static void uncovered_node_is_named(void **state)
{
    (void)state;
    tf_nodesets blocks = {0};
    tf_csc k;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(pattern(&ctx, 5, &blocks, &k), -1);
    assert_non_null(strstr(ctx.err, "node 5 lies in no integration cell"));
    tf_csc_free(&k);
    tf_nodesets_free(&blocks);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_node_covered),
        cmocka_unit_test(uncovered_node_is_named),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
