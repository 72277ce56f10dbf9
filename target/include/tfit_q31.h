/*
 * tfit_q31.h — the fixed-point evaluator for cores without an FPU
 * (Cortex-M0+, Cortex-M3): integer-only, in the style of CMSIS-DSP's Q31
 * functions, bit-exact against the host's integer reference.
 *
 * A tfit_model_q31 is the host's quantisation of a nodal, contact or prony model
 * (the families whose outputs are polynomial rows, and prony models with a
 * nodal static map, section 8 of q31-format.md; modal and zhou2017 have
 * no Q31 form).  Every generated header holds one beside each such float
 * model, named tfit_NAME_q31, with its scales and the error the
 * quantisation adds (docs/q31-format.md):
 *
 *     input   int32 x[3], value x * 2^(TFIT_NAME_Q31_IN_EXP - 31) in the
 *             model's input unit (N, or mm for contact models)
 *     output  int32 y[3 n_out], value y * 2^(TFIT_NAME_Q31_OUT_EXP - 31)
 *             in its output unit (mm, or N)
 *     TFIT_NAME_Q31_ADDED_ERROR_MM (_N)   largest difference from the exact
 *             float model over the envelope, input rounding included
 *
 * The fitted envelope fills at most half the input range, so an input up to
 * twice the envelope's extent is representable; inputs beyond it are
 * projected onto the envelope exactly like the float path does
 * (TFIT_CLAMPED).  Saturate when converting a larger sensor value: it is
 * outside the envelope anyway.  There is no NaN in Q31, so the statuses are
 * TFIT_OK and TFIT_CLAMPED (and the argument errors).
 *
 * Like the float path: no libc, no heap, no recursion, no static state, and
 * a fixed instruction count per model whatever the input.  Multiplications
 * are 32 x 32 -> 64 bits (SMULL/UMULL on Armv7-M; a 16-bit decomposition on
 * Armv6-M, which has no long multiply), so no libgcc helper is needed.
 */
#ifndef TFIT_Q31_H
#define TFIT_Q31_H

#include <stdint.h>

#include "tfit.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Version of the Q31 table layout and integer operation order. */
#define TFIT_Q31_API_VERSION 3

/* Words of a Q31 input map at the start of q[]: x0 (3), W (9), H (1). */
#define TFIT_Q31_MAP_WORDS 13

typedef struct tfit_model_q31 {
    uint32_t api_version;     /* TFIT_Q31_API_VERSION */
    uint32_t family;          /* TFIT_FAMILY_NODAL, _CONTACT or _PRONY */
    uint32_t n_out;           /* output points; outputs are 3 x n_out words */
    uint32_t degree;          /* total degree p of the rows */
    uint32_t n_words;         /* entries in q[]: 13 + 3 n_out (T(p) + 1); prony: + 1 + 2 K */
    const int32_t *q;         /* input map, [prony: K, K pairs {a_k, D_k}], then per row:
                                 shift, T(p) coefficients */
    const uint32_t *node_ids; /* n_out scene node numbers */
    /* q + n_words and node_ids + n_out: a damaged pointer no longer matches
     * its end, and tfit_model_check_q31() finds it without reading through it
     * (the CRC cannot cover addresses). */
    const int32_t *q_end;
    const uint32_t *node_ids_end;
    uint32_t crc32; /* CRC-32 over the scalar fields and the two tables */
} tfit_model_q31;

/* Pointers (NULL: TFIT_ERR_ARG; not matching their ends: TFIT_ERR_CORRUPT),
 * version, family, sizes, CRC-32 and the range proof (every shift in its
 * documented range, every coefficient row small enough that no
 * intermediate overflows).  Call once at boot. */
tfit_status tfit_model_check_q31(const tfit_model_q31 *m);

/* CRC-32 of the model as tfit_model_check_q31() computes it; 0 for NULL. */
uint32_t tfit_model_crc32_q31(const tfit_model_q31 *m);

/* Forward model: force in Q31 of 2^IN_EXP N -> out[3 n_out] in Q31 of
 * 2^OUT_EXP mm.  Returns TFIT_OK, TFIT_CLAMPED, TFIT_ERR_ARG or
 * TFIT_ERR_FAMILY. */
tfit_status tfit_displacements_q31(const tfit_model_q31 *m, const int32_t force[3], int32_t *out);

/* Contact model: displacement in Q31 of 2^IN_EXP mm -> force[3] in Q31 of
 * 2^OUT_EXP N. */
tfit_status tfit_contact_force_q31(const tfit_model_q31 *m, const int32_t disp[3],
                                   int32_t force[3]);

/* Prony models in Q31 (TFIT_FAMILY_PRONY, docs/q31-format.md §8): the
 * float prony step (tfit_prony_step) with a caller-owned int32 state of
 * TFIT_PRONY_Q31_STATE_WORDS(K) words (the header's
 * TFIT_NAME_Q31_STATE_WORDS): the previous tick's projected input (Q30),
 * then each term's three components (Q29).  Same tick period as the float
 * model (TFIT_NAME_TICK_NS).  There is no NaN in Q31: every int32 force is
 * valid; TFIT_CLAMPED when it was projected onto the envelope. */
#define TFIT_PRONY_Q31_STATE_WORDS(terms) (3u + 3u * (uint32_t)(terms))
tfit_status tfit_prony_reset_q31(const tfit_model_q31 *m, int32_t *state);
tfit_status tfit_prony_step_q31(const tfit_model_q31 *m, int32_t *state, const int32_t force[3],
                                int32_t *out);

/* Golden vectors of a Q31 model (NAME_golden.h, TFIT_NAME_GOLDEN_Q31_SETS,
 * a null-terminated list): inputs, statuses and output words computed by
 * the host's integer reference.  A prony model's vectors are one tick
 * sequence stepped from tfit_prony_reset_q31(). */
typedef struct tfit_golden_q31 {
    const tfit_model_q31 *model;
    uint32_t n_vec;
    const int32_t *in;     /* n_vec x 3 */
    const int32_t *status; /* n_vec */
    const int32_t *out;    /* n_vec x 3 n_out */
} tfit_golden_q31;

/* Mismatching words (statuses and outputs) over every golden vector, into
 * scratch[3 * model->n_out]; UINT32_MAX for NULL arguments. */
uint32_t tfit_golden_run_q31(const tfit_golden_q31 *g, int32_t *scratch);

#ifdef __cplusplus
}
#endif

#endif /* TFIT_Q31_H */
