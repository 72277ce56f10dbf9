/*
 * tfit_stateful.c — the one stepping path of the stateful forms (prony,
 * resonant; docs/header-format.md §5.6, §5.8).  A stateful model is a
 * filter over the projected input followed by a static map:
 *
 *   coef  = input map (12) | K terms of the filter | the static map's tables
 *           (nodal rows when r = 0, else a modal table of rank r),
 *   dims  = {p, r, K, tick_ns},
 *   state = gp[3] (the previous tick's projected input) | K terms' words.
 *
 * One tick: g = projection of the force (§4), bad = NaN/Inf in it; the
 * form's filter (tfit_prony.c, tfit_resonant.c) turns g into h, writing
 * its new state over the caller's, or into a scratch copy when bad (the
 * caller's state keeps every bit); the static map at h, masked with ~bad.
 * Each form's file holds its filter, its shape (tfit_filter: table floats
 * and state words per term, the most terms) and its public reset and step:
 * the step makes the checks of tfit_stateful_refuse() for its family and
 * then runs the tick here.  No branch on the input or the state;
 * the branches below test pointers and the model's family.
 */
#include "tfit_internal.h"

void tfit_stateful_filter(const tfit_model *m, const float g[3], uint32_t keep, float *state,
                          float h[3])
{
    switch (m->family) {
    case TFIT_FAMILY_RESONANT:
        tfit_resonant_filter(m, g, keep, state, h);
        break;
    default:
        tfit_prony_filter(m, g, keep, state, h);
        break;
    }
}

/* The filter of a stateful model: never NULL (tfit_filter_of is, for any
 * other family). */
static const tfit_filter *filter(const tfit_model *m)
{
    return m->family == TFIT_FAMILY_RESONANT ? &tfit_filter_resonant : &tfit_filter_prony;
}

int tfit_stateful_terms_ok(const tfit_model *m)
{
    switch (m->family) {
    case TFIT_FAMILY_RESONANT:
        return tfit_resonant_terms_ok(m);
    default:
        return tfit_prony_terms_ok(m);
    }
}

uint32_t tfit_stateful_words(const tfit_model *m)
{
    return 3u + filter(m)->words * m->dims[2];
}

void tfit_stateful_static(const tfit_model *m, tfit_model *v)
{
    const uint32_t skip = filter(m)->floats * m->dims[2];
    v->family = m->dims[1] == 0u ? TFIT_FAMILY_NODAL : TFIT_FAMILY_MODAL;
    v->n_out = m->n_out;
    v->n_dims = m->dims[1] == 0u ? TFIT_NODAL_DIMS : TFIT_MODAL_DIMS;
    v->dims = m->dims;
    v->coef = m->coef + skip;
    v->n_coef = m->n_coef - skip;
    v->node_ids = m->node_ids;
}

/* The static map of a p = 1 model: the assembly of tfit_degree1_armv7em.c
 * on Cortex-M4F/M7, else the same operations in C. */
static void degree1_rows(const float *rows, const float h[3], uint32_t n_out, uint32_t keep,
                         float *out)
{
#if TFIT_DEGREE1_ASM
    tfit_degree1_rows_asm(rows, h, n_out, keep, out);
#else
    tfit_rows_degree1(rows, h, n_out, keep, out);
#endif
}

void tfit_stateful_eval(const tfit_model *v, const float h[3], uint32_t keep, float *out)
{
    if (v->family == TFIT_FAMILY_MODAL) {
        tfit_eval_modal(v, h, keep, out);
    } else if (v->dims[0] != 1u) {
        tfit_eval_nodal(v, h, keep, out);
    } else { /* p = 1: rows of {1, h0, h1, h2} (docs/firmware.md §5.4) */
        degree1_rows(v->coef + TFIT_INPUT_MAP_FLOATS, h, v->n_out, keep, out);
    }
}

tfit_status tfit_stateful_reset(uint32_t family, const tfit_model *m, float *state)
{
    if ((m == 0) | (state == 0)) {
        return TFIT_ERR_ARG;
    }
    if ((m->dims == 0) | (m->coef == 0)) {
        return TFIT_ERR_ARG;
    }
    if (m->family != family) {
        return TFIT_ERR_FAMILY;
    }
    const float zero[3] = {0.0f, 0.0f, 0.0f};
    uint32_t bad;
    /* volatile: GCC would make the zeroing loop a call to memset, which a
     * freestanding library cannot make (check-freestanding: nm -u) */
    volatile float *terms = state + 3;
    const uint32_t words = tfit_stateful_words(m) - 3u;
    (void)tfit_input_map(m->coef, zero, state, &bad); /* the projected zero force */
    for (uint32_t w = 0u; w < words; ++w) {
        terms[w] = 0.0f;
    }
    return TFIT_OK;
}

tfit_status tfit_stateful_step(const tfit_model *m, float *state, const float force[3],
                               float *out)
{
    float g[3], h[3];
    uint32_t bad;
    tfit_model v;
    const uint32_t clamped = tfit_input_map(m->coef, force, g, &bad);
    tfit_stateful_filter(m, g, ~bad, state, h);
    tfit_stateful_static(m, &v);
    tfit_stateful_eval(&v, h, ~bad, out);
    return (tfit_status)((int)(clamped & ~bad & 1u) - (int)(bad & 1u));
}
