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

/* Contact p = 1, the exact degree for linear elasticity and the model the
 * haptic loop calls every tick: the same operations as evaluate() (the
 * projection, then tfit_eval_nodal's degree-1 rows for one output point),
 * without the family dispatch, the nodal set-up and the loop.  This is what
 * brings the contact-force call within 2 us on a 168 MHz M4F
 * (docs/firmware.md §5). */
static tfit_status contact_degree1(const tfit_model *m, const float disp[3], float force[3])
{
    float g[3];
    uint32_t bad;
    const uint32_t clamped = tfit_input_map(m->coef, disp, g, &bad);
    tfit_rows_degree1(m->coef + TFIT_INPUT_MAP_FLOATS, g, 1u, ~bad, force);
    return status_of(clamped, bad);
}

tfit_status tfit_displacements(const tfit_model *m, const float force[3], float *out)
{
    if (m == 0 || force == 0 || out == 0) {
        return TFIT_ERR_ARG;
    }
    if (!is_forward(m->family)) {
        return TFIT_ERR_FAMILY;
    }
    return evaluate(m, force, out);
}

tfit_status tfit_contact_force(const tfit_model *m, const float disp[3], float force[3])
{
    if (m == 0 || disp == 0 || force == 0) {
        return TFIT_ERR_ARG;
    }
    if (m->family != TFIT_FAMILY_CONTACT) {
        return TFIT_ERR_FAMILY;
    }
    if (m->dims[0] == 1u) {
        return contact_degree1(m, disp, force);
    }
    return evaluate(m, disp, force);
}
