/*
 * form.h — the target's model forms on the host: one tf_form per tfit_family
 * id (tfit.h), in one file per form named after the target file that
 * evaluates it (forms/nodal.c pairs with target/src/tfit_nodal.c, ...).
 *
 * A form is what the target evaluates: the table layout, the bounds that
 * tfit_model_check() proves, the reference evaluation the golden vectors
 * come from, the operation count and the instruction mix of the compiled
 * evaluator, the header's layout comments, the Q31 form and, for a stateful
 * form, its filter.  A family (fitting/families/family.h) is a way of
 * fitting models of one form.  Everything below the fitting layer that
 * depends on the form looks it up here (tf_form_of) and calls it: model/,
 * cost/ and emit/ never switch on a family id.
 *
 * Adding a form: a file here defining `const tf_form tf_form_NAME` (and
 * its target evaluator, target/src/tfit_NAME.c), and its name in the FORMS
 * list of registry.c, in id order (docs/architecture.md, "Adding a form").
 */
#ifndef TF_FORM_H
#define TF_FORM_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "base/context.h"
#include "cost/cycles.h"
#include "tfit.h"

/* Defined in model/model.h, model/ref_arith.h and model/q31.h, which include
 * this header's users, not this header (the forms include them). */
typedef struct tf_model tf_model;
typedef struct tf_opcount tf_opcount;
typedef struct tf_arith tf_arith;
typedef struct tf_q31 tf_q31;
typedef struct tf_ctx tf_ctx; /* base/context.h */

/* A stateful form's filter (model/forms/stateful.h): the per-tick
 * recurrence and its coefficients.  NULL for a stateless form. */
typedef struct tf_filter tf_filter;

/* A form's Q31 fixed-point form (docs/q31-format.md; model/q31.h). */
typedef struct tf_form_q31 {
    /* The Q31 table of m, or NULL with the reason. */
    tf_q31 *(*quantise)(tf_ctx *ctx, const tf_model *m);
    /* Sets q's added_error, float_error and error_cases (q31.h). */
    void (*measure)(tf_q31 *q, const tf_model *m, uint64_t seed, uint32_t n_cases);
    /* What the error was measured over, for the header ("envelope points"). */
    const char *error_cases;
    /* Statuses and outputs of the golden inputs in[0..n), as
     * tfit_golden_run_q31 runs them (each alone, or one tick sequence). */
    void (*run)(const tf_q31 *q, const int32_t (*in)[3], size_t n, int32_t *status,
                int32_t *out);
    /* Words of the table between the input map and the rows, written with
     * their comment; returns how many (NULL: none). */
    uint32_t (*emit_words)(FILE *f, const tf_q31 *q);
    /* Banner lines and macros beyond every Q31 form's (NULL: none). */
    void (*emit_banner)(FILE *f, const tf_q31 *q, const tf_model *m);
    void (*emit_macros)(FILE *f, const tf_q31 *q, const tf_model *m, const char *prefix);
} tf_form_q31;

typedef struct tf_form {
    tfit_family id;   /* the target's family id of the form's models */
    const char *name; /* as the family that fits it names it */
    uint32_t n_dims;  /* entries in dims[] (TFIT_*_DIMS) */

    /* ---- layout (docs/header-format.md §3, §8) ---- */
    /* coef[] length for n_out and dims, 0 when invalid or beyond the
     * target's capacity (n_out and n_dims already checked); f is the form
     * itself. */
    uint64_t (*coefs)(const struct tf_form *f, uint32_t n_out, const uint32_t *dims);
    /* What tfit_model_check() proves of the tables beyond the input map:
     * 0, or 1 with a message naming the table and index at fault. */
    int (*bounds)(tf_ctx *ctx, const tf_model *m);

    /* ---- the reference evaluation (model/ref_eval.h, ref_arith.h) ---- */
    /* The form's part (§5) at the projected input g into out[3 n_out],
     * operations counted in c; NULL for a form that is not evaluated at a
     * projected input alone (cut, the stateful forms). */
    void (*ref_map)(tf_arith *c, const tf_model *m, const float g[3], float *out);
    /* The model at the raw input in[3] (its static response: a cut model
     * fully cut, a stateful model relaxed); the tfit_status the target
     * returns, operations added to ops (may be NULL). */
    tfit_status (*ref_eval)(const tf_model *m, const float in[3], float *out, tf_opcount *ops);

    /* ---- golden vectors and the self-test (model/golden.h, §7, §8) ---- */
    /* The golden input design: tf_golden_inputs or tf_golden_ticks. */
    size_t (*golden_inputs)(const tf_model *m, uint64_t seed, float in[][3]);
    /* The self-test's TFIT_CHECK_INPUTS inputs: their indices in that design. */
    const size_t *check_pick;
    /* Statuses and outputs (n x 3 n_out) of inputs in[0..n) as
     * tfit_golden_run() evaluates them. */
    void (*golden_run)(const tf_model *m, const float (*in)[3], size_t n, int32_t *status,
                       float *out);
    /* Self-test input k (tfit_check.c): its status and outputs; state is
     * the run's (a stateful form's, reset before input 0). */
    tfit_status (*check_step)(const tf_model *m, float *state, int k, const float in[3],
                              float *out);
    /* A form whose state is not a filter's (the region law's proxy): the
     * state words the self-test folds after each status, the state zero
     * at the start (0: none; a stateful form's come from its filter). */
    uint32_t state_words;
    /* The self-test's far inputs (§8) when they are not far forces through
     * the input map at coef[0..12) (NULL): far input x (tfit_check.c's
     * sequence) and the state after the carried inputs; returns crc
     * continued over the words the target folds for it. */
    uint32_t (*check_far)(const tf_model *m, float *state, const uint32_t *check,
                          const float x[3], uint32_t crc);

    /* ---- cost (§6; docs/firmware.md, cost/cycles.h) ---- */
    /* Adds the operations of one evaluation. */
    void (*ops)(const tf_model *m, tf_opcount *ops);
    /* Adds the instructions one call of the compiled evaluator executes. */
    void (*insn_mix)(const tf_model *m, tf_core core, tf_insn_mix *mix);
    /* The form's own blocks of the compiled evaluator (those of its target
     * file), for the objdump check of their loops. */
    const tf_block *blocks;
    size_t n_blocks;

    /* ---- the generated header (emit/emit_header.c) ---- */
    const char *input; /* TFIT_NAME_INPUT: "force [N]", ... */
    /* The tables after the input map, each block with its comment; site
     * names an output ("node" or "point"). */
    void (*emit_tables)(FILE *f, const tf_model *m, const char *site);
    /* Banner lines and macros beyond every model's (NULL: none). */
    void (*emit_banner)(FILE *f, const tf_model *m);
    void (*emit_macros)(FILE *f, const tf_model *m, const char *prefix);

    const tf_form_q31 *q31;   /* NULL: no Q31 form */
    const tf_filter *filter;  /* NULL: stateless */
} tf_form;

/* The form of a family id, or NULL when the target has none (registry.c). */
const tf_form *tf_form_of(tfit_family id);

/* The loop blocks of the compiled evaluator, every form's and the shared
 * ones, one line each in the format of tests/firmware/insn_mix.c
 * ("FUNCTION loop K depth D: mix").  Writes at most n bytes; returns the
 * length needed. */
size_t tf_form_loop_table(tf_core core, char *buf, size_t n);

/* ---- shared by the forms (shared.c) ---------------------------------- */

/* The evaluation fields of a stateless form evaluated at its projected
 * input (its ref_map), whose golden vectors and self-test inputs are
 * evaluated each on its own (tf_golden_inputs' design; model/golden.h). */
#define TF_FORM_EACH_INPUT                                                                         \
    .ref_eval = tf_form_ref_eval, .golden_inputs = tf_golden_inputs,                               \
    .check_pick = tf_golden_pick_points, .golden_run = tf_form_run_each,                           \
    .check_step = tf_form_check_each

/* A stateless form's model at the raw input: the projection, its ref_map,
 * the output mask (a NaN/Inf input gives +0 outputs). */
tfit_status tf_form_ref_eval(const tf_model *m, const float in[3], float *out, tf_opcount *ops);
/* Each golden input alone (tf_ref_eval), and self-test input k as the
 * target checks it (alone, no state). */
void tf_form_run_each(const tf_model *m, const float (*in)[3], size_t n, int32_t *status,
                      float *out);
tfit_status tf_form_check_each(const tf_model *m, float *state, int k, const float in[3],
                               float *out);

/* Bounds: one bit of margin under the target's 2^100 (the target sums in
 * float, the host in double). */
#define TF_FORM_BOUND_LIMIT 0x1p99
/* sum_k |c_k| tau^k, k = 0..order: a polynomial's bound for |x| <= tau. */
double tf_form_abs_poly(const float *c, uint32_t order, double tau);
/* 0 when b <= TF_FORM_BOUND_LIMIT; else 1 with a message naming `what`
 * and its index. */
int tf_form_bound_fail(tf_ctx *ctx, double b, const char *what, const tf_model *m, uint32_t index);
/* n_rows rows of n_terms coefficients at c, each bounded on the unit ball
 * (nodal, contact, cut): 0, or 1 with a message. */
int tf_form_rows_bounds(tf_ctx *ctx, const tf_model *m, const float *c, uint64_t n_rows,
                        uint32_t n_terms);

/* The float operations of the M4F's instruction mix of one call (fadd,
 * fmul, fdiv): the operations of a form whose cost model is its traced
 * paths (the region forms). */
void tf_form_mix_ops(const tf_model *m, tf_opcount *ops);
/* crc continued over the bits of n floats (tf_crc32_u32). */
uint32_t tf_form_crc_floats(uint32_t crc, const float *x, size_t n);

/* Operations (§6): the projection (§4), and the basis of degree p (§5.1). */
void tf_form_input_ops(tf_opcount *ops);
void tf_form_basis_ops(uint32_t p, tf_opcount *ops);

/* A block of a coefficient table in the header: n floats as hexadecimal
 * literals, four a line, after its comment (NULL: none). */
void tf_form_write_floats(FILE *f, const float *v, size_t n, const char *comment);
/* The 3 n_out rows of n_terms coefficients at c, one block per output
 * component, commented "SITE NODE C" and suffix. */
void tf_form_write_rows(FILE *f, const tf_model *m, const float *c, uint32_t n_terms,
                        const char *site, const char *suffix);

#endif /* TF_FORM_H */
