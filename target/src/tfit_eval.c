/*
 * tfit_eval.c — the public evaluation entry points.
 *
 * Every call runs the same instruction sequence for a given model: the input
 * projection is branch-free, the family loops depend only on the model's
 * sizes, and every output is masked with the input's validity as it is
 * stored (a NaN/Inf input leaves +0.0f everywhere).  Branches below test only
 * pointers and the model's family, never the input value.
 */
#include "tfit_internal.h"

static int is_forward(uint32_t family)
{
    return family == TFIT_FAMILY_NODAL || family == TFIT_FAMILY_MODAL ||
           family == TFIT_FAMILY_ZHOU2017;
}

/* -1 for bad input, else 1 when projected, else 0 — without a branch. */
static tfit_status status_of(uint32_t clamped, uint32_t bad)
{
    return (tfit_status)((int)(clamped & ~bad & 1u) - (int)(bad & 1u));
}

static tfit_status evaluate(const tfit_model *m, const float in[3], float *out)
{
    float g[3];
    uint32_t bad;
    const uint32_t clamped = tfit_input_map(m->coef, in, g, &bad);
    const uint32_t keep = ~bad;

    switch (m->family) {
    case TFIT_FAMILY_MODAL:
        tfit_eval_modal(m, g, keep, out);
        break;
    case TFIT_FAMILY_ZHOU2017:
        tfit_eval_zhou2017(m, g, out);
        for (uint32_t o = 0u; o < 3u * m->n_out; ++o) {
            out[o] = tfit_masked(out[o], keep);
        }
        break;
    default: /* nodal and contact share one layout */
        tfit_eval_nodal(m, g, keep, out);
        break;
    }
    return status_of(clamped, bad);
}

/* Degree 1 (nodal and contact p = 1: the exact degree for linear
 * elasticity, and the models the haptic loop calls every tick): the same
 * operations as evaluate() — the projection, then the rows of §5.2 with
 * phi = {1, g0, g1, g2} = g, and the output mask — without the family
 * dispatch and the basis.  On Cortex-M4F/M7 in assembly
 * (tfit_degree1_armv7em.c), elsewhere in C; docs/firmware.md §5. */
static tfit_status degree1(const tfit_model *m, const float in[3], float *out)
{
#if TFIT_DEGREE1_ASM
    return tfit_degree1_asm(m, in, out);
#else
    float g[3];
    uint32_t bad;
    const uint32_t clamped = tfit_input_map(m->coef, in, g, &bad);
    tfit_rows_degree1(m->coef + TFIT_INPUT_MAP_FLOATS, g, m->n_out, ~bad, out);
    return status_of(clamped, bad);
#endif
}

/* The contact family's one output point. */
static tfit_status contact_degree1(const tfit_model *m, const float disp[3], float force[3])
{
#if TFIT_DEGREE1_ASM
    return tfit_degree1_one_asm(m, disp, force);
#else
    return degree1(m, disp, force);
#endif
}

/* modal_q15 (header-format.md §5.9), as evaluate() does a family, and the
 * error for a family that is no forward one: kept out of evaluate()'s
 * dispatch and out of line, so that the other families' instructions (and
 * the cycle counts their headers state) stay as they were. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static tfit_status forward_other(const tfit_model *m, const float in[3], float *out)
{
    if (m->family != TFIT_FAMILY_MODAL_Q15) {
        return TFIT_ERR_FAMILY;
    }
    float g[3];
    uint32_t bad;
    const uint32_t clamped = tfit_input_map(m->coef, in, g, &bad);
    tfit_eval_modal_q15(m, g, ~bad, out);
    return status_of(clamped, bad);
}

/* The forward families other than nodal p = 1. */
static tfit_status forward_general(const tfit_model *m, const float force[3], float *out)
{
    if (!is_forward(m->family)) {
        return forward_other(m, force, out);
    }
    return evaluate(m, force, out);
}

tfit_status tfit_displacements(const tfit_model *m, const float force[3], float *out)
{
    /* bitwise tests: the degree-1 path falls through every conditional
     * branch (GCC 12), a taken branch costing the M4 up to 4 cycles.  A
     * model with NULL tables is an argument error, as in the Q31 API. */
    if ((m == 0) | (force == 0) | (out == 0)) {
        return TFIT_ERR_ARG;
    }
    if ((m->dims == 0) | (m->coef == 0)) {
        return TFIT_ERR_ARG;
    }
    if ((m->dims[0] == 1u) & (m->family == TFIT_FAMILY_NODAL)) {
        return degree1(m, force, out);
    }
    return forward_general(m, force, out);
}

tfit_status tfit_contact_force(const tfit_model *m, const float disp[3], float force[3])
{
    if ((m == 0) | (disp == 0) | (force == 0)) {
        return TFIT_ERR_ARG;
    }
    if ((m->dims == 0) | (m->coef == 0)) {
        return TFIT_ERR_ARG;
    }
    if (m->family != TFIT_FAMILY_CONTACT) {
        return TFIT_ERR_FAMILY;
    }
    if (m->dims[0] != 1u) {
        return evaluate(m, disp, force);
    }
    return contact_degree1(m, disp, force);
}
