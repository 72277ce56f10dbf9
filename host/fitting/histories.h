/*
 * histories.h — force histories sampled at a tick and the output points'
 * displacements along them: what the prony family (families/prony.c) fits
 * its time constants to and is judged on (docs/fitting.md §7).
 *
 * A set holds n histories of n_ticks ticks each: the force of every tick
 * (rounded to float, the input the firmware gets) and the displacements of
 * the output points after it (3 n_out per tick).  Training histories and
 * held-out ones are separate sets; the held-out ones are press-hold-release
 * histories of other directions, levels and durations than any training
 * history.
 *
 * Sources:
 *   tf_histories_solve         a time-dependent solver's history
 *                              (tf_solver_history, solvers/solver.h);
 *   tf_histories_linear_creep  a linear viscoelastic body with a constant
 *                              Poisson ratio: the relaxed static response
 *                              (the cases' unit responses) of the force
 *                              filtered by a creep function, exact by the
 *                              correspondence principle.  The force is
 *                              smooth between ticks (cosine ramps) and the
 *                              creep is integrated in continuous time
 *                              (TF_HIST_SUBSTEPS exact exponential substeps
 *                              per tick), so it is not the device's
 *                              first-order hold at the tick.
 */
#ifndef TF_FIT_HISTORIES_H
#define TF_FIT_HISTORIES_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "fitting/cases.h"

#define TF_HIST_SUBSTEPS 64
#define TF_CREEP_MAX_TERMS 8

/* A normalised creep function J(t)/J(inf) = 1 - sum_k w_k exp(-t / tau_k). */
typedef struct tf_creep {
    int n;
    double tau[TF_CREEP_MAX_TERMS]; /* s */
    double w[TF_CREEP_MAX_TERMS];   /* >= 0, sum <= 1 */
} tf_creep;

/* Seed 001's Kelvin solid (materials/material.h: relaxation modulus
 * E(t) = k1 + k2 exp(-t/tau), tau = eta/k2) as a creep function: one term,
 * w = k2 / (k1 + k2), retardation time tau (k1 + k2) / k1 (docs/solver.md,
 * "Seed 001's Kelvin law"). */
tf_creep tf_creep_kelvin(double k1, double k2, double eta);

typedef struct tf_history_set {
    size_t n, n_ticks;
    uint32_t n_out;
    double (*force)[3]; /* n x n_ticks forces [N], history-major */
    double *u;          /* 3 n_out per tick, history-major [mm] */
} tf_history_set;

typedef struct tf_histories {
    double tick;         /* s */
    uint32_t tick_ns;    /* the same, in ns (the model's dims[3]) */
    tf_history_set train, heldout;
} tf_histories;

/* Force of history h at tick n, and its displacements. */
static inline const double *tf_history_force(const tf_history_set *s, size_t h, size_t n)
{
    return s->force[h * s->n_ticks + n];
}

static inline const double *tf_history_u(const tf_history_set *s, size_t h, size_t n)
{
    return s->u + (h * s->n_ticks + n) * 3 * (size_t)s->n_out;
}

/* The force design: n_train training histories (presses along random
 * directions to random levels, held and released, with random ramp and
 * hold times, some with a second press on top) and n_heldout held-out
 * press-hold-release histories (other seeds: directions, levels and
 * durations the fit never saw), each n_ticks long, inside the envelope of
 * the cases (centre, radius).  The force between ticks is a cosine ramp:
 * tf_histories_force_at gives it at any time.  Returns 0, or -1 when out
 * of memory. */
typedef struct tf_history_design tf_history_design;

/* Which design: presses for creep (above), or dynamic histories for a body
 * with inertia (strikes, press-release, ramps, smooth random forces up to
 * TF_HIST_DYNAMIC_LEVEL of the radius; histories.c, docs/fitting.md §8). */
typedef enum tf_history_kind { TF_HIST_PRESS = 0, TF_HIST_DYNAMIC = 1 } tf_history_kind;
#define TF_HIST_DYNAMIC_LEVEL 0.5
tf_history_design *tf_history_design_kind(const tf_fitdata *d, tf_history_kind kind,
                                          size_t n_train, size_t n_heldout, size_t n_ticks,
                                          double tick, uint64_t seed);
tf_history_design *tf_history_design_new(const tf_fitdata *d, size_t n_train, size_t n_heldout,
                                         size_t n_ticks, double tick, uint64_t seed);
void tf_history_design_free(tf_history_design *hd);
/* Force of history h (training ones first, then held-out) at time t [s]. */
void tf_history_design_force(const tf_history_design *hd, size_t h, double t, double f[3]);

/* The histories of a linear viscoelastic body whose relaxed static response
 * the (affine) cases hold: u(t) = base + sum_k unit_k y_k(t), y = the force
 * filtered by the creep function in continuous time.  tick_ns: the tick in
 * ns.  Returns 0, or -1 with a message (cases not affine, no memory). */
int tf_histories_linear_creep(tf_ctx *ctx, const tf_cases *c, const tf_creep *creep,
                              uint32_t tick_ns, size_t n_train, size_t n_heldout, size_t n_ticks,
                              uint64_t seed, tf_histories *h);

/* A linear body with damped modes (the resonant family's test substrate):
 * the dynamic design, the force held over each tick, each force axis's
 * response y_a = f_a + sum_k w_ka (x_ka - f_a) with x_k the unit-gain
 * oscillator (omega_k, zeta_k) stepped exactly, then u = base + sum_a
 * unit_a y_a (an affine solver's unit responses). */
#define TF_RESONANT_TRUTH_MAX 8
typedef struct tf_resonant_truth {
    int n;
    double omega[TF_RESONANT_TRUTH_MAX], zeta[TF_RESONANT_TRUTH_MAX];
    double w[TF_RESONANT_TRUTH_MAX][3];
} tf_resonant_truth;
int tf_histories_linear_modes(tf_ctx *ctx, const tf_cases *c, const tf_resonant_truth *truth,
                              uint32_t tick_ns, size_t n_train, size_t n_heldout, size_t n_ticks,
                              uint64_t seed, tf_histories *h);

/* A design (kind: press-hold-release or dynamic) solved by a
 * time-dependent solver (tf_solver_history) with a time step of
 * solve_every ticks.  solve_every = 1: the force
 * sampled at every tick, each tick a solver step.  solve_every = m > 1:
 * the design sampled every m ticks, the force linear in between (so the
 * ticks' forces are piecewise linear, not the design's cosine ramps), and
 * the displacements of the ticks between two solver steps interpolated
 * linearly: m times fewer solves, at an error the caller must measure
 * (docs/fitting.md §7.6: block48_ve's).  Returns 0, or -1 with the message
 * in the solver's context. */
int tf_histories_solve(const tf_cases *c, tf_history_kind kind, uint32_t tick_ns,
                       size_t solve_every, size_t n_train, size_t n_heldout, size_t n_ticks,
                       uint64_t seed, tf_histories *h);

/* The output rows (3 per output node, per tick) of n_ticks ticks from a
 * solver's history `full` (dofs per step) with a step every m ticks: at a
 * step its displacements, between two steps the line between them. */
void tf_histories_outputs(const tf_outputs *o, const double *full, size_t dofs, size_t n_ticks,
                          size_t m, double *u);

void tf_histories_free(tf_histories *h);

#endif /* TF_FIT_HISTORIES_H */
