/*
 * cv_folds.h — k-fold cross-validation folds: a seeded shuffle of the cases, then
 * case i belongs to fold (position of i) mod k.  Deterministic for a seed.
 */
#ifndef TF_CV_FOLDS_H
#define TF_CV_FOLDS_H

#include <stddef.h>
#include <stdint.h>

/* fold[i] in 0..k-1 for each of n cases.  k >= 2, n >= k. */
void tf_cv_folds(size_t n, unsigned k, uint64_t seed, unsigned *fold);

/* The indices of the cases in (or, with in == 0, outside) fold f; returns
 * their count. */
size_t tf_cv_select(const unsigned *fold, size_t n, unsigned f, int in, size_t *idx);

#endif /* TF_CV_FOLDS_H */
