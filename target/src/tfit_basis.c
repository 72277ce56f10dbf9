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
 * Implementation: the three T tables in one loop, then the terms in the
 * graded order, each as written: two multiplications per term, one of them
 * by T_0 = 1 for a = 0 (exact, so the bits are the definition's).  One
 * code path for every p, 0 and 1 included; the nodal family does not call
 * this at p = 1 (phi = {1, g0, g1, g2} is g itself, tfit_rows_degree1).
 */
#include "tfit_internal.h"

#define DEG1 ((uint32_t)TFIT_MAX_DEGREE + 1u)

void tfit_basis(uint32_t p, const float g[3], float *phi)
{
    float t0[DEG1], t1[DEG1], t2[DEG1];
    const float h0 = g[0] + g[0], h1 = g[1] + g[1], h2 = g[2] + g[2];
    uint32_t k = 0u;

    t0[0] = 1.0f;
    t1[0] = 1.0f;
    t2[0] = 1.0f;
    t0[1] = g[0];
    t1[1] = g[1];
    t2[1] = g[2];
    for (uint32_t i = 2u; i <= p; ++i) {
        t0[i] = h0 * t0[i - 1u] - t0[i - 2u];
        t1[i] = h1 * t1[i - 1u] - t1[i - 2u];
        t2[i] = h2 * t2[i - 1u] - t2[i - 2u];
    }
    for (uint32_t d = 0u; d <= p; ++d) {
        for (uint32_t e = 0u; e <= d; ++e) { /* e = b + c: a = d - e from d down */
            const float ta = t0[d - e];
            for (uint32_t c = 0u; c <= e; ++c) { /* b = e - c from e down */
                phi[k++] = ta * (t1[e - c] * t2[c]);
            }
        }
    }
}
