/*
 * sweep.h — the speed-for-accuracy trade of a problem (docs/tradeoff.md):
 * every candidate model — family, orders or rank, precision, output set —
 * fitted to the same load cases and measured the same way: coefficients,
 * table bytes, operations, estimated Cortex-M4F/M7 time, measured native
 * time of the real evaluator, held-out error against true solves.
 */
#ifndef TF_SWEEP_H
#define TF_SWEEP_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "fitting/families/family.h"
#include "fitting/plan.h"
#include "model/model.h"
#include "problem/problem.h"
#include "solvers/solver.h"

typedef enum tf_precision { TF_PREC_F32, TF_PREC_F64, TF_PREC_Q31 } tf_precision;

/* Which output points a candidate reports. */
typedef enum tf_output_set {
    TF_SET_SCENE,   /* the problem's outputs (the scene's) */
    TF_SET_CONTACT, /* the contact site only */
    TF_SET_ALL,     /* every node */
    TF_SET_COUNT
} tf_output_set;

typedef struct tf_candidate {
    char label[96];           /* "nodal p=2", "modal p=1 r=4", ... */
    const tf_family *family;
    tf_precision precision;
    tf_output_set set;
    uint32_t n_out;
    uint32_t n_coef, table_bytes;
    uint64_t ops;
    double us_m4f, us_m4f_low, us_m7; /* estimates (float32 only; NAN otherwise) */
    double ns_native;                 /* median per call, real evaluator; NAN for float64 */
    double heldout_max, heldout_rms;  /* mm (forward models) or N (contact) */
    double peak;                      /* the held-out truths' largest |component|: the
                                       * displacement (mm) or force (N) the model renders */
    int pareto;                       /* on the error/time front of its set and kind,
                                       * among the candidates off by less than their peak */
    int passive;                      /* contact laws: passivity.h holds (forward: 1) */
    tf_model *model;                  /* float32 candidates: the model (owned) */
} tf_candidate;

typedef struct tf_sweep {
    tf_candidate *c;
    size_t n, cap;
    size_t n_train, n_heldout;
} tf_sweep;

/* Output sets to sweep: bit (1 << tf_output_set). */
#define TF_SWEEP_ALL_SETS ((1u << TF_SET_COUNT) - 1u)

/* Fits and measures every candidate of problem p with a solver of it.
 * Returns 0, or -1 with a message in ctx->err (usually the context the
 * solver was created with). */
int tf_sweep_run(tf_ctx *ctx, const tf_problem *p, tf_solver *solver, const tf_fit_plan *plan,
                 unsigned sets, tf_sweep *out);
void tf_sweep_free(tf_sweep *sw);

const char *tf_precision_name(tf_precision p);
const char *tf_output_set_name(tf_output_set s);

#endif /* TF_SWEEP_H */
