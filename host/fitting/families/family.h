/*
 * family.h — fitting the model families of GUIDE §3 to solved load
 * cases (docs/fitting.md).  Every fitter builds a tf_model in the target's
 * layout from a subset of the cases (idx[0..m), or all when idx is NULL);
 * linear-in-parameter fits go through the pivoted-QR least squares of
 * lsq.h, one factorisation for all output columns.
 */
#ifndef TF_FIT_FAMILY_H
#define TF_FIT_FAMILY_H

#include <stddef.h>
#include <stdint.h>

#include "fitting/fitdata.h"
#include "model/model.h"

/* Orders of a candidate: nodal/contact {p}; modal {p, r}; zhou2017 uses
 * fit_zhou2017.h.  Returns NULL with a message on failure. */
typedef tf_model *(*tf_family_fitter)(const tf_fitdata *d, const size_t *idx, size_t m,
                                      const uint32_t *orders, const char *name, char *err,
                                      size_t errlen);

/* Nodal: every output component a polynomial of total degree p in the
 * normalised force g = (f - centre) / radius. */
tf_model *tf_fit_nodal(const tf_fitdata *d, const size_t *idx, size_t m, const uint32_t *orders,
                       const char *name, char *err, size_t errlen);

/* Modal: rank-r POD of the training displacements, each amplitude a
 * polynomial of total degree p in g. */
tf_model *tf_fit_modal(const tf_fitdata *d, const size_t *idx, size_t m, const uint32_t *orders,
                       const char *name, char *err, size_t errlen);

/* Contact inverse: the force as a polynomial of degree p in the contact-site
 * displacement, normalised by the fitted contact stiffness so that its
 * envelope is the image of the force ball. */
tf_model *tf_fit_contact(const tf_fitdata *d, const size_t *idx, size_t m, const uint32_t *orders,
                         const char *name, char *err, size_t errlen);

/* Errors of a model on cases idx[0..m) (all when NULL), evaluated exactly as
 * the target does (reference evaluator, float32 input): forward models
 * against d->u in mm; contact models against d->force in N (rel_max: the
 * largest |error| / |force|).  Any of the outputs may be NULL. */
void tf_family_errors(const tf_model *model, const tf_fitdata *d, const size_t *idx, size_t m,
                      double *max, double *rms, double *rel_max);

/* k-fold cross-validated RMS error of fitter at the given orders (and the
 * largest validation error in *max when not NULL): infinite when the folds'
 * cases cannot determine the order (common.h, TF_FAMILY_UNDETERMINED).
 * Returns -1 with a message when a fold fails otherwise. */
int tf_family_cv_error(const tf_fitdata *d, tf_family_fitter fit, const uint32_t *orders,
                       unsigned folds, uint64_t seed, double *rms, double *max, char *err,
                       size_t errlen);

#endif /* TF_FIT_FAMILY_H */
