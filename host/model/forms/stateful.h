/*
 * stateful.h — the stateful forms (prony, resonant; docs/header-format.md
 * §5.6, §5.8) on the host: one layer (stateful.c, paired with
 * target/src/tfit_stateful.c) over a filter per form (forms/prony.c,
 * forms/resonant.c).
 *
 * A stateful model is {p, r, K, tick_ns}: the input map, K terms of its
 * form's filter, then a static map (nodal rows when r = 0, else modal);
 * state = gp[3] (the previous tick's projected input) | K terms' words.
 * One tick: g = the projected force; the filter turns the increment
 * d = g - gp and the terms' state into new terms and h (h starts at g);
 * h, clamped to [-1, 1], is the static map's input.  The filter is the
 * only part a stateful form has of its own.
 */
#ifndef TF_STATEFUL_H
#define TF_STATEFUL_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "base/context.h"
#include "model/forms/form.h"
#include "model/model.h"
#include "model/ref_arith.h"

/* State words of any stateful model, at most (TFIT_RESONANT_MAX_STATE). */
#define TF_STATEFUL_MAX_STATE TFIT_RESONANT_MAX_STATE

/* A filter: the per-tick recurrence and its coefficients. */
struct tf_filter {
    uint32_t floats;    /* table floats per term, after the input map */
    uint32_t words;     /* state words per term, after gp[3] */
    uint32_t max_terms; /* K at most (the target's capacity) */
    uint32_t term_add, term_mul; /* operations per term, three axes (§6) */
    const char *reset, *step;    /* the public entry points (tfit.h) */
    const char *count;           /* the header's macro of K: "TERMS", "MODES" */
    /* The terms' part of one tick in float arithmetic (c counts it): from
     * the increment d and the terms' state z, the new state zn, with h
     * (which starts at g) updated. */
    void (*ref_terms)(tf_arith *c, const tf_model *m, const float d[3], const float *z,
                      float *zn, float h[3]);
    /* Term k within the device's bounds (tfit_check.c): 0, or 1 with a
     * message naming it. */
    int (*term_check)(tf_ctx *ctx, const tf_model *m, uint32_t k);
    /* Adds the instructions of the filter's function for K terms, its
     * dispatch in tfit_stateful_filter included. */
    void (*insn_mix)(tf_insn_mix *t, tf_core core, uint32_t terms);
    /* The header: the banner's text after "stateful: tick .., state ..; "
     * (the terms as time constants, modes, ...), and term k of the table
     * with its comment. */
    void (*emit_terms)(FILE *f, const tf_model *m);
    void (*emit_term)(FILE *f, const tf_model *m, uint32_t k);
};

/* 1 when m's form is stateful, else 0. */
int tf_stateful(const tf_model *m);

/* The filter of a stateful model. */
const tf_filter *tf_stateful_filter(const tf_model *m);

/* State words of a stateful model (gp included). */
uint32_t tf_stateful_words(const tf_model *m);

/* The tick of m in seconds (dims[3] is in ns). */
double tf_stateful_tick(const tf_model *m);

/* The static map of a stateful model as a nodal (r = 0) or modal model
 * sharing its tables (coef points past the terms, so that its tables start
 * at coef + 12 as that form's do; not an owner: never free it). */
tf_model tf_stateful_static_view(const tf_model *m);

/* A stateful model of family id (named as it) with static map s (a nodal
 * or modal model: its input map, tables, node ids and envelope radius) and
 * K zero terms at tick_ns; the caller sets the terms.  NULL with a message
 * when the shape is invalid or out of memory. */
tf_model *tf_stateful_new(tf_ctx *ctx, tfit_family id, const char *name, const tf_model *s,
                          uint32_t terms, uint32_t tick_ns);

/* The state at rest (the projected zero force, zero terms) and one tick
 * (§5.6, §5.8), as tfit_prony_reset/_step and tfit_resonant_reset/_step:
 * a NaN/Inf force gives TFIT_ERR_INPUT, +0 outputs and the state left as
 * it was.  state holds tf_stateful_words(m) floats; operations added to
 * ops (may be NULL). */
void tf_stateful_reset(const tf_model *m, float *state);
tfit_status tf_stateful_step(const tf_model *m, float *state, const float in[3], float *out,
                             tf_opcount *ops);

/* ---- the form operations every stateful form shares (tf_form) ---------- */

/* The fields of a stateful form's tf_form beside its id, name, dims, own
 * blocks, Q31 form and filter: the stateful layer's operations, and one
 * tick sequence from rest as its golden vectors (tf_golden_ticks;
 * model/golden.h). */
#define TF_STATEFUL_FORM                                                                           \
    .coefs = tf_stateful_coefs, .bounds = tf_stateful_bounds, .ref_map = NULL,                     \
    .ref_eval = tf_stateful_ref_eval, .golden_inputs = tf_golden_ticks,                            \
    .check_pick = tf_golden_pick_ticks, .golden_run = tf_stateful_run,                             \
    .check_step = tf_stateful_check_step, .ops = tf_stateful_ops,                                  \
    .insn_mix = tf_stateful_insn_mix, .input = "force [N]",                                        \
    .emit_tables = tf_stateful_emit_tables, .emit_banner = tf_stateful_emit_banner,                \
    .emit_macros = tf_stateful_emit_macros

uint64_t tf_stateful_coefs(const tf_form *f, uint32_t n_out, const uint32_t *dims);
int tf_stateful_bounds(tf_ctx *ctx, const tf_model *m);
/* The relaxed response: the force held for ever (the state {g, 0}, then one
 * tick), the equilibrium a time-dependent solver's static solve gives;
 * h = g there, so it is the static map at g. */
tfit_status tf_stateful_ref_eval(const tf_model *m, const float in[3], float *out,
                                 tf_opcount *ops);
void tf_stateful_run(const tf_model *m, const float (*in)[3], size_t n, int32_t *status,
                     float *out);
tfit_status tf_stateful_check_step(const tf_model *m, float *state, int k, const float in[3],
                                   float *out);
void tf_stateful_ops(const tf_model *m, tf_opcount *ops);
void tf_stateful_insn_mix(const tf_model *m, tf_core core, tf_insn_mix *mix);
void tf_stateful_emit_tables(FILE *f, const tf_model *m, const char *site);
void tf_stateful_emit_banner(FILE *f, const tf_model *m);
void tf_stateful_emit_macros(FILE *f, const tf_model *m, const char *prefix);
/* The stateful path's own blocks of the compiled evaluator (tfit_prony_step
 * or tfit_resonant_step, tfit_stateful_step and the static map's dispatch). */
extern const tf_block tf_stateful_blocks[];
extern const size_t tf_stateful_n_blocks;

#endif /* TF_STATEFUL_H */
