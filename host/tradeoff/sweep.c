/*
 * sweep.c — see sweep.h.  Candidates per output set: every registered
 * family that applies gives its candidates (family.h; today nodal p = 0 ..
 * max_degree, modal p = 1 .. max_degree and r = 1 .. max_rank, zhou2017 at its
 * cross-validated orders, the contact inverse p = 1 .. max_degree), each in
 * float32 and, where the family has them, its Q31 and float64 forms.  An
 * inverse family does not depend on the output set and is swept once, with
 * the scene's outputs.  float64 is the same fit evaluated with double
 * coefficients and arithmetic: what the fit achieves before float32
 * rounding.  There is no float64 target evaluator, so it has no time.
 */
#include "tradeoff/sweep.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "base/log.h"
#include "fitting/cases.h"
#include "fitting/families/family.h"
#include "model/passivity.h"
#include "model/q31.h"
#include "model/target_view.h"

#define TIMING_REPEATS 15

const char *tf_precision_name(tf_precision p)
{
    return p == TF_PREC_F32 ? "float32" : (p == TF_PREC_F64 ? "float64" : "Q31");
}

const char *tf_output_set_name(tf_output_set s)
{
    return s == TF_SET_SCENE ? "scene" : (s == TF_SET_CONTACT ? "contact only" : "all nodes");
}

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return 1e9 * (double)ts.tv_sec + (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Median over repeats of the time per call; inputs cycle through the
 * held-out cases.  Batches are sized to about 0.2 ms. */
typedef struct timing_job {
    const tfit_model *f32;
    const tfit_model_q31 *q31;
    float (*in)[3];
    int32_t (*qin)[3];
    size_t n_in;
    void *out;
    int inverse; /* the target's contact-force entry point, else displacements */
} timing_job;

static void call(const timing_job *j, size_t i)
{
    size_t k = i % j->n_in;
    if (j->f32 != NULL) {
        if (j->inverse) {
            tfit_contact_force(j->f32, j->in[k], j->out);
        } else {
            tfit_displacements(j->f32, j->in[k], j->out);
        }
    } else if (j->inverse) {
        tfit_contact_force_q31(j->q31, j->qin[k], j->out);
    } else {
        tfit_displacements_q31(j->q31, j->qin[k], j->out);
    }
}

static double time_calls(const timing_job *j)
{
    size_t batch = 1;
    for (;;) { /* size the batch */
        double t0 = now_ns();
        for (size_t i = 0; i < batch; ++i) {
            call(j, i);
        }
        if (now_ns() - t0 > 2e5 || batch > (1u << 24)) {
            break;
        }
        batch *= 2;
    }
    double per_call[TIMING_REPEATS];
    for (int r = 0; r < TIMING_REPEATS; ++r) {
        double t0 = now_ns();
        for (size_t i = 0; i < batch; ++i) {
            call(j, i);
        }
        per_call[r] = (now_ns() - t0) / (double)batch;
    }
    qsort(per_call, TIMING_REPEATS, sizeof per_call[0], cmp_double);
    return per_call[TIMING_REPEATS / 2];
}

static int grow(tf_sweep *sw)
{
    if (sw->n < sw->cap) {
        return 0;
    }
    size_t cap = sw->cap ? 2 * sw->cap : 64;
    tf_candidate *c = realloc(sw->c, cap * sizeof *c);
    if (c == NULL) {
        return -1;
    }
    sw->c = c;
    sw->cap = cap;
    return 0;
}

/* Inputs of the held-out cases as the firmware gets them. */
static const double *case_input(const tf_fitdata *d, int contact, size_t i)
{
    return contact ? d->contact[i] : d->force[i];
}

static int is_inverse(const tf_model *m)
{
    return tf_family_of(m->family)->kind == TF_FAMILY_INVERSE;
}

/* The largest |component| of the held-out truths m renders: displacements
 * (mm) for a forward model, forces (N) for a contact inverse. */
static double heldout_peak(const tf_model *m, const tf_fitdata *held)
{
    const int contact = tf_family_of(m->family)->kind == TF_FAMILY_INVERSE;
    const size_t rows = contact ? 3 : 3 * (size_t)held->n_out;
    double peak = 0;
    for (size_t i = 0; i < held->n_cases; ++i) {
        const double *truth = contact ? held->force[i] : held->u + rows * i;
        for (size_t o = 0; o < rows; ++o) {
            peak = fmax(peak, fabs(truth[o]));
        }
    }
    return peak;
}

static void fill_common(tf_candidate *c, const tf_model *m, const char *label, tf_precision prec,
                        tf_output_set set)
{
    memset(c, 0, sizeof *c);
    snprintf(c->label, sizeof c->label, "%s", label);
    c->family = tf_family_of(m->family);
    c->precision = prec;
    c->set = set;
    c->n_out = m->n_out;
    c->us_m4f = c->us_m4f_low = c->us_m7 = c->ns_native = NAN;
}

static int add_f32(tf_ctx *ctx, tf_sweep *sw, tf_model *m, const char *label, tf_output_set set,
                   const tf_fitdata *held)
{
    if (grow(sw) != 0) {
        return -1;
    }
    tf_candidate *c = &sw->c[sw->n++];
    fill_common(c, m, label, TF_PREC_F32, set);
    c->peak = heldout_peak(m, held);
    c->model = m;
    c->n_coef = m->n_coef;
    tf_family_cost cost;
    c->family->cost(m, &cost);
    c->table_bytes = cost.table_bytes;
    c->ops = cost.ops.add + cost.ops.mul + cost.ops.div;
    c->us_m4f = cost.m4f.cycles / tf_core_mhz(TF_CORE_M4F);
    c->us_m4f_low = cost.m4f.cycles_low / tf_core_mhz(TF_CORE_M4F);
    c->us_m7 = cost.m7.cycles / tf_core_mhz(TF_CORE_M7);
    tf_family_errors(m, held, NULL, held->n_cases, &c->heldout_max, &c->heldout_rms,
                     &m->heldout_rel_max);
    m->heldout_max = c->heldout_max; /* the header reports them if it is chosen */
    m->heldout_rms = c->heldout_rms;
    m->heldout_cases = (uint32_t)held->n_cases;

    const int contact = is_inverse(m);
    const int passivity = contact ? tf_passivity_require(ctx, m) : 0;
    if (passivity < 0) {
        return -1;
    }
    c->passive = passivity == 0; /* a non-passive law stays in the sweep, never selected */
    tfit_model view;
    tf_target_view(m, &view);
    timing_job j = {.f32 = &view, .n_in = held->n_cases, .inverse = contact};
    j.in = malloc(held->n_cases * sizeof *j.in);
    j.out = malloc(3 * m->n_out * sizeof(float));
    if (j.in == NULL || j.out == NULL) {
        free(j.in);
        free(j.out);
        return -1;
    }
    for (size_t i = 0; i < held->n_cases; ++i) {
        for (int k = 0; k < 3; ++k) {
            j.in[i][k] = (float)case_input(held, contact, i)[k];
        }
    }
    c->ns_native = time_calls(&j);
    free(j.in);
    free(j.out);
    return 0;
}

/* The Q31 form of a float32 candidate (families that have one). */
static int add_q31(tf_ctx *ctx, tf_sweep *sw, const tf_model *m, const char *label,
                   tf_output_set set, const tf_fitdata *held)
{
    tf_q31 *q = tf_family_of(m->family)->q31(ctx, m);
    if (q == NULL) {
        return 0; /* no Q31 form: not a candidate */
    }
    if (grow(sw) != 0) {
        tf_q31_free(q);
        return -1;
    }
    tf_candidate *c = &sw->c[sw->n++];
    fill_common(c, m, label, TF_PREC_Q31, set);
    c->peak = heldout_peak(m, held);
    c->n_coef = q->n_words;
    c->table_bytes = 4 * (q->n_words + m->n_out);
    const int contact = is_inverse(m);
    const size_t rows = 3 * (size_t)m->n_out;
    int32_t *out = malloc(rows * sizeof *out);
    int32_t(*qin)[3] = malloc(held->n_cases * sizeof *qin);
    if (out == NULL || qin == NULL) {
        free(out);
        free(qin);
        tf_q31_free(q);
        return -1;
    }
    double emax = 0, sum2 = 0;
    for (size_t i = 0; i < held->n_cases; ++i) {
        for (int k = 0; k < 3; ++k) {
            qin[i][k] = tf_q31_from_value(case_input(held, contact, i)[k], q->in_exp);
        }
        tf_q31_ref_eval(q, qin[i], out, NULL);
        const double *truth = contact ? held->force[i] : held->u + rows * i;
        for (size_t o = 0; o < rows; ++o) {
            double e = tf_q31_to_value(out[o], q->out_exp) - truth[o];
            emax = fmax(emax, fabs(e));
            sum2 += e * e;
        }
    }
    c->heldout_max = emax;
    c->heldout_rms = sqrt(sum2 / ((double)held->n_cases * (double)rows));
    tfit_model_q31 view;
    tf_target_view_q31(q, &view);
    timing_job j = {.q31 = &view, .qin = qin, .n_in = held->n_cases, .out = out,
                    .inverse = contact};
    c->ns_native = time_calls(&j);
    free(out);
    free(qin);
    tf_q31_free(q);
    return 0;
}

/* The float64 form of a float32 candidate (families that have one). */
static int add_f64(tf_ctx *ctx, tf_sweep *sw, const tf_model *m, const char *label,
                   tf_output_set set, const tf_cases *cases)
{
    if (grow(sw) != 0) {
        return tf_fail(ctx, "out of memory for the candidates");
    }
    tf_candidate *c = &sw->c[sw->n];
    fill_common(c, m, label, TF_PREC_F64, set);
    c->peak = heldout_peak(m, &cases->heldout);
    c->n_coef = m->n_coef;
    c->table_bytes = 8 * m->n_coef + 4 * (m->n_dims + m->n_out);
    if (c->family->f64_errors(ctx, m, cases, &c->heldout_max, &c->heldout_rms) != 0) {
        return -1;
    }
    ++sw->n;
    return 0;
}

/* A float32 candidate fitted on every training case, with its Q31 and
 * float64 forms where its family has them.  Takes ownership of m. */
typedef struct measure_job {
    tf_sweep *sw;
    tf_output_set set;
    const tf_cases *cases;
    tf_ctx *ctx;
} measure_job;

static int measure(void *arg, tf_model *m)
{
    const measure_job *j = arg;
    const tf_family *f = tf_family_of(m->family);
    char label[96], orders[64];
    f->orders_text(m, TF_ORDERS_SHORT, orders, sizeof orders);
    snprintf(label, sizeof label, "%s %s", f->name, orders);
    int rc = 0;
    if (f->q31 != NULL && add_q31(j->ctx, j->sw, m, label, j->set, &j->cases->heldout) != 0) {
        tf_fail(j->ctx, "out of memory for the candidates");
        rc = -1;
    }
    if (rc == 0 && f->f64_errors != NULL &&
        add_f64(j->ctx, j->sw, m, label, j->set, j->cases) != 0) {
        rc = -1;
    }
    if (rc == 0 && add_f32(j->ctx, j->sw, m, label, j->set, &j->cases->heldout) != 0) {
        tf_fail(j->ctx, "out of memory for the candidates");
        rc = -1;
    }
    if (rc != 0) {
        tf_model_free(m);
    }
    return rc;
}

/* The problem with another output selection (a shallow copy: the solver
 * does not read the outputs). */
static int outputs_of(const tf_problem *s, const tf_solver *solver, tf_output_set set,
                      int contact, tf_problem *copy, uint32_t **nodes)
{
    *copy = *s;
    *nodes = NULL;
    if (set == TF_SET_SCENE) {
        return 0;
    }
    /* an organ's "every node" is every surface vertex: the renderer has no other */
    size_t n = set == TF_SET_CONTACT      ? 1
               : s->cloud.n_surface > 0 ? s->cloud.n_surface
                                        : tf_solver_node_count(solver);
    *nodes = malloc(n * sizeof **nodes);
    if (*nodes == NULL) {
        return -1;
    }
    for (size_t i = 0; i < n; ++i) {
        (*nodes)[i] = set == TF_SET_CONTACT ? s->contacts[contact].node : (uint32_t)i;
    }
    copy->outputs = (tf_outputs){.kind = set == TF_SET_CONTACT ? TF_OUT_CONTACT : TF_OUT_ALL,
                                 .nodes = *nodes, .n_nodes = n};
    return 0;
}

static int sweep_set(tf_ctx *ctx, tf_sweep *sw, const tf_problem *s, tf_solver *solver,
                     const tf_fit_plan *plan, tf_output_set set)
{
    tf_problem copy;
    uint32_t *nodes;
    tf_cases cases;
    if (outputs_of(s, solver, set, plan->contact, &copy, &nodes) != 0) {
        return tf_fail(ctx, "out of memory for the output set");
    }
    tf_fit_plan superposed = *plan;
    superposed.direct = 0;
    if (tf_cases_build(&copy, solver, &superposed, &cases) != 0) {
        free(nodes);
        if (ctx != solver->ctx) { /* the solves report in the solver's context */
            tf_fail(ctx, "%s", solver->ctx->err);
        }
        return -1;
    }
    measure_job job = {.sw = sw, .set = set, .cases = &cases, .ctx = ctx};
    int rc = 0;
    tf_info(ctx, "sweep: %s (%u output points)", tf_output_set_name(set), cases.train.n_out);
    for (size_t i = 0; rc == 0 && i < tf_family_count(); ++i) {
        const tf_family *f = tf_family_at(i);
        if ((f->kind == TF_FAMILY_INVERSE && set != TF_SET_SCENE) ||
            f->applicable(ctx, &cases, plan) != 0) { /* the reason, in ctx->err, is not a failure */
            continue;
        }
        rc = f->candidates(ctx, &cases, plan, measure, &job);
    }
    tf_cases_free(&cases);
    free(nodes);
    return rc;
}

/* On the front: no other candidate of the same set and kind is at least as
 * fast and as accurate, and better in one.  A candidate off by its peak or
 * more renders nothing better than zero: it is never on the front (and does
 * not push others off it). */
static int renders(const tf_candidate *c)
{
    return isfinite(c->ns_native) && c->heldout_max < c->peak;
}

static void mark_pareto(tf_sweep *sw)
{
    for (size_t i = 0; i < sw->n; ++i) {
        tf_candidate *a = &sw->c[i];
        a->pareto = renders(a);
        for (size_t k = 0; a->pareto && k < sw->n; ++k) {
            const tf_candidate *b = &sw->c[k];
            int same_kind = a->family->kind == b->family->kind;
            if (k == i || b->set != a->set || !same_kind || !renders(b)) {
                continue;
            }
            if (b->ns_native <= a->ns_native && b->heldout_max <= a->heldout_max &&
                (b->ns_native < a->ns_native || b->heldout_max < a->heldout_max)) {
                a->pareto = 0;
            }
        }
    }
}

int tf_sweep_run(tf_ctx *ctx, const tf_problem *s, tf_solver *solver, const tf_fit_plan *plan,
                 unsigned sets, tf_sweep *sw)
{
    memset(sw, 0, sizeof *sw);
    sw->n_train = plan->n_train;
    sw->n_heldout = plan->n_heldout;
    for (int set = 0; set < TF_SET_COUNT; ++set) {
        if ((sets & (1u << set)) && sweep_set(ctx, sw, s, solver, plan, (tf_output_set)set) != 0) {
            tf_sweep_free(sw);
            return -1;
        }
    }
    mark_pareto(sw);
    return 0;
}

void tf_sweep_free(tf_sweep *sw)
{
    for (size_t i = 0; i < sw->n; ++i) {
        if (sw->c[i].precision == TF_PREC_F32) {
            tf_model_free(sw->c[i].model);
        }
    }
    free(sw->c);
    memset(sw, 0, sizeof *sw);
}
