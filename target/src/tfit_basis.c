/*
 * tfit_basis.c — the monomial basis in the normalised input.
 *
 * Monomials g0^a g1^b g2^c with a + b + c <= p, graded by degree, and within
 * a degree ordered by decreasing a, then decreasing b:
 *   1 | g0 g1 g2 | g0^2 g0g1 g0g2 g1^2 g1g2 g2^2 | ...
 * Each monomial of degree d is one product: g_v times the monomial with the
 * exponent of v lowered by one, where v is the first variable with a
 * positive exponent.  In this order that is a block recurrence: the degree-d
 * block is g0 x (degree d-1 block), then g1 x (its last d entries), then
 * g2 x (its last entry).  Degree 1 — every linear-elastic nodal model — is
 * written out: the same three products without the loop set-up, which
 * costs more than they do.
 */
#include "tfit_internal.h"

/* Degrees 2..p (after phi[0..3] when p >= 1): the block recurrence. */
static void basis_degrees(uint32_t p, const float g[3], float *phi)
{
    uint32_t prev = 0u;   /* start of the degree d-1 block */
    uint32_t n_prev = 1u; /* its length, d(d+1)/2 */
    uint32_t k = 1u;

    for (uint32_t d = 1u; d <= p; ++d) {
        for (uint32_t i = 0u; i < n_prev; ++i) {
            phi[k++] = g[0] * phi[prev + i];
        }
        for (uint32_t i = n_prev - d; i < n_prev; ++i) {
            phi[k++] = g[1] * phi[prev + i];
        }
        phi[k++] = g[2] * phi[prev + n_prev - 1u];
        prev += n_prev;
        n_prev += d + 1u;
    }
}

void tfit_basis(uint32_t p, const float g[3], float *phi)
{
    phi[0] = 1.0f;
    if (p != 1u) {
        basis_degrees(p, g, phi);
        return;
    }
    phi[1] = g[0] * phi[0];
    phi[2] = g[1] * phi[0];
    phi[3] = g[2] * phi[0];
}
