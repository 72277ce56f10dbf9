/*
 * plan.h — how a fit samples and searches (docs/fitting.md): the scene's
 * fit: section, with the command line's choices on top.
 */
#ifndef TF_FIT_PLAN_H
#define TF_FIT_PLAN_H

#include <stddef.h>
#include <stdint.h>

typedef struct tf_family tf_family; /* fitting/families/family.h */
typedef struct tf_case_runner tf_case_runner; /* fitting/case_runner.h */

typedef struct tf_fit_plan {
    const tf_family *family; /* forward family to emit (the registry's) */
    int family_asked;     /* 1: named by fit.family or --family (else the default) */
    int contact;          /* contact site index (-1 when the problem has none) */
    size_t n_train, n_heldout;
    uint64_t seed;        /* load-case design and folds */
    unsigned folds;       /* k of the k-fold cross-validation */
    uint32_t max_degree;  /* degrees searched (nodal, modal, contact): 0 (1) .. max */
    uint32_t max_rank;    /* ranks searched (modal): 1 .. max */
    int direct;           /* solve every training case even when the solver is affine */
    unsigned servo_hz;    /* the haptic loop's rate the header states its budget at (0: none) */
    /* Force histories, for a time-dependent solver (histories.h): the tick
     * (the prony model's), how many training and held-out histories, and
     * their length in ticks; the solver's time step in ticks (1: every
     * tick solved; m > 1: the force is linear between solver steps and the
     * ticks between them are interpolated, histories.h). */
    uint32_t tick_ns;
    size_t hist_train, hist_heldout, hist_ticks, hist_solve_every;
    /* Cut progress (cut_progress.h, the cut family): 0, or the largest
     * number of intervals K_max in s (a power of two; the knots s = i / K_max
     * are solved) and how many held-out s values. */
    uint32_t cut_intervals;
    size_t cut_heldout;
    /* where the cases of a solver that is not affine are solved: NULL here,
     * or spread over ranks (dist/); the bits are the same */
    const tf_case_runner *runner;
} tf_fit_plan;

/* tf_fit_plan_defaults() is declared by fitting/families/family.h: the
 * default plan names the registry's nodal family, and the registry sits
 * above this header (family.h includes it). */

#endif /* TF_FIT_PLAN_H */
