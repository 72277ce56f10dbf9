/*
 * stateful.c — see stateful.h: the stateful forms' one layer on the host,
 * paired with target/src/tfit_stateful.c.  Everything here is the same for
 * every filter; a filter (tf_filter) brings its terms' recurrence, bounds,
 * operations, compiled blocks and header text.
 */
#include "model/forms/stateful.h"

#include <math.h>
#include <string.h>

#include "cost/evaluator.h"

int tf_stateful(const tf_model *m)
{
    const tf_form *f = tf_form_of(m->family);
    return f != NULL && f->filter != NULL;
}

const tf_filter *tf_stateful_filter(const tf_model *m)
{
    return tf_form_of(m->family)->filter;
}

uint32_t tf_stateful_words(const tf_model *m)
{
    return 3 + tf_stateful_filter(m)->words * m->dims[2];
}

double tf_stateful_tick(const tf_model *m)
{
    return 1e-9 * (double)m->dims[3];
}

tf_model tf_stateful_static_view(const tf_model *m)
{
    tf_model v = *m;
    const uint32_t skip = tf_stateful_filter(m)->floats * m->dims[2];
    /* the layout's own choice (r = 0: nodal rows, else a modal table) */
    v.family = m->dims[1] == 0 ? TFIT_FAMILY_NODAL : TFIT_FAMILY_MODAL;
    v.n_dims = m->dims[1] == 0 ? TFIT_NODAL_DIMS : TFIT_MODAL_DIMS;
    v.coef = m->coef + skip; /* its tables at coef + 12, as the form's own */
    v.n_coef = m->n_coef - skip;
    return v;
}

tf_model *tf_stateful_new(tf_ctx *ctx, tfit_family id, const char *name, const tf_model *s,
                          uint32_t terms, uint32_t tick_ns)
{
    const uint32_t r = s->dims[1] * (s->n_dims > 1); /* a nodal map has no rank */
    const uint32_t dims[TFIT_PRONY_DIMS] = {s->dims[0], r, terms, tick_ns}; /* every stateful form's */
    tf_model *m = tf_model_new(ctx, name, id, s->n_out, dims, TFIT_PRONY_DIMS);
    if (m == NULL) {
        return NULL;
    }
    const uint32_t skip = tf_stateful_filter(m)->floats * terms;
    memcpy(m->coef, s->coef, TFIT_INPUT_MAP_FLOATS * sizeof *m->coef);
    memcpy(m->coef + TFIT_INPUT_MAP_FLOATS + skip, s->coef + TFIT_INPUT_MAP_FLOATS,
           (s->n_coef - TFIT_INPUT_MAP_FLOATS) * sizeof *m->coef);
    memcpy(m->node_ids, s->node_ids, s->n_out * sizeof *m->node_ids);
    m->envelope_radius = s->envelope_radius;
    return m;
}

/* {p, r, K, tick_ns}: K terms, then nodal rows (r = 0) or a modal table;
 * a tick of at least 1 ns. */
uint64_t tf_stateful_coefs(const tf_form *f, uint32_t n_out, const uint32_t *dims)
{
    const tf_filter *fl = f->filter;
    if (dims[0] > TFIT_MAX_DEGREE || dims[1] > TFIT_MAX_RANK || dims[2] > fl->max_terms ||
        dims[3] == 0) {
        return 0;
    }
    const uint64_t t = tf_terms(dims[0]);
    return TFIT_INPUT_MAP_FLOATS + (uint64_t)fl->floats * dims[2] +
           (dims[1] == 0 ? 3ull * n_out * t : dims[1] * t + 3ull * n_out * dims[1]);
}

/* Every term within the device's bounds, then the static map as its own
 * form (h is clamped to [-1, 1] before it). */
int tf_stateful_bounds(tf_ctx *ctx, const tf_model *m)
{
    const tf_filter *f = tf_stateful_filter(m);
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        if (f->term_check(ctx, m, k) != 0) {
            return 1;
        }
    }
    const tf_model v = tf_stateful_static_view(m);
    return tf_form_of(v.family)->bounds(ctx, &v);
}

/* The filter (§5.6, §5.8): d_i = g_i - gp_i, h_i = g_i, the terms; h
 * clamped; the state becomes {g, terms} unless the input was bad. */
static void filter_tick(tf_arith *c, const tf_model *m, const float g[3], int bad, float *state,
                        float h[3])
{
    float next[TF_STATEFUL_MAX_STATE], d[3];
    for (int i = 0; i < 3; ++i) {
        d[i] = tf_ref_sub(c, g[i], state[i]);
        h[i] = g[i];
        next[i] = g[i];
    }
    tf_stateful_filter(m)->ref_terms(c, m, d, state + 3, next + 3, h);
    for (int i = 0; i < 3; ++i) {
        h[i] = tf_ref_clamp_unit(h[i]);
    }
    if (!bad) {
        memcpy(state, next, tf_stateful_words(m) * sizeof *state);
    }
}

void tf_stateful_reset(const tf_model *m, float *state)
{
    const float zero[3] = {0, 0, 0};
    tf_arith c = {{0, 0, 0}};
    int clamped, bad;
    tf_ref_project(&c, m, zero, state, &clamped, &bad); /* the projected zero force */
    for (uint32_t w = 3; w < tf_stateful_words(m); ++w) {
        state[w] = 0.0f;
    }
}

tfit_status tf_stateful_step(const tf_model *m, float *state, const float in[3], float *out,
                             tf_opcount *ops)
{
    tf_arith c = {{0, 0, 0}};
    float g[3], h[3];
    int clamped, bad;
    tf_ref_project(&c, m, in, g, &clamped, &bad);
    filter_tick(&c, m, g, bad, state, h);
    const tf_model v = tf_stateful_static_view(m);
    tf_form_of(v.family)->ref_map(&c, &v, h, out);
    if (bad) {
        for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
            out[o] = 0.0f;
        }
    }
    tf_ref_count(ops, &c);
    return bad ? TFIT_ERR_INPUT : (clamped ? TFIT_CLAMPED : TFIT_OK);
}

tfit_status tf_stateful_ref_eval(const tf_model *m, const float in[3], float *out,
                                 tf_opcount *ops)
{
    float state[TF_STATEFUL_MAX_STATE];
    tf_arith c = {{0, 0, 0}};
    int clamped, bad;
    tf_stateful_reset(m, state);
    tf_ref_project(&c, m, in, state, &clamped, &bad); /* gp = g: no increment, at rest */
    return tf_stateful_step(m, state, in, out, ops);
}

/* The golden vectors are one tick sequence from rest (tfit_golden_run). */
void tf_stateful_run(const tf_model *m, const float (*in)[3], size_t n, int32_t *status,
                     float *out)
{
    float state[TF_STATEFUL_MAX_STATE];
    tf_stateful_reset(m, state);
    for (size_t v = 0; v < n; ++v) {
        status[v] = (int32_t)tf_stateful_step(m, state, in[v], out + v * 3 * (size_t)m->n_out,
                                              NULL);
    }
}

tfit_status tf_stateful_check_step(const tf_model *m, float *state, int k, const float in[3],
                                   float *out)
{
    (void)k;
    return tf_stateful_step(m, state, in, out, NULL);
}

/* The filter (§6): 3 differences, the terms' operations; then the static
 * map as its own form. */
void tf_stateful_ops(const tf_model *m, tf_opcount *ops)
{
    const tf_filter *f = tf_stateful_filter(m);
    const tf_model v = tf_stateful_static_view(m);
    tf_form_of(v.family)->ops(&v, ops);
    ops->add += 3 + (uint64_t)f->term_add * m->dims[2];
    ops->mul += (uint64_t)f->term_mul * m->dims[2];
}

/* The path outside the filter's function and the static map's evaluator,
 * measured as the QEMU trace less the projection, the filter and the
 * static map's evaluator: the same for every stateful test model of each
 * kind of static map. */
enum { STATEFUL_NODAL, STATEFUL_ROWS, STATEFUL_MODAL, N_BLOCKS };
const tf_block tf_stateful_blocks[N_BLOCKS] = {
    /* one tick outside the filter and the static map: tfit_prony_step or
     * tfit_resonant_step (checks, tail call), tfit_stateful_step (the
     * projection's and the filter's calls, the static map's view, the
     * status), tfit_stateful_eval to tfit_eval_nodal (p != 1) */
    [STATEFUL_NODAL] = {"tfit_stateful_step", 0, 0,
                        {"alu=53 mul=1 load=23 store=6 ldm=3 ldm_pc=1 stm=5 words=28 branch=6 "
                         "nbranch=7",
                         "alu=53 mul=1 load=23 store=8 ldm=3 ldm_pc=1 stm=4 words=24 branch=6 "
                         "nbranch=7"}},
    /* ... to tfit_degree1_rows_asm (nodal p = 1) */
    [STATEFUL_ROWS] = {"tfit_stateful_step", 0, 0,
                       {"alu=56 mul=1 load=25 store=7 ldm=2 ldm_pc=2 stm=5 words=28 branch=7 "
                        "nbranch=6",
                        "alu=56 mul=1 load=25 store=9 ldm=2 ldm_pc=2 stm=4 words=24 branch=7 "
                        "nbranch=6"}},
    /* ... to tfit_eval_modal */
    [STATEFUL_MODAL] = {"tfit_stateful_step", 0, 0,
                        {"alu=51 mul=1 load=21 store=6 ldm=3 ldm_pc=1 stm=5 words=28 branch=7 "
                         "nbranch=5",
                         "alu=51 mul=1 load=21 store=8 ldm=3 ldm_pc=1 stm=4 words=24 branch=7 "
                         "nbranch=5"}},
};
const size_t tf_stateful_n_blocks = N_BLOCKS;

/* The entry point and the step's path for the static map's kind, the
 * projection, the filter, then the static map's evaluator (at p = 1 the
 * rows of tfit_degree1_rows_asm). */
void tf_stateful_insn_mix(const tf_model *m, tf_core core, tf_insn_mix *mix)
{
    const tf_model v = tf_stateful_static_view(m);
    tf_insn_input(mix, core);
    tf_stateful_filter(m)->insn_mix(mix, core, m->dims[2]);
    if (m->dims[1] != 0) { /* rank r: a modal static map */
        tf_insn_add(mix, &tf_stateful_blocks[STATEFUL_MODAL], core, 1);
        tf_insn_modal(mix, core, v.dims[0], v.dims[1], v.n_out);
    } else if (v.dims[0] != 1) {
        tf_insn_add(mix, &tf_stateful_blocks[STATEFUL_NODAL], core, 1);
        tf_insn_nodal(mix, core, v.dims[0], v.n_out);
    } else {
        tf_insn_add(mix, &tf_stateful_blocks[STATEFUL_ROWS], core, 1);
        tf_insn_degree1_rows(mix, core, v.n_out);
    }
}

/* The terms, then the static map's tables as its own form's. */
void tf_stateful_emit_tables(FILE *f, const tf_model *m, const char *site)
{
    const tf_filter *fl = tf_stateful_filter(m);
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        fl->emit_term(f, m, k);
    }
    const tf_model v = tf_stateful_static_view(m);
    tf_form_of(v.family)->emit_tables(f, &v, site);
}

void tf_stateful_emit_banner(FILE *f, const tf_model *m)
{
    const tf_filter *fl = tf_stateful_filter(m);
    fprintf(f, " *       stateful: tick %u ns, state %u floats (%s, %s);", m->dims[3],
            tf_stateful_words(m), fl->reset, fl->step);
    fl->emit_terms(f, m);
    fprintf(f, "\n");
    if (!isnan(m->heldout_rel_max)) {
        fprintf(f,
                " *       held-out cases are force histories stepped from rest: largest error "
                "%.3g %% of the largest displacement\n",
                100 * m->heldout_rel_max);
    }
}

/* PREFIX_TICK_NS and the #error lines that stop a firmware whose
 * TFIT_TICK_NS or TFIT_TICK_US differs from dims[3]. */
static void tick_macros(FILE *f, const tf_model *m, const char *p, const char *step)
{
    const uint32_t ns = m->dims[3];
    fprintf(f, "#define %s_TICK_NS %uu /* the model's tick: call %s at %.9g Hz */\n", p, ns, step,
            1e9 / ns);
    /* The firmware states its own tick as TFIT_TICK_NS or TFIT_TICK_US: a
     * model fitted for another one must not build (the discrete update is
     * exact for this period only). */
    fprintf(f,
            "#if defined(TFIT_TICK_NS) && (TFIT_TICK_NS) != %u\n"
            "#error \"%s: fitted for a %u ns tick, the firmware's TFIT_TICK_NS differs: refit "
            "with that tick\"\n#endif\n",
            ns, m->name, ns);
    fprintf(f,
            "#if defined(TFIT_TICK_US) && (TFIT_TICK_US) * 1000 != %u\n"
            "#error \"%s: fitted for a %u ns tick, the firmware's TFIT_TICK_US differs: refit "
            "with that tick\"\n#endif\n",
            ns, m->name, ns);
}

/* PREFIX_TERMS (or _MODES), _STATE_WORDS, _TICK_NS and the tick check. */
void tf_stateful_emit_macros(FILE *f, const tf_model *m, const char *p)
{
    const tf_filter *fl = tf_stateful_filter(m);
    fprintf(f, "#define %s_%s %u\n", p, fl->count, m->dims[2]);
    fprintf(f, "#define %s_STATE_WORDS %uu /* float state[]: %s, _step */\n", p,
            tf_stateful_words(m), fl->reset);
    tick_macros(f, m, p, fl->step);
}
