/*
 * tfit_nodal.c — nodal family (and the contact family, which has the same
 * layout with one output point): every output component is a polynomial of
 * total degree p in the normalised input.
 *
 * coef = input map (12) | C[3 n_out][T], row o = output component o
 * (node-major: ux, uy, uz of node 0, then node 1, ...), T = C(p+3, 3).
 * out[o] = C[o][0] + C[o][1] phi1 + ... + C[o][T-1] phi_{T-1}, left to right.
 *
 * Speed without touching that order (docs/firmware.md §5): one output
 * point per iteration, so the three rows of a node share each basis value
 * and keep three independent sums in flight.  p = 1 (the exact degree for
 * linear elasticity) never comes here: tfit_eval.c evaluates it directly
 * (tfit_rows_degree1, or the assembly of tfit_degree1_armv7em.c).  The
 * output mask (header-format.md §5.5) is applied as each word is stored
 * instead of in a second pass over the outputs.
 */
#include "tfit_internal.h"

/* Any p: the three rows of a node side by side, each summed left to right. */
static void nodes_any_degree(const float *c, const float *phi, uint32_t n_terms, uint32_t n_out,
                             uint32_t keep, float *out)
{
    for (uint32_t j = 0u; j < n_out; ++j) {
        const float *cy = c + n_terms;
        const float *cz = cy + n_terms;
        float x = c[0], y = cy[0], z = cz[0];
        for (uint32_t t = 1u; t < n_terms; ++t) {
            const float f = phi[t];
            x = x + c[t] * f;
            y = y + cy[t] * f;
            z = z + cz[t] * f;
        }
        out[0] = tfit_masked(x, keep);
        out[1] = tfit_masked(y, keep);
        out[2] = tfit_masked(z, keep);
        c += 3u * n_terms;
        out += 3;
    }
}

void tfit_eval_nodal(const tfit_model *m, const float g[3], uint32_t keep, float *out)
{
    float phi[TFIT_MAX_TERMS];
    const uint32_t p = m->dims[0];
    const float *c = m->coef + TFIT_INPUT_MAP_FLOATS;

    tfit_basis(p, g, phi);
    nodes_any_degree(c, phi, TFIT_TERMS(p), m->n_out, keep, out);
}
