/*
 * cv_folds.c — see cv_folds.h.
 */
#include "fitting/cv_folds.h"

#include <stdlib.h>

#include "base/rng.h"

void tf_cv_folds(size_t n, unsigned k, uint64_t seed, unsigned *fold)
{
    size_t *order = malloc(n * sizeof *order);
    tf_rng r = {seed};
    for (size_t i = 0; i < n; ++i) {
        order[i] = i;
    }
    for (size_t i = n; i > 1; --i) { /* Fisher-Yates */
        size_t j = tf_rng_below(&r, (uint32_t)i);
        size_t t = order[i - 1];
        order[i - 1] = order[j];
        order[j] = t;
    }
    for (size_t pos = 0; pos < n; ++pos) {
        fold[order[pos]] = (unsigned)(pos % k);
    }
    free(order);
}

size_t tf_cv_select(const unsigned *fold, size_t n, unsigned f, int in, size_t *idx)
{
    size_t m = 0;
    for (size_t i = 0; i < n; ++i) {
        if ((fold[i] == f) == (in != 0)) {
            idx[m++] = i;
        }
    }
    return m;
}
