/*
 * modal.c — the modal family: the first r POD modes of the training
 * displacements (pod.h), and each mode's amplitude a polynomial of total
 * degree p in the normalised force.  Amplitudes of the training cases are
 * their projections on the (orthonormal) modes.
 */
#include <stdio.h>
#include <stdlib.h>

#include "fitting/families/common.h"
#include "fitting/families/family.h"
#include "numerics/pod.h"

tf_model *tf_fit_modal(const tf_fitdata *d, const size_t *idx, size_t m, const uint32_t *orders,
                       const char *name, char *err, size_t errlen)
{
    const uint32_t p = orders[0], r = orders[1];
    const size_t rows = 3 * (size_t)d->n_out;
    if (r > m || r > rows) {
        snprintf(err, errlen, "modal r=%u: more modes than the %zu cases or %zu outputs", r, m,
                 rows);
        return NULL;
    }
    tf_model *model =
        tf_family_forward_model(name, TFIT_FAMILY_MODAL, orders, 2, p, d, idx, m, err, errlen);
    if (model == NULL) {
        return NULL;
    }
    const uint32_t t = tf_terms(p);
    double *y = tf_family_gather_u(d, idx, m); /* m x rows: row = case */
    double *data = malloc(rows * m * sizeof *data);
    double *amp = malloc(m * r * sizeof *amp);
    double *a = tf_family_design(model, d->force, idx, m, p);
    double *x = malloc(t * r * sizeof *x);
    tf_pod pod = {0};
    int rc = -1;
    if (y && data && amp && a && x) {
        for (size_t i = 0; i < m; ++i) {
            for (size_t o = 0; o < rows; ++o) {
                data[o + i * rows] = y[i + o * m];
            }
        }
        rc = tf_pod_compute(data, (int)rows, (int)m, &pod, err, errlen);
    } else {
        snprintf(err, errlen, "modal p=%u r=%u: out of memory", p, r);
    }
    if (rc == 0) {
        for (size_t i = 0; i < m; ++i) { /* amplitudes: U_r^T u_i */
            for (uint32_t k = 0; k < r; ++k) {
                double s = 0;
                for (size_t o = 0; o < rows; ++o) {
                    s += pod.modes[o + k * rows] * data[o + i * rows];
                }
                amp[i + k * m] = s;
            }
        }
        rc = tf_family_lsq(a, m, t, amp, r, x, err, errlen);
    }
    if (rc == 0) {
        float *c = tf_model_tables(model);
        for (uint32_t k = 0; k < r; ++k) {
            for (uint32_t j = 0; j < t; ++j) {
                c[k * t + j] = (float)x[j + k * t];
            }
        }
        float *u = c + (size_t)r * t;
        for (size_t o = 0; o < rows; ++o) {
            for (uint32_t k = 0; k < r; ++k) {
                u[o * r + k] = (float)pod.modes[o + k * rows];
            }
        }
    }
    tf_pod_free(&pod);
    free(y);
    free(data);
    free(amp);
    free(a);
    free(x);
    if (rc != 0) {
        tf_model_free(model);
        return NULL;
    }
    return model;
}
