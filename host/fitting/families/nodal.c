/*
 * nodal.c — the nodal family: each output component a polynomial of
 * total degree p in the normalised force; one QR factorisation of the
 * design matrix serves all 3 n_out columns.
 */
#include <stdio.h>
#include <stdlib.h>

#include "fitting/families/common.h"
#include "fitting/families/family.h"

tf_model *tf_fit_nodal(const tf_fitdata *d, const size_t *idx, size_t m, const uint32_t *orders,
                       const char *name, char *err, size_t errlen)
{
    const uint32_t p = orders[0];
    tf_model *model =
        tf_family_forward_model(name, TFIT_FAMILY_NODAL, &p, 1, p, d, idx, m, err, errlen);
    if (model == NULL) {
        return NULL;
    }
    const uint32_t t = tf_terms(p);
    const size_t rows = 3 * (size_t)d->n_out;
    double *a = tf_family_design(model, d->force, idx, m, p);
    double *y = tf_family_gather_u(d, idx, m);
    double *x = malloc(t * rows * sizeof *x);
    int rc = (a && y && x) ? tf_family_lsq(a, m, t, y, rows, x, err, errlen) : -1;
    if (rc == 0) {
        float *c = tf_model_tables(model);
        for (size_t o = 0; o < rows; ++o) {
            for (uint32_t k = 0; k < t; ++k) {
                c[o * t + k] = (float)x[k + o * t];
            }
        }
    } else if (!(a && y && x)) {
        snprintf(err, errlen, "nodal p=%u: out of memory", p);
    }
    free(a);
    free(y);
    free(x);
    if (rc != 0) {
        tf_model_free(model);
        return NULL;
    }
    return model;
}
