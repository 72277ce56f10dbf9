/*
 * basis.h — the Chebyshev basis of docs/header-format.md §5.1 (tfit API
 * version 3) in double precision, for building design matrices:
 * T_a(g0) T_b(g1) T_c(g2), a + b + c <= p, graded by degree, then by
 * decreasing a, then decreasing b.
 */
#ifndef TF_BASIS_H
#define TF_BASIS_H

#include <stdint.h>

/* phi[tf_terms(p)] = every term of total degree <= p at g. */
void tf_basis(uint32_t p, const double g[3], double *phi);

/* The basis and its gradient: dphi[k][v] = d phi[k] / d g[v]. */
void tf_basis_grad(uint32_t p, const double g[3], double *phi, double (*dphi)[3]);

/* 1-D Chebyshev polynomials: out[k] = T_k(x), k = 0..n. */
void tf_chebyshev(uint32_t n, double x, double *out);

#endif /* TF_BASIS_H */
