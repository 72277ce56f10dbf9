/*
 * family.h — the model families of GUIDE §3 as a registry (registry.c).
 *
 * A family is a way of fitting solved load cases (fitting/cases.h) with a
 * model the target evaluates (tfit.h's family id, model/model.h's layout).
 * Each family is one file in this folder that fills a tf_family; the fit
 * pipeline, the sweep and the header emitter iterate the registry and call
 * these operations, and never switch on a family.  A forward family maps
 * the contact force [N] to the output points' displacements [mm]; an
 * inverse one maps the contact site's displacement [mm] to the contact
 * force [N] (the haptic impedance).  The two families of a contact region
 * (region.c: the law, tool-tip position -> force, an inverse family;
 * region_surface.c: force -> the outputs' displacements, a forward one) are
 * fitted together from the region's site solves (`region` below).
 *
 * Orders are the model's dims (model.h): nodal and contact {p}, modal
 * {p, r}, zhou2017 its 30 orders.  Messages of fits that the cases cannot
 * determine begin with TF_FAMILY_UNDETERMINED (common.h), so that
 * cross-validation can tell "this order is not supported" from a failure.
 */
#ifndef TF_FAMILY_H
#define TF_FAMILY_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "cost/cycles.h"
#include "fitting/cases.h"
#include "fitting/plan.h"
#include "model/model.h"
#include "model/q31.h"

#define TF_FAMILY_MAX_RANK 24 /* ranks a family with a rank (modal) searches and tabulates */

typedef struct tf_family tf_family;

typedef enum tf_family_kind {
    TF_FAMILY_FORWARD, /* contact force -> displacements of the output points */
    TF_FAMILY_INVERSE, /* contact-site displacement -> contact force */
} tf_family_kind;

/* One family fitted by the pipeline (pipeline.h): its order search, the
 * model on every training case and what the pipeline measured of it. */
typedef struct tf_family_result {
    const tf_family *family;
    int applicable;
    char why[320];                  /* when not applicable */
    tf_model *model;                /* fitted on every training case */
    double cv[TFIT_MAX_DEGREE + 1]; /* CV RMS by degree (INFINITY: not tried) */
    /* Families with a rank (modal), at the chosen degree: CV RMS and
     * held-out max error by rank (INFINITY: not tried). */
    double cv_rank[TF_FAMILY_MAX_RANK + 1];
    double heldout_rank[TF_FAMILY_MAX_RANK + 1];
    double heldout_max, heldout_rms, heldout_rel_max;
    double seconds; /* order selection and fit */
    /* Forward families: force s e_a at the seed's levels s = 0.2 .. 1.0 of
     * the envelope radius.  table3[a][c]: RMS over points and levels of
     * error_c / s (mm/N, seed Table 3); deviation: the mean error over the
     * levels at each point (mm, seed Figs 5-13), 3 x 3 x n_out. */
    double table3[3][3];
    double *deviation;
} tf_family_result;

/* The cost of one evaluation on the target. */
typedef struct tf_family_cost {
    tf_opcount ops;
    uint32_t table_bytes;
    tf_cycles m4f, m7;
} tf_family_cost;

/* A sweep's consumer of candidate models: takes ownership of m; returns 0
 * to go on, non-zero to stop (with a message of its own). */
typedef int (*tf_family_take)(void *arg, tf_model *m);

/* Orders as text: TF_ORDERS_FULL for the header (ASCII, every order),
 * TF_ORDERS_SHORT for tables and labels. */
enum { TF_ORDERS_FULL, TF_ORDERS_SHORT };

struct tf_family {
    tfit_family id;   /* the target's family of its models (tfit.h) */
    const char *name; /* scene key fit.family, --family, the header's FAMILY */
    tf_family_kind kind;
    /* 0 when the family can describe the cases; else -1 with the reason
     * in ctx->err (not a failure: the family is skipped). */
    int (*applicable)(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan);
    /* Order search: the orders by cross-validation on c->train within the
     * plan's limits, then the model on every training case, into r (model,
     * cv curves).  Returns 0, or -1 with a message. */
    int (*select)(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan, tf_family_result *r);
    /* The model of the given orders on training cases idx[0..m) (idx NULL:
     * all of c->train).  NULL with a message. */
    tf_model *(*fit)(tf_ctx *ctx, const tf_cases *c, const size_t *idx, size_t m,
                     const uint32_t *orders);
    /* The sweep's candidates (tradeoff/sweep.h): every order the plan
     * allows, each fitted on every training case and given to take.
     * Returns 0, or -1 with a message (or take's non-zero). */
    int (*candidates)(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan, tf_family_take take,
                      void *arg);
    void (*orders_text)(const tf_model *m, int style, char *buf, size_t n);
    /* The Q31 form of a model (model/q31.h), or NULL when the family has none. */
    tf_q31 *(*q31)(tf_ctx *ctx, const tf_model *m);
    /* Held-out errors of the same fit with coefficients and arithmetic in
     * double (what the fit achieves before float32 rounding); NULL when the
     * family has no such form.  Returns 0, or -1 with a message. */
    int (*f64_errors)(tf_ctx *ctx, const tf_model *m, const tf_cases *c, double *max, double *rms);
    /* Operations, table bytes and cycles of one evaluation. */
    void (*cost)(const tf_model *m, tf_family_cost *out);
    /* The held-out errors the family is judged on, when they are not the
     * static held-out cases' (NULL: tf_family_errors on c->heldout): the
     * largest and RMS error, the largest error relative to the largest
     * true value (NAN when not meaningful), and how many held-out cases
     * (or histories) behind them.  Returns 0, or -1 with a message when out
     * of memory. */
    int (*heldout)(tf_ctx *ctx, const tf_model *m, const tf_cases *c, double *max, double *rms,
                   double *rel_max, uint32_t *n);
    /* The model's name in a header after its base: "NAME_" suffix (NULL:
     * "forward" for a forward family, "contact" for an inverse one). */
    const char *suffix;
    /* The families fitted from a contact region (contact.K.region) rather
     * than from one contact site's load cases (NULL for those): the models
     * of region plan->contact of p with solver s, one per family of the
     * region (the law and the surface), into models[0 .. *n) (at most
     * TF_FAMILY_REGION_MODELS, owned by the caller).  Such a family is never
     * applicable to load cases.  Returns 0, or -1 with the message (-2: a
     * region this family cannot fit, a problem the user must change). */
    int (*region)(tf_ctx *ctx, tf_solver *s, const tf_problem *p, const tf_fit_plan *plan,
                  tf_model **models, size_t *n);
};

#define TF_FAMILY_REGION_MODELS 2

/* ---- the registry (registry.c) ------------------------------------------- */

size_t tf_family_count(void);
const tf_family *tf_family_at(size_t i);
/* The family registered under name, or NULL. */
const tf_family *tf_family_find(const char *name);
/* The family whose models carry this id, or NULL. */
const tf_family *tf_family_of(tfit_family id);
/* "nodal, modal, zhou2017": the names of every family of a kind. */
void tf_family_names(tf_family_kind kind, char *out, size_t outlen);
/* The suffix of a family's models' names in a header ("forward", "law"). */
const char *tf_family_suffix(const tf_family *f);
/* The plan's forward family for its contact (plan->contact of p): a
 * contact region's models come from the forward family fitted from a
 * region (the registry's first), a site's from any other.  A family the
 * plan did not ask for (family_asked 0) follows the contact; one asked
 * for that does not fit the contact is refused (a region is never fitted
 * as a point).  Returns 0, or -1 with the message. */
int tf_fit_plan_family_for_contact(tf_ctx *ctx, tf_fit_plan *plan, const tf_problem *p);

/* ---- shared by the pipeline, the sweep and the families (model_errors.c) */

/* Errors of a model on cases idx[0..m) (all when NULL), evaluated exactly
 * as the target does (reference evaluator, float32 input): forward models
 * against d->u in mm; inverse models against d->force in N (rel_max: the
 * largest |error| / |force|, NAN for forward models).  Any output may be
 * NULL. */
void tf_family_errors(const tf_model *model, const tf_fitdata *d, const size_t *idx, size_t m,
                      double *max, double *rms, double *rel_max);

/* k-fold cross-validated RMS error of family f at the given orders on
 * c->train (and the largest validation error in *max when not NULL):
 * infinite when the folds' cases cannot determine the order.  Returns -1
 * with a message when a fold fails otherwise. */
int tf_family_cv_error(tf_ctx *ctx, const tf_family *f, const tf_cases *c, const uint32_t *orders,
                       unsigned folds, uint64_t seed, double *rms, double *max);

/* The default fit plan (plan.h): nodal, contact site 0, 100 training and
 * 50 held-out cases, seed 20170912, 5 folds, degrees to 4, ranks to 12,
 * superposed when the solver allows; for a time-dependent solver 12
 * training and 6 held-out histories of 5000 ticks of 1 ms.  Here rather
 * than beside plan.h because it names a family of the registry (registry.c). */
void tf_fit_plan_defaults(tf_fit_plan *p);

#endif /* TF_FAMILY_H */
