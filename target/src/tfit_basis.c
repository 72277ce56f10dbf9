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
 * Implementation: the three T tables, then the inner products
 * q = T_b(g1) T_c(g2) for b + c = e <= p, stored by e and decreasing b.  For
 * a fixed (d, a) the terms b = e..0 (e = d - a) are then the contiguous run
 * q[e(e+1)/2 .. e(e+1)/2 + e], so each term costs one multiplication here.
 * Products with a factor T_0 = 1 are exact, so performing them (as the loops
 * do) gives the bits of the definition.  p = 1 — every linear-elastic nodal
 * model — is written out: {1, g0, g1, g2}, identical to API 2.
 */
#include "tfit_internal.h"

#define DEG1 ((uint32_t)TFIT_MAX_DEGREE + 1u)
#define PAIRS ((DEG1 * (DEG1 + 1u)) / 2u)

/* t[k] = T_k(g), k = 0..p (p >= 1). */
static void chebyshev(uint32_t p, float g, float *t)
{
    const float h = g + g;
    t[0] = 1.0f;
    t[1] = g;
    for (uint32_t k = 2u; k <= p; ++k) {
        t[k] = h * t[k - 1u] - t[k - 2u];
    }
}

/* p >= 2. */
static void basis_any_degree(uint32_t p, const float g[3], float *phi)
{
    float t0[DEG1], t1[DEG1], t2[DEG1];
    float q[PAIRS];
    uint32_t k = 0u;

    chebyshev(p, g[0], t0);
    chebyshev(p, g[1], t1);
    chebyshev(p, g[2], t2);
    for (uint32_t e = 0u; e <= p; ++e) {
        for (uint32_t b = e + 1u; b-- > 0u;) {
            q[k++] = t1[b] * t2[e - b];
        }
    }
    k = 0u;
    for (uint32_t d = 0u; d <= p; ++d) {
        uint32_t base = 0u; /* e (e + 1) / 2 for e = d - a, a = d .. 0 */
        for (uint32_t e = 0u; e <= d; ++e) {
            const float ta = t0[d - e];
            for (uint32_t j = 0u; j <= e; ++j) {
                phi[k++] = ta * q[base + j];
            }
            base += e + 1u;
        }
    }
}

void tfit_basis(uint32_t p, const float g[3], float *phi)
{
    phi[0] = 1.0f;
    if (p != 1u) {
        if (p != 0u) {
            basis_any_degree(p, g, phi);
        }
        return;
    }
    phi[1] = g[0];
    phi[2] = g[1];
    phi[3] = g[2];
}
