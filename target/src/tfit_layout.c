/*
 * tfit_layout.c — the size of a model's coefficient table as implied by its
 * family, dims and n_out (docs/header-format.md §3).  Used by
 * tfit_model_check() before it reads any table.
 */
#include "tfit_region.h"

static uint32_t nodal_coefs(const tfit_model *m)
{
    uint32_t p = m->dims[0];
    if (p > TFIT_MAX_DEGREE) {
        return 0u;
    }
    return TFIT_INPUT_MAP_FLOATS + 3u * m->n_out * TFIT_TERMS(p);
}

static uint32_t modal_coefs(const tfit_model *m)
{
    uint32_t p = m->dims[0];
    uint32_t r = m->dims[1];
    if (p > TFIT_MAX_DEGREE || r == 0u || r > TFIT_MAX_RANK) {
        return 0u;
    }
    return TFIT_INPUT_MAP_FLOATS + r * TFIT_TERMS(p) + 3u * m->n_out * r;
}

/* map | At[T][8] | v[8] | S | rows: 3 n_out x 4 words (§5.9) */
static uint32_t modal_q15_coefs(const tfit_model *m)
{
    uint32_t p = m->dims[0];
    if (p == 0u || p > TFIT_MAX_DEGREE || m->dims[1] != TFIT_MODAL_Q15_RANK) {
        return 0u;
    }
    return TFIT_INPUT_MAP_FLOATS + TFIT_MODAL_Q15_RANK * TFIT_TERMS(p) + TFIT_MODAL_Q15_RANK + 1u +
           3u * m->n_out * TFIT_MODAL_Q15_WORDS;
}

static uint32_t zhou2017_coefs(const tfit_model *m)
{
    const uint32_t *dm = m->dims;
    uint32_t n = TFIT_INPUT_MAP_FLOATS + 2u * m->n_out;
    for (uint32_t a = 0u; a < 3u; ++a) {
        if (dm[a] > TFIT_MAX_DEGREE) {
            return 0u;
        }
        n += dm[a] + 2u;
    }
    for (uint32_t i = 0u; i < 9u; ++i) {
        const uint32_t *o = dm + 3u + 3u * i;
        if (o[0] > TFIT_ZHOU_MAX_ORDER || o[1] > TFIT_ZHOU_MAX_ORDER || o[2] > TFIT_MAX_DEGREE) {
            return 0u;
        }
        n += (o[0] + o[1] + 1u) * (o[2] + 1u);
    }
    return n;
}

/* {p, r, K, tick_ns}: K terms of the form's filter after the input map
 * (tfit_stateful.c), then nodal rows (r = 0) or a modal table of rank r; a
 * tick of at least 1 ns. */
static uint32_t stateful_coefs(const tfit_model *m)
{
    const tfit_filter *f = tfit_filter_of(m->family);
    const uint32_t *dm = m->dims;
    const uint32_t p = dm[0], r = dm[1], terms = dm[2];
    if (p > TFIT_MAX_DEGREE || r > TFIT_MAX_RANK || terms > f->max_terms || dm[3] == 0u) {
        return 0u;
    }
    const uint32_t table = r == 0u ? 3u * m->n_out * TFIT_TERMS(p)
                                   : r * TFIT_TERMS(p) + 3u * m->n_out * r;
    return TFIT_INPUT_MAP_FLOATS + f->floats * terms + table;
}

/* {p, K}: K + 1 nodal tables; 0 when the count would not fit uint32_t. */
static uint32_t cut_coefs(const tfit_model *m)
{
    const uint32_t p = m->dims[0], k = m->dims[1];
    if (p > TFIT_MAX_DEGREE || k == 0u || k > TFIT_CUT_MAX_INTERVALS) {
        return 0u;
    }
    const uint64_t n = (uint64_t)(k + 1u) * 3u * m->n_out * TFIT_TERMS(p) + TFIT_INPUT_MAP_FLOATS;
    return n > 0xffffffffu ? 0u : (uint32_t)n;
}

uint32_t tfit_expected_coefs(const tfit_model *m)
{
    if (m->n_out == 0u || m->n_out > TFIT_MAX_OUT) {
        return 0u;
    }
    switch (m->family) {
    case TFIT_FAMILY_NODAL:
        return m->n_dims == TFIT_NODAL_DIMS ? nodal_coefs(m) : 0u;
    case TFIT_FAMILY_CONTACT:
        return (m->n_dims == TFIT_CONTACT_DIMS && m->n_out == 1u) ? nodal_coefs(m) : 0u;
    case TFIT_FAMILY_MODAL:
        return m->n_dims == TFIT_MODAL_DIMS ? modal_coefs(m) : 0u;
    case TFIT_FAMILY_ZHOU2017:
        return m->n_dims == TFIT_ZHOU2017_DIMS ? zhou2017_coefs(m) : 0u;
    case TFIT_FAMILY_PRONY:
    case TFIT_FAMILY_RESONANT:
        return m->n_dims == TFIT_PRONY_DIMS ? stateful_coefs(m) : 0u;
    case TFIT_FAMILY_CUT:
        return m->n_dims == TFIT_CUT_DIMS ? cut_coefs(m) : 0u;
    case TFIT_FAMILY_MODAL_Q15:
        return m->n_dims == TFIT_MODAL_Q15_DIMS ? modal_q15_coefs(m) : 0u;
    case TFIT_FAMILY_REGION:
    case TFIT_FAMILY_REGION_SURFACE:
        return tfit_region_coefs(m); /* tfit_region_check.c */
    default:
        return 0u;
    }
}
