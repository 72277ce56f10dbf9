/*
 * tfit_basis.c — the Chebyshev basis in the normalised input
 * (docs/header-format.md §5.1, API version 3).
 *
 * Term (a, b, c), a + b + c <= p, is phi = T_a(g0) * (T_b(g1) * T_c(g2)),
 * each product rounded to float as written, in the graded order of API 2:
 * degree blocks, within a degree decreasing a, then decreasing b.  Per
 * variable t[0] = 1, t[1] = g, t[k] = (h * t[k-1]) - t[k-2] with h = g + g
 * (exact).  Why Chebyshev and not monomials: docs/stability.md §1 — the
 * normalised monomials lose up to 1.6 decimal digits in float32 at orders
 * 5-8, T_k (|T_k| <= 1 on [-1, 1]) less than 0.4.
 *
 * Implementation: the three T tables; then, degree by degree, the terms
 * with a >= 1 as T_a(g0) times the a = 0 group of degree e = d - a (which
 * holds exactly the inner products T_b(g1) T_c(g2), b + c = e, b = e..0, in
 * the order needed), and last the a = 0 group of degree d itself.  Each
 * term costs one multiplication.
 * Products with a factor T_0 = 1 are exact, so performing them (as the loops
 * do) gives the bits of the definition.  p = 1 — every linear-elastic nodal
 * model — is written out: {1, g0, g1, g2}, identical to API 2.
 */
#include "tfit_internal.h"

#define DEG1 ((uint32_t)TFIT_MAX_DEGREE + 1u)
#define PAIRS ((DEG1 * (DEG1 + 1u)) / 2u)

/* p >= 2.  A named, external function rather than a static helper: the
 * cycle model (host/cycles.c, check-cycles) reads its loops from objdump by
 * name, and keeping its stack frame out of tfit_basis keeps the p = 1 path
 * as short as in API 2. */
void tfit_basis_chebyshev(uint32_t p, const float g[3], float *phi)
{
    float t[3][DEG1];
    uint32_t k = 1u;

    for (uint32_t v = 0u; v < 3u; ++v) {
        const float h = g[v] + g[v];
        float *tv = t[v];
        tv[0] = 1.0f;
        tv[1] = g[v];
        for (uint32_t i = 2u; i <= p; ++i) {
            tv[i] = h * tv[i - 1u] - tv[i - 2u];
        }
    }
    for (uint32_t d = 1u; d <= p; ++d) {
        /* a = d .. 1: T_a(g0) times the a = 0 group of degree e = d - a,
         * which holds the inner products T_b(g1) T_c(g2), b + c = e */
        uint32_t from = 0u; /* index of (0, e, 0), e(e+1)(e+2)/6 + e(e+1)/2 */
        for (uint32_t e = 0u; e < d; ++e) {
            const float ta = t[0][d - e];
            for (uint32_t j = 0u; j <= e; ++j) {
                phi[k++] = ta * phi[from + j];
            }
            from += (e + 1u) * (e + 2u) / 2u + e + 1u;
        }
        /* a = 0: the inner products of degree d, b = d .. 0 */
        for (uint32_t b = d + 1u; b-- > 0u;) {
            phi[k++] = t[1][b] * t[2][d - b];
        }
    }
}

void tfit_basis(uint32_t p, const float g[3], float *phi)
{
    phi[0] = 1.0f;
    if (p != 1u) {
        if (p != 0u) {
            tfit_basis_chebyshev(p, g, phi);
        }
        return;
    }
    phi[1] = g[0];
    phi[2] = g[1];
    phi[3] = g[2];
}
