/*
 * q31.h — the Q31 form of a nodal, contact or prony model (docs/q31-format.md):
 * host-side quantisation, the integer reference evaluator that golden
 * vectors come from (written from the specification, independently of
 * target/src/tfit_q31_*.c), and the error the quantisation adds.
 */
#ifndef TF_Q31_H
#define TF_Q31_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "base/context.h"
#include "model/forms/form.h"
#include "model/model.h"
#include "tfit_q31.h"

typedef struct tf_q31 {
    tfit_family family;
    uint32_t n_out, degree, n_words;
    uint32_t terms;           /* prony: K (q[13]); else 0 */
    int32_t *q;               /* owned: the table of tfit_model_q31.q */
    const uint32_t *node_ids; /* the float model's */
    int in_exp;               /* input value = x * 2^(in_exp - 31) */
    int out_exp;              /* output value = y * 2^(out_exp - 31) */
    /* Measured by tf_q31_measure(): largest |Q31 result - exact model| over
     * points inside and on the envelope (output units), and the float32
     * path's on the same points, for comparison.  NAN until measured. */
    double added_error;
    double float_error;
    uint32_t error_cases;
} tf_q31;

/* Quantises m by its form's Q31 form (model/forms/form.h).  Returns NULL
 * and a reason in ctx->err when m has no Q31 form (a form without one, a prony
 * model with a modal static map or a term too slow for §8's bound; an
 * envelope so elongated that the projection's headroom exceeds 14 bits). */
tf_q31 *tf_q31_quantise(tf_ctx *ctx, const tf_model *m);

/* The Q31 forms (q31_forms.c): of the nodal layout (nodal and contact:
 * §2-§5) and of the prony form (§8). */
extern const tf_form_q31 tf_q31_rows, tf_q31_prony;
/* Their quantisers and error measurements (q31_quantise.c, q31_error.c). */
tf_q31 *tf_q31_quantise_rows(tf_ctx *ctx, const tf_model *m);
tf_q31 *tf_q31_quantise_prony(tf_ctx *ctx, const tf_model *m);
void tf_q31_measure_points(tf_q31 *q, const tf_model *m, uint64_t seed, uint32_t n_cases);
void tf_q31_measure_ticks(tf_q31 *q, const tf_model *m, uint64_t seed, uint32_t n_cases);

/* Q31 words as a block of the header's table: six a line, after their
 * comment (NULL: none). */
void tf_q31_write_words(FILE *f, const int32_t *v, size_t n, const char *comment);
void tf_q31_free(tf_q31 *q);

/* W^-1 of the model's input map (LAPACK); -1 when W is singular. */
int tf_envelope_inverse(const tf_model *m, double inv[9]);

/* CRC-32 in the target's serialisation (tfit_model_crc32_q31). */
uint32_t tf_q31_crc32(const tf_q31 *q);

/* Integer reference: in[3] -> out[3 n_out]; TFIT_OK or TFIT_CLAMPED.
 * g_out (may be NULL) receives the projected input in Q30. */
tfit_status tf_q31_ref_eval(const tf_q31 *q, const int32_t in[3], int32_t *out, int32_t g_out[3]);

/* The prony family's integer reference (q31-format.md §8): state of
 * TFIT_PRONY_Q31_STATE_WORDS(q->terms) words. */
void tf_q31_ref_prony_reset(const tf_q31 *q, int32_t *state);
tfit_status tf_q31_ref_prony_step(const tf_q31 *q, int32_t *state, const int32_t in[3],
                                  int32_t *out);

/* Value <-> Q31 word with exponent e (value = word * 2^(e - 31)); the
 * conversion rounds to nearest and saturates. */
int32_t tf_q31_from_value(double v, int e);
double tf_q31_to_value(int32_t w, int e);

/* Sets added_error, float_error and error_cases (by the form: measure)
 * from n_cases seeded points (inside the envelope, uniform in its volume,
 * and on its boundary: tf_q31_measure_points); for a prony model
 * n_cases x TF_Q31_PRONY_TICKS_PER_CASE ticks of a seeded
 * press-hold-release history from rest, against the float coefficients
 * stepped in double (tf_q31_measure_ticks). */
void tf_q31_measure(tf_q31 *q, const tf_model *m, uint64_t seed, uint32_t n_cases);
#define TF_Q31_PRONY_TICKS_PER_CASE 6u /* 2,000 cases: 12,000 ticks, eight 1.5 s segments */

/* Basis terms of the largest degree, T(TFIT_MAX_DEGREE). */
#define TFIT_Q31_MAX_DEGREE_TERMS 165

#define TF_Q31_GOLDEN_MAX 96
/* Golden inputs: the float golden design's finite inputs converted (with
 * saturation), then the extreme words.  Fills in[][3]; returns the count. */
size_t tf_q31_golden_inputs(const tf_q31 *q, const tf_model *m, uint64_t seed, int32_t in[][3]);

#endif /* TF_Q31_H */
