/*
 * basis.h — the monomial basis of docs/header-format.md §5.1 in double
 * precision, for building design matrices: g0^a g1^b g2^c, a + b + c <= p,
 * graded by degree, then by decreasing a, then decreasing b.
 */
#ifndef TF_BASIS_H
#define TF_BASIS_H

#include <stdint.h>

/* phi[tf_terms(p)] = every monomial of total degree <= p at g. */
void tf_basis(uint32_t p, const double g[3], double *phi);

/* 1-D powers: out[k] = x^k, k = 0..n. */
void tf_powers(uint32_t n, double x, double *out);

#endif /* TF_BASIS_H */
