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

#endif /* TF_FITDATA_H */
