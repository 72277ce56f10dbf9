/*
 * tfit_golden.c — runs a model's golden vectors (NAME_golden.h) and counts
 * mismatching words, so that the bit-for-bit contract can be verified on the
 * device itself, not only on the host.
 */
#include "tfit_region.h"

uint32_t tfit_golden_run(const tfit_golden *gv, float *scratch)
{
    if (gv == 0 || gv->model == 0 || gv->in == 0 || gv->status == 0 || gv->out == 0 ||
        scratch == 0) {
        return UINT32_MAX;
    }
    const tfit_model *m = gv->model;
    const uint32_t n = 3u * m->n_out;
    static const uint32_t cut_s[16] = TFIT_CUT_GOLDEN_S_BITS;
    uint32_t mismatches = 0u;
    float state[TFIT_STATEFUL_MAX_STATE]; /* a stateful model's: one tick sequence */
    const int stateful = tfit_filter_of(m->family) != 0;
    if (stateful) {
        (void)tfit_stateful_reset(m->family, m, state);
    } else if (m->family == TFIT_FAMILY_REGION) { /* a region law's: one tick sequence too */
        (void)tfit_region_reset(m, state);
    }

    for (uint32_t v = 0u; v < gv->n_vec; ++v) {
        float x[3];
        tfit_status s;
        for (uint32_t i = 0u; i < 3u; ++i) {
            x[i] = tfit_float(gv->in[3u * v + i]);
        }
        if (m->family == TFIT_FAMILY_PRONY) { /* the public entry points, as firmware calls them */
            s = tfit_prony_step(m, state, x, scratch);
        } else if (m->family == TFIT_FAMILY_RESONANT) {
            s = tfit_resonant_step(m, state, x, scratch);
        } else if (m->family == TFIT_FAMILY_CUT) {
            s = tfit_displacements_cut(m, x, tfit_float(cut_s[v & 15u]), scratch);
        } else if (m->family == TFIT_FAMILY_CONTACT) {
            s = tfit_contact_force(m, x, scratch);
        } else if (m->family == TFIT_FAMILY_REGION) {
            s = tfit_region_force(m, state, x, scratch);
        } else if (m->family == TFIT_FAMILY_REGION_SURFACE) {
            /* the proxy of vector v: fractions of the grid from the cut table */
            const float st[3] = {tfit_float(cut_s[v & 15u]) * (float)(m->dims[0] - 1u),
                                 tfit_float(cut_s[(7u * v + 3u) & 15u]) *
                                     (float)(m->dims[1] - 1u),
                                 1.0f};
            s = tfit_region_surface(m, st, x, scratch);
        } else {
            s = tfit_displacements(m, x, scratch);
        }
        mismatches += (uint32_t)((int32_t)s != gv->status[v]);
        for (uint32_t o = 0u; o < n; ++o) {
            mismatches += (uint32_t)(tfit_bits(scratch[o]) != gv->out[v * n + o]);
        }
    }
    return mismatches;
}
