/*
 * tfit_nodal.c — nodal family (and the contact family, which has the same
 * layout with one output point): every output component is a polynomial of
 * total degree p in the normalised input.
 *
 * coef = input map (12) | C[3 n_out][T], row o = output component o
 * (node-major: ux, uy, uz of node 0, then node 1, ...), T = C(p+3, 3).
 * out[o] = C[o][0] + C[o][1] phi1 + ... + C[o][T-1] phi_{T-1}, left to right.
 */
#include "tfit_internal.h"

void tfit_eval_nodal(const tfit_model *m, const float g[3], float *out)
{
    float phi[TFIT_MAX_TERMS];
    const uint32_t p = m->dims[0];
    const uint32_t n_terms = TFIT_TERMS(p);
    const uint32_t n_rows = 3u * m->n_out;
    const float *c = m->coef + TFIT_INPUT_MAP_FLOATS;

    tfit_basis(p, g, phi);
    for (uint32_t o = 0u; o < n_rows; ++o) {
        out[o] = tfit_row(c + o * n_terms, phi, n_terms);
    }
}
