/*
 * emit_q31.c — see emit_q31.h.  The quantisation is a pure function of the
 * model, so each part re-derives it rather than threading state through
 * the emitter.
 */
#include "emit/emit_q31.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fitting/families/family.h"
#include "model/forms/form.h"
#include "model/q31.h"

#define ERROR_SEED 0x51u /* fixed: the same header every time */

static int inverse(const tf_model *m)
{
    return tf_family_of(m->family)->kind == TF_FAMILY_INVERSE;
}

/* Output unit in macro names (upper case) or text; input unit. */
static const char *unit(const tf_model *m, int upper_case)
{
    return inverse(m) ? "N" : (upper_case ? "MM" : "mm");
}

static const char *in_unit(const tf_model *m)
{
    return inverse(m) ? "mm" : "N";
}

/* The Q31 form of the model's form (form.h), or NULL with the reason. */
static const tf_form_q31 *form_q31(const tf_model *m)
{
    return tf_form_of(m->family)->q31;
}

static tf_q31 *quantised(tf_ctx *ctx, const tf_model *m)
{
    const tf_form *f = tf_form_of(m->family);
    if (f->q31 == NULL) {
        tf_fail(ctx, "model '%s': no Q31 form for the %s family", m->name, f->name);
        return NULL;
    }
    return f->q31->quantise(ctx, m);
}

static tf_q31 *measured(tf_ctx *ctx, const tf_model *m)
{
    tf_q31 *q = quantised(ctx, m);
    if (q != NULL) {
        tf_q31_measure(q, m, ERROR_SEED, TF_Q31_ERROR_CASES);
    }
    return q;
}

void tf_emit_q31_banner(FILE *f, const tf_model *m)
{
    tf_ctx why; /* no Q31 form is not a failure: the banner says why */
    tf_ctx_init(&why);
    tf_q31 *q = measured(&why, m);
    if (q == NULL) {
        fprintf(f, " *       %s\n", why.err);
        return;
    }
    fprintf(f,
            " *       Q31 form tfit_%s_q31: input 2^%d %s, output 2^%d %s full scale; adds "
            "%.3g %s (float32 path: %.3g)\n",
            m->name, q->in_exp, in_unit(m), q->out_exp, unit(m, 0), q->added_error, unit(m, 0),
            q->float_error);
    if (form_q31(m)->emit_banner != NULL) {
        form_q31(m)->emit_banner(f, q, m);
    }
    tf_q31_free(q);
}

void tf_emit_q31_macros(FILE *f, const tf_model *m, const char *p)
{
    tf_ctx scratch; /* no Q31 form: nothing to write, no failure */
    tf_ctx_init(&scratch);
    tf_q31 *q = measured(&scratch, m);
    if (q == NULL) {
        return;
    }
    fprintf(f, "#define %s_Q31_IN_EXP %d /* input word x = value * 2^(31 - %d), %s */\n", p,
            q->in_exp, q->in_exp, in_unit(m));
    fprintf(f, "#define %s_Q31_OUT_EXP %d /* output value = word * 2^(%d - 31), %s */\n", p,
            q->out_exp, q->out_exp, unit(m, 0));
    fprintf(f,
            "#define %s_Q31_ADDED_ERROR_%s %.6g /* max |Q31 - exact| at %u %s; "
            "float32: %.6g */\n",
            p, unit(m, 1), q->added_error, q->error_cases, form_q31(m)->error_cases,
            q->float_error);
    if (form_q31(m)->emit_macros != NULL) {
        form_q31(m)->emit_macros(f, q, m, p);
    }
    fprintf(f, "#define %s_Q31_CRC32 0x%08xu\n", p, tf_q31_crc32(q));
    fprintf(f, "#define tfit_%s_q31 tfit_%s_q31_%08x /* this header's version of the model */\n",
            m->name, m->name, tf_q31_crc32(q));
    fprintf(f, "extern const tfit_model_q31 tfit_%s_q31;\n", m->name);
    tf_q31_free(q);
}

void tf_emit_q31_definition(FILE *f, const tf_model *m)
{
    char note[96];
    static const char comp[] = "xyz";
    tf_ctx scratch; /* no Q31 form: nothing to write, no failure */
    tf_ctx_init(&scratch);
    tf_q31 *q = quantised(&scratch, m);
    if (q == NULL) {
        return;
    }
    const uint32_t t = tf_terms(q->degree);
    fprintf(f, "static const int32_t tfit_%s_q31_coef[%u] = {\n", m->name, q->n_words);
    tf_q31_write_words(f, q->q, 3, "Q31 input map: centre (Q30 of 2^IN_EXP)");
    tf_q31_write_words(f, q->q + 3, 9, "W (row-major), then the projection's headroom H");
    tf_q31_write_words(f, q->q + 12, 1, NULL);
    const int32_t *rows = q->q + TFIT_Q31_MAP_WORDS;
    if (form_q31(m)->emit_words != NULL) { /* a form's words before the rows */
        rows += form_q31(m)->emit_words(f, q);
    }
    for (uint32_t o = 0; o < 3 * q->n_out; ++o) {
        snprintf(note, sizeof note, "node %u %c: shift, then %u coefficients", m->node_ids[o / 3],
                 comp[o % 3], t);
        tf_q31_write_words(f, rows + o * (t + 1), t + 1, note);
    }
    fprintf(f, "};\n");
    fprintf(f,
            "const tfit_model_q31 tfit_%s_q31 = {\n    %uu, %uu, %uu, %uu, %uu,\n"
            "    tfit_%s_q31_coef, tfit_%s_nodes,\n"
            "    tfit_%s_q31_coef + %uu, tfit_%s_nodes + %uu,\n    0x%08xu\n};\n",
            m->name, TFIT_Q31_API_VERSION, (unsigned)q->family, q->n_out, q->degree, q->n_words,
            m->name, m->name, m->name, q->n_words, m->name, q->n_out, tf_q31_crc32(q));
    tf_q31_free(q);
}

int tf_emit_q31_golden(FILE *f, const tf_model *m, uint64_t seed)
{
    tf_ctx scratch; /* no Q31 form: nothing to write, no failure */
    tf_ctx_init(&scratch);
    tf_q31 *q = quantised(&scratch, m);
    if (q == NULL) {
        return 0;
    }
    int32_t in[TF_Q31_GOLDEN_MAX][3], status[TF_Q31_GOLDEN_MAX];
    const size_t n_vec = tf_q31_golden_inputs(q, m, seed, in), n_out = 3 * (size_t)q->n_out;
    int32_t *out = malloc(n_vec * n_out * sizeof *out);
    if (out == NULL) {
        tf_q31_free(q);
        return -1;
    }
    form_q31(m)->run(q, (const int32_t(*)[3])in, n_vec, status, out);
    char upper[TF_NAME_MAX];
    size_t k = 0;
    for (; m->name[k] != '\0' && k + 1 < sizeof upper; ++k) {
        upper[k] = (char)toupper((unsigned char)m->name[k]);
    }
    upper[k] = '\0';
    fprintf(f, "\n#define TFIT_%s_Q31_GOLDEN_N %zu\n", upper, n_vec);
    fprintf(f, "static const int32_t tfit_%s_q31_golden_in[%zu] = {\n", m->name, 3 * n_vec);
    tf_q31_write_words(f, &in[0][0], 3 * n_vec, NULL);
    fprintf(f, "};\nstatic const int32_t tfit_%s_q31_golden_status[%zu] = {\n", m->name, n_vec);
    tf_q31_write_words(f, status, n_vec, NULL);
    fprintf(f, "};\nstatic const int32_t tfit_%s_q31_golden_out[%zu] = {\n", m->name,
            n_vec * n_out);
    tf_q31_write_words(f, out, n_vec * n_out, NULL);
    fprintf(f,
            "};\nstatic const tfit_golden_q31 tfit_%s_q31_golden = {\n    &tfit_%s_q31, %zuu, "
            "tfit_%s_q31_golden_in, tfit_%s_q31_golden_status, tfit_%s_q31_golden_out\n};\n",
            m->name, m->name, n_vec, m->name, m->name, m->name);
    free(out);
    tf_q31_free(q);
    return 0;
}

void tf_emit_q31_sets(FILE *f, const char *base_upper, tf_model *const *models, size_t n)
{
    tf_ctx scratch; /* no Q31 form: not in the list, no failure */
    tf_ctx_init(&scratch);
    fprintf(f, "#define TFIT_%s_GOLDEN_Q31_SETS {", base_upper);
    for (size_t i = 0; i < n; ++i) {
        tf_q31 *q = quantised(&scratch, models[i]);
        if (q != NULL) {
            fprintf(f, "&tfit_%s_q31_golden, ", models[i]->name);
        }
        tf_q31_free(q);
    }
    fprintf(f, "0}\n");
}
