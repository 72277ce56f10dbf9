/*
 * shared.c — what several forms share (form.h): the evaluation of a
 * stateless form at a raw input, its golden run and self-test steps, the
 * bounds of polynomial rows, the operations of the projection and the
 * basis, and the header's float blocks.
 */
#include "model/forms/form.h"

#include <math.h>
#include <string.h>

#include "base/context.h"

#include "model/model.h"
#include "model/ref_arith.h"
#include "model/ref_eval.h"

tfit_status tf_form_ref_eval(const tf_model *m, const float in[3], float *out, tf_opcount *ops)
{
    tf_arith c = {{0, 0, 0}};
    float g[3];
    int clamped, bad;
    tf_ref_project(&c, m, in, g, &clamped, &bad);
    tf_form_of(m->family)->ref_map(&c, m, g, out);
    if (bad) {
        for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
            out[o] = 0.0f;
        }
    }
    tf_ref_count(ops, &c);
    return bad ? TFIT_ERR_INPUT : (clamped ? TFIT_CLAMPED : TFIT_OK);
}

void tf_form_run_each(const tf_model *m, const float (*in)[3], size_t n, int32_t *status,
                      float *out)
{
    const size_t n_out = 3 * (size_t)m->n_out;
    for (size_t v = 0; v < n; ++v) {
        status[v] = (int32_t)tf_ref_eval(m, in[v], out + v * n_out, NULL);
    }
}

tfit_status tf_form_check_each(const tf_model *m, float *state, int k, const float in[3],
                               float *out)
{
    (void)state;
    (void)k;
    return tf_ref_eval(m, in, out, NULL);
}

void tf_form_write_floats(FILE *f, const float *v, size_t n, const char *comment)
{
    if (comment != NULL) {
        fprintf(f, "    /* %s */\n", comment);
    }
    for (size_t i = 0; i < n; ++i) {
        fprintf(f, "%s%af,%s", i % 4 == 0 ? "    " : " ", (double)v[i],
                (i % 4 == 3 || i + 1 == n) ? "\n" : "");
    }
}

void tf_form_write_rows(FILE *f, const tf_model *m, const float *c, uint32_t n_terms,
                        const char *site, const char *suffix)
{
    static const char comp[] = "xyz";
    char note[128];
    for (uint32_t o = 0; o < 3 * m->n_out; ++o, c += n_terms) {
        snprintf(note, sizeof note, "%s %u %c%s", site, m->node_ids[o / 3], comp[o % 3], suffix);
        tf_form_write_floats(f, c, n_terms, note);
    }
}

double tf_form_abs_poly(const float *c, uint32_t order, double tau)
{
    double s = 0, pw = 1;
    for (uint32_t k = 0; k <= order; ++k, pw *= tau) {
        s += fabs((double)c[k]) * pw;
    }
    return s;
}

int tf_form_bound_fail(tf_ctx *ctx, double b, const char *what, const tf_model *m, uint32_t index)
{
    if (b <= TF_FORM_BOUND_LIMIT) {
        return 0;
    }
    tf_fail(ctx,
            "model '%s': %s %u can reach %g, beyond the float-safe bound 2^99 (non-finite or "
            "ill-scaled coefficients)",
            m->name, what, index, b);
    return 1;
}

int tf_form_rows_bounds(tf_ctx *ctx, const tf_model *m, const float *c, uint64_t n_rows,
                        uint32_t n_terms)
{
    for (uint64_t o = 0; o < n_rows; ++o) {
        if (tf_form_bound_fail(ctx, tf_form_abs_poly(c + o * n_terms, n_terms - 1, 1.0), "output",
                               m, (uint32_t)o)) {
            return 1;
        }
    }
    return 0;
}

/* §4: 33 mul, 14 add, no division. */
void tf_form_input_ops(tf_opcount *ops)
{
    ops->add += 14;
    ops->mul += 33;
}

/* Float operations of the Chebyshev basis of degree p (§5.1, §6): per
 * variable h = g + g and p - 1 recurrence steps (mul, sub) when p >= 2;
 * p (p - 1) / 2 inner products T_b T_c with b, c >= 1, b + c <= p (one per
 * pair, shared by every a) and T(p - 1) - p outer products T_a (..) with
 * a >= 1, b + c >= 1 (a factor T_0 = 1 is exact and not multiplied). */
void tf_form_basis_ops(uint32_t p, tf_opcount *ops)
{
    if (p >= 2) {
        ops->add += 3 * (1 + (uint64_t)(p - 1));
        ops->mul += 3 * (uint64_t)(p - 1) + (uint64_t)p * (p - 1) / 2 + tf_terms(p - 1) - p;
    }
}

void tf_form_mix_ops(const tf_model *m, tf_opcount *ops)
{
    tf_insn_mix mix;
    memset(&mix, 0, sizeof mix);
    tf_form_of(m->family)->insn_mix(m, TF_CORE_M4F, &mix);
    ops->add += mix.n[TF_INSN_FADD];
    ops->mul += mix.n[TF_INSN_FMUL];
    ops->div += mix.n[TF_INSN_FDIV];
}

uint32_t tf_form_crc_floats(uint32_t crc, const float *x, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        uint32_t w;
        memcpy(&w, &x[i], sizeof w);
        crc = tf_crc32_u32(crc, w);
    }
    return crc;
}
