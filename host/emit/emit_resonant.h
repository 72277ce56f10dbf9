/*
 * emit_resonant.h — what a resonant model (docs/header-format.md §5.8)
 * adds to the generated header: its state size, tick and the firmware's
 * tick check (shared with prony: emit_prony.h), its modes as frequencies,
 * damping ratios and weights.  Nothing for other families.
 */
#ifndef TF_EMIT_RESONANT_H
#define TF_EMIT_RESONANT_H

#include <stdio.h>

#include "model/model.h"

/* Banner lines: tick, state, each mode's frequency, damping and weights. */
void tf_emit_resonant_banner(FILE *f, const tf_model *m);

/* PREFIX_MODES, _STATE_WORDS, _TICK_NS and the tick check. */
void tf_emit_resonant_macros(FILE *f, const tf_model *m, const char *prefix);

/* The modes' nine floats each in the coefficient table, commented. */
void tf_emit_resonant_modes(FILE *f, const tf_model *m);

#endif /* TF_EMIT_RESONANT_H */
