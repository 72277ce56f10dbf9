/*
 * fitdata.h — solved load cases, the input of every fitter: forces at the
 * contact site, the displacements of the output points, and the contact
 * site's own displacement.
 */
#ifndef TF_FITDATA_H
#define TF_FITDATA_H

#include <stddef.h>
#include <stdint.h>

typedef struct tf_fitdata {
    size_t n_cases;
    const double (*force)[3];   /* n_cases forces [N] */
    const double *u;            /* 3 n_out x n_cases, column-major: case i at u + 3 n_out i [mm] */
    const double (*contact)[3]; /* n_cases contact-site displacements [mm] */
    uint32_t n_out;
    const uint32_t *node_ids;   /* n_out scene node numbers */
    const double (*rest)[3];    /* n_out rest positions [mm] */
    double centre[3];           /* force envelope: ball around centre ... */
    double radius;              /* ... of this radius [N] */
} tf_fitdata;

/* The output points' z range: the points lie on one plane z = const when
 * the range is within rounding of their extent (zhou2017 needs that, and
 * only it uses the single-axis cases: cases.c skips them otherwise). */
static inline int tf_fitdata_flat(const tf_fitdata *d, double *zlo, double *zhi)
{
    double lo = d->n_out ? d->rest[0][2] : 0, hi = lo, span = 1.0;
    for (uint32_t j = 0; j < d->n_out; ++j) {
        lo = d->rest[j][2] < lo ? d->rest[j][2] : lo;
        hi = d->rest[j][2] > hi ? d->rest[j][2] : hi;
        for (int k = 0; k < 2; ++k) {
            double a = d->rest[j][k] < 0 ? -d->rest[j][k] : d->rest[j][k];
            span = a > span ? a : span;
        }
    }
    *zlo = lo;
    *zhi = hi;
    return hi - lo <= 1e-9 * span;
}

#endif /* TF_FITDATA_H */
