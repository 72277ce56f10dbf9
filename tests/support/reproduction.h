/*
 * reproduction.h — how far shape functions are from reproducing linear
 * fields (test support).
 */
#ifndef TF_TEST_REPRODUCTION_H
#define TF_TEST_REPRODUCTION_H

#include <stddef.h>
#include <stdint.h>

/* Largest violation of sum phi_i (1, x_i) = (1, x) and sum d_a phi_i
 * (1, x_i) = (0, e_a) over the n nodes idx[] (coordinates in xyz), with
 * phi[i] and dphi[a n + i] at x; positions are divided by L and gradients
 * multiplied by it (L: the cloud's size). */
double tf_test_reproduction_error(const double *xyz, const uint32_t *idx, size_t n,
                                  const double *phi, const double *dphi, const double x[3],
                                  double L);

#endif /* TF_TEST_REPRODUCTION_H */
