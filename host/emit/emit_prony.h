/*
 * emit_prony.h — what a prony model (docs/header-format.md §5.6) adds to
 * the generated header: its state size, tick period and the compile-time
 * check of the firmware's own tick, its terms as time constants and
 * weights.  Called by emit_header.c for every model; nothing for other
 * families.
 */
#ifndef TF_EMIT_PRONY_H
#define TF_EMIT_PRONY_H

#include <stdio.h>

#include "model/model.h"

/* Banner lines: tick, state, each term's time constant and weight. */
void tf_emit_prony_banner(FILE *f, const tf_model *m);

/* PREFIX_TERMS, _STATE_WORDS, _TICK_NS, _TICK_HZ and the #error lines that
 * stop a firmware whose TFIT_TICK_NS or TFIT_TICK_US differs. */
void tf_emit_prony_macros(FILE *f, const tf_model *m, const char *prefix);

/* PREFIX_TICK_NS and the #error lines that stop a firmware whose
 * TFIT_TICK_NS or TFIT_TICK_US differs from dims[3] (every stateful family;
 * step names its step function in the comment). */
void tf_emit_tick_macros(FILE *f, const tf_model *m, const char *prefix, const char *step);

/* The term pairs {a_k, D_k} of the coefficient table, commented. */
void tf_emit_prony_terms(FILE *f, const tf_model *m);

#endif /* TF_EMIT_PRONY_H */
