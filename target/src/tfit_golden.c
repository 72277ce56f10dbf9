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

static uint32_t pair_ticks(const tfit_golden_pair *g)
{
    float state[2u * TFIT_REGION_STATE_WORDS];
    float tip[6];
    float force[6];
    uint32_t mismatches = 0u;
    (void)tfit_region_reset(g->law, &state[0]);
    (void)tfit_region_reset(g->law, &state[TFIT_REGION_STATE_WORDS]);
    for (uint32_t v = 0u; v < g->n_tick; ++v) {
        for (uint32_t i = 0u; i < 6u; ++i) {
            tip[i] = tfit_float(g->tip[6u * v + i]);
        }
        const tfit_status s = tfit_region_pair(g->law, g->surf, state, tip, force);
        mismatches += (uint32_t)((int32_t)s != g->status[v]);
        for (uint32_t i = 0u; i < 6u; ++i) {
            mismatches += (uint32_t)(tfit_bits(force[i]) != g->force[6u * v + i]);
        }
    }
    return mismatches;
}

static uint32_t surface_pairs(const tfit_golden_pair *g, float *scratch)
{
    const uint32_t n = 3u * g->surf->n_out;
    float state[2u * TFIT_REGION_STATE_WORDS];
    float force[6];
    uint32_t mismatches = 0u;
    for (uint32_t v = 0u; v < g->n_surf; ++v) {
        for (uint32_t i = 0u; i < 6u; ++i) {
            state[i] = tfit_float(g->state[6u * v + i]);
            force[i] = tfit_float(g->sforce[6u * v + i]);
        }
        const tfit_status s = tfit_region_surface_pair(g->surf, state, force, scratch);
        mismatches += (uint32_t)((int32_t)s != g->sstatus[v]);
        for (uint32_t o = 0u; o < n; ++o) {
            mismatches += (uint32_t)(tfit_bits(scratch[o]) != g->out[v * n + o]);
        }
    }
    return mismatches;
}

uint32_t tfit_golden_run_pair(const tfit_golden_pair *g, float *scratch)
{
    if (g == 0 || g->law == 0 || g->surf == 0 || g->tip == 0 || g->status == 0 ||
        g->force == 0 || g->state == 0 || g->sforce == 0 || g->sstatus == 0 || g->out == 0 ||
        scratch == 0) {
        return UINT32_MAX;
    }
    const uint32_t ticks = pair_ticks(g);
    /* the surface pairs as a set of their own: a QEMU trace starts a golden
     * set at a model check (tests/firmware/trace_mix.c) */
    const uint32_t checked = (uint32_t)(tfit_model_check(g->surf) != TFIT_OK);
    return ticks + checked + surface_pairs(g, scratch);
}
