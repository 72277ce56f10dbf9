/*
 * q15_study.c — where block48_nh's forward model spends its M4F cycles
 * (`make q15-study`, tests/q15.mk; docs/reports/block48_nh_q15.md): the
 * cycle model of host/cost/cycles.c, which check-cycles holds equal to
 * QEMU's trace, split into the rows, the amplitudes and the rest (input
 * map, basis, call) for the float modal family and for modal_q15 at the
 * scene's 121 output points.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "cost/cycles.h"
#include "model/model.h"

#define N_OUT 121u

static double cycles(tfit_family f, uint32_t p, uint32_t r, uint32_t n_out)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    uint32_t dims[2] = {p, r};
    tf_model *m = tf_model_new(&ctx, "study", f, n_out, dims, 2);
    if (m == NULL) {
        fprintf(stderr, "q15_study: %s\n", ctx.err);
        exit(1);
    }
    double c = tf_model_cycles(m, TF_CORE_M4F).cycles;
    tf_model_free(m);
    return c;
}

static void row(const char *what, double c)
{
    printf(" %.0f (%.1f us) |", c, c / 168.0);
    (void)what;
}

/* The rows: what n_out adds (two shapes of odd n_out, so that the
 * modal_q15 odd point cancels); the rest: the model at n_out = 1 less one
 * point's rows; the amplitudes: that rest less the same model at degree 1
 * with its amplitude terms removed is not separable without the blocks, so
 * the amplitudes are the difference to degree p = 1 plus the degree-1
 * terms' share (3 terms per mode), stated as such. */
static void profile(tfit_family f, const char *name, uint32_t p, uint32_t r)
{
    const double all = cycles(f, p, r, N_OUT), small = cycles(f, p, r, 1);
    const double rows = (all - small) * N_OUT / (double)(N_OUT - 1u);
    const double rest = all - rows;
    printf("| %s p=%u r=%u |", name, p, r);
    row("total", all);
    row("rows", rows);
    row("amplitudes, basis, input, call", rest);
    printf("\n");
}

int main(void)
{
    printf("| model | M4F total | rows (121 points) | amplitudes, basis, input map, call |\n"
           "|---|---|---|---|\n");
    profile(TFIT_FAMILY_MODAL, "modal", 4, 8);
    profile(TFIT_FAMILY_MODAL, "modal", 3, 8);
    profile(TFIT_FAMILY_MODAL, "modal", 3, 3);
    profile(TFIT_FAMILY_MODAL_Q15, "modal_q15", 4, 8);
    profile(TFIT_FAMILY_MODAL_Q15, "modal_q15", 3, 8);
    profile(TFIT_FAMILY_MODAL_Q15, "modal_q15", 2, 8);
    /* the amplitudes alone: the same shape at p and at p = 1 differ by the
     * basis and the amplitude terms */
    printf("\nAmplitudes and basis from p = 1 to p = 4 at rank 8: modal +%.0f cycles, "
           "modal_q15 +%.0f cycles\n",
           cycles(TFIT_FAMILY_MODAL, 4, 8, N_OUT) - cycles(TFIT_FAMILY_MODAL, 1, 8, N_OUT),
           cycles(TFIT_FAMILY_MODAL_Q15, 4, 8, N_OUT) - cycles(TFIT_FAMILY_MODAL_Q15, 1, 8, N_OUT));
    return 0;
}
