/*
 * nist_strd.h — reader for the NIST StRD nonlinear-regression files
 * (the .dat files in ../shared/reference/nist-strd): the model text, the two starting
 * points, the certified values, standard deviations and residual sum of
 * squares, and the data, all taken from the file itself using the line
 * ranges of its "File Format" block.  CRLF and LF line endings are accepted.
 */
#ifndef TF_NIST_STRD_H
#define TF_NIST_STRD_H

#include <stddef.h>

#include "base/context.h"

#define TF_NIST_MAX_PAR 16
#define TF_NIST_MAX_X 4

typedef struct tf_nist {
    char name[64];              /* "Dataset Name" */
    char model[1024];           /* model text without blanks, [] as (), no "+e" */
    size_t model_line;          /* 1-based line of the model text, for messages */
    size_t n_par;
    double start[2][TF_NIST_MAX_PAR];
    double certified[TF_NIST_MAX_PAR];
    double certified_sd[TF_NIST_MAX_PAR];
    double certified_rss;
    size_t n_obs, n_x;          /* observations; predictors per observation */
    double *y;                  /* n_obs responses, as in the file */
    double *x;                  /* n_obs * n_x predictors, x[i * n_x + k] */
} tf_nist;

/* Reads path into d.  Returns 0, or -1 with "PATH:LINE: what" in ctx->err (or
 * "PATH: what" when no line applies); d then holds nothing to free. */
int tf_nist_read(tf_ctx *ctx, const char *path, tf_nist *d);
void tf_nist_free(tf_nist *d);

#endif /* TF_NIST_STRD_H */
