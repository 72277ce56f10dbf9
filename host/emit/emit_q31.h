/*
 * emit_q31.h — the Q31 form of each model whose family has one
 * (family.h: nodal and contact) in the generated header and its golden file
 * (docs/q31-format.md §7).  Called by emit_header.c; models without a Q31
 * form get a comment saying why.
 */
#ifndef TF_EMIT_Q31_H
#define TF_EMIT_Q31_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "model/model.h"

/* Points of the envelope behind TFIT_NAME_Q31_ADDED_ERROR_*. */
#define TF_Q31_ERROR_CASES 2000

/* Banner line: the Q31 scales and added error, or why there is no Q31 form. */
void tf_emit_q31_banner(FILE *f, const tf_model *m);

/* PREFIX_Q31_IN_EXP, _OUT_EXP, _ADDED_ERROR_MM (_N), _CRC32, extern. */
void tf_emit_q31_macros(FILE *f, const tf_model *m, const char *prefix);

/* The table tfit_NAME_q31_coef and the tfit_model_q31 tfit_NAME_q31
 * (inside the IMPLEMENTATION block, after the float model's tables). */
void tf_emit_q31_definition(FILE *f, const tf_model *m);

/* Golden vectors from the host integer reference (q31_ref.c).  Returns 0,
 * or -1 when out of memory. */
int tf_emit_q31_golden(FILE *f, const tf_model *m, uint64_t seed);

/* #define TFIT_BASE_GOLDEN_Q31_SETS {&..., 0}: null-terminated. */
void tf_emit_q31_sets(FILE *f, const char *base_upper, tf_model *const *models, size_t n);

#endif /* TF_EMIT_Q31_H */
