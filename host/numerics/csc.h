/*
 * csc.h — symmetric sparse matrices in compressed columns, lower triangle
 * stored (the layout CHOLMOD reads with stype -1).
 */
#ifndef TF_CSC_H
#define TF_CSC_H

#include <stddef.h>

typedef struct tf_csc {
    size_t n;   /* rows = columns */
    size_t nnz;
    int *p;     /* n + 1 column starts */
    int *i;     /* row indices, ascending in each column */
    double *x;  /* values */
} tf_csc;

void tf_csc_free(tf_csc *a);

/* y = A x for the symmetric A (both triangles from the stored one); x and y
 * hold ncol columns of length n (column major). */
void tf_csc_symv(const tf_csc *a, const double *x, double *y, size_t ncol);

#endif /* TF_CSC_H */
