/*
 * nist_models.h — the model functions of the NIST StRD nonlinear problems
 * and their analytic derivatives.  These are data about the problems, not
 * part of the solver: a file is matched to its function by the model text
 * it contains (nist_strd.h normalises it), never by its name.
 */
#ifndef TF_NIST_MODELS_H
#define TF_NIST_MODELS_H

#include <stddef.h>

/* f(x; b) for one observation (x has n_x entries); when grad is not NULL
 * it receives df/db_j for the n_par parameters. */
typedef double (*tf_nist_fn)(const double *b, const double *x, double *grad);

typedef struct tf_nist_model {
    const char *text;  /* the normalised model text, as nist_strd.c produces it */
    size_t n_par, n_x;
    int log_response;  /* the model is for log(y) (Nelson) */
    tf_nist_fn f;
} tf_nist_model;

/* The model whose text is `text`, or NULL. */
const tf_nist_model *tf_nist_model_find(const char *text);

/* All models (for tests): *count receives their number. */
const tf_nist_model *tf_nist_models(size_t *count);

/* The 27 problem names of the suite in NIST's order (lower, average, then
 * higher difficulty); *count receives 27. */
const char *const *tf_nist_suite(size_t *count);

#endif /* TF_NIST_MODELS_H */
