/*
 * csc.c — symmetric compressed-column matrices (csc.h).
 */
#include "numerics/csc.h"

#include <stdlib.h>
#include <string.h>

void tf_csc_free(tf_csc *a)
{
    free(a->p);
    free(a->i);
    free(a->x);
    a->p = a->i = NULL;
    a->x = NULL;
    a->n = a->nnz = 0;
}

void tf_csc_symv(const tf_csc *a, const double *x, double *y, size_t ncol)
{
    for (size_t c = 0; c < ncol; ++c) {
        const double *xc = x + c * a->n;
        double *yc = y + c * a->n;
        memset(yc, 0, a->n * sizeof *yc);
        for (size_t j = 0; j < a->n; ++j) {
            for (int q = a->p[j]; q < a->p[j + 1]; ++q) {
                size_t i = (size_t)a->i[q];
                yc[i] += a->x[q] * xc[j];
                if (i != j) {
                    yc[j] += a->x[q] * xc[i];
                }
            }
        }
    }
}
