/*
 * q31_forms.c — the Q31 forms (q31.h, model/forms/form.h): how a Q31 model
 * of the nodal layout (nodal, contact) and of the prony form is quantised,
 * measured, run for its golden vectors and written into the header beyond
 * what every Q31 form has (docs/q31-format.md §7, §8).
 */
#include "model/q31.h"

#include <math.h>

void tf_q31_write_words(FILE *f, const int32_t *v, size_t n, const char *comment)
{
    if (comment != NULL) {
        fprintf(f, "    /* %s */\n", comment);
    }
    for (size_t i = 0; i < n; ++i) {
        const char *sep = i % 6 == 0 ? "    " : " ";
        if (v[i] == INT32_MIN) {
            fprintf(f, "%s(-2147483647 - 1),", sep);
        } else {
            fprintf(f, "%s%d,", sep, v[i]);
        }
        if (i % 6 == 5 || i + 1 == n) {
            fprintf(f, "\n");
        }
    }
}

/* ---- the nodal layout: every golden input alone -------------------------- */

static void run_rows(const tf_q31 *q, const int32_t (*in)[3], size_t n, int32_t *status,
                     int32_t *out)
{
    for (size_t v = 0; v < n; ++v) {
        status[v] = (int32_t)tf_q31_ref_eval(q, in[v], out + v * 3 * (size_t)q->n_out, NULL);
    }
}

const tf_form_q31 tf_q31_rows = {
    .quantise = tf_q31_quantise_rows,
    .measure = tf_q31_measure_points,
    .error_cases = "envelope points",
    .run = run_rows,
    .emit_words = NULL,
    .emit_banner = NULL,
    .emit_macros = NULL,
};

/* ---- the prony form: one tick sequence from rest, K and the terms -------- */

static void run_prony(const tf_q31 *q, const int32_t (*in)[3], size_t n, int32_t *status,
                      int32_t *out)
{
    int32_t state[TFIT_PRONY_Q31_STATE_WORDS(TFIT_PRONY_MAX_TERMS)];
    tf_q31_ref_prony_reset(q, state);
    for (size_t v = 0; v < n; ++v) {
        status[v] = (int32_t)tf_q31_ref_prony_step(q, state, in[v], out + v * 3 * (size_t)q->n_out);
    }
}

static uint32_t prony_words(FILE *f, const tf_q31 *q)
{
    const int32_t *w = q->q + TFIT_Q31_MAP_WORDS;
    tf_q31_write_words(f, w, 1, "prony: K, then {a_k (Q31), D_k (Q30)} per term");
    tf_q31_write_words(f, w + 1, 2 * q->terms, NULL);
    return 1 + 2 * q->terms;
}

/* A prony model is a forward model: its outputs are in mm. */
static void prony_banner(FILE *f, const tf_q31 *q, const tf_model *m)
{
    fprintf(f,
            " *         (prony, q31-format.md section 8: %u ticks of a press-hold-release "
            "history from rest against the float coefficients stepped in double; state %u "
            "int32 words, tfit_prony_reset_q31, tfit_prony_step_q31)\n",
            q->error_cases, TFIT_PRONY_Q31_STATE_WORDS(q->terms));
    if (!isnan(m->heldout_q31_max)) {
        fprintf(f,
                " *         Q31 against the held-out solves: max %.3g mm over %u histories (the "
                "float model's %.3g)\n",
                m->heldout_q31_max, m->heldout_cases, m->heldout_max);
    }
}

static void prony_macros(FILE *f, const tf_q31 *q, const tf_model *m, const char *p)
{
    fprintf(f,
            "#define %s_Q31_STATE_WORDS %uu /* int32 state[]: tfit_prony_reset_q31, _step_q31 "
            "*/\n",
            p, TFIT_PRONY_Q31_STATE_WORDS(q->terms));
    if (!isnan(m->heldout_q31_max)) {
        fprintf(f,
                "#define %s_Q31_HELDOUT_MAX_MM %.6g /* the Q31 form's held-out max, measured "
                "*/\n",
                p, m->heldout_q31_max);
    }
}

const tf_form_q31 tf_q31_prony = {
    .quantise = tf_q31_quantise_prony,
    .measure = tf_q31_measure_ticks,
    .error_cases = "ticks of a press-hold-release history",
    .run = run_prony,
    .emit_words = prony_words,
    .emit_banner = prony_banner,
    .emit_macros = prony_macros,
};
