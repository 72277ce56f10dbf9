/*
 * histories.c — see histories.h.
 */
#include "fitting/histories.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/context.h"
#include "base/rng.h"
#include "model/oscillator.h"

#define MAX_RAMPS 8

/* One history: ramps from one force to the next (cosine in time), held
 * between them; before the first ramp the force is zero. */
typedef struct ramp {
    double t0, dur;
    double to[3];
} ramp;

typedef struct history {
    int n;
    ramp r[MAX_RAMPS];
} history;

struct tf_history_design {
    size_t n;
    history *h;
};

tf_creep tf_creep_kelvin(double k1, double k2, double eta)
{
    tf_creep c = {0, {0}, {0}};
    if (k2 > 0) {
        c.n = 1;
        c.w[0] = k2 / (k1 + k2);
        c.tau[0] = eta / k2 * (k1 + k2) / k1;
    }
    return c;
}

/* A force at level s of the radius in a random direction, around centre. */
static void random_force(tf_rng *r, const tf_fitdata *d, double s, double f[3])
{
    double u[3], n2;
    do {
        for (int i = 0; i < 3; ++i) {
            u[i] = tf_rng_range(r, -1, 1);
        }
        n2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    } while (n2 > 1 || n2 < 1e-4);
    for (int i = 0; i < 3; ++i) {
        f[i] = d->centre[i] + s * d->radius * u[i] / sqrt(n2);
    }
}

static void add_ramp(history *h, double t0, double dur, const double to[3])
{
    if (h->n < MAX_RAMPS) {
        ramp *r = &h->r[h->n++];
        r->t0 = t0;
        r->dur = dur;
        memcpy(r->to, to, sizeof r->to);
    }
}

/* Training: press to a random force (level 0.3..1 of the radius) over
 * 0.02..0.5 s, hold 0.2..0.45 of the history, sometimes a second press on
 * top, release to no force over 0.02..0.5 s, rest.  Held-out: press, hold and release
 * only, with levels, directions and times from another stream. */
static void design_one(tf_rng *r, const tf_fitdata *d, double duration, int heldout, history *h)
{
    double f[3];
    const double zero[3] = {0, 0, 0};
    h->n = 0;
    double t = tf_rng_range(r, 0, 0.05 * duration);
    double ramp_t = tf_rng_range(r, 0.02, 0.5);
    random_force(r, d, tf_rng_range(r, 0.3, 1.0), f);
    add_ramp(h, t, ramp_t, f);
    t += ramp_t + tf_rng_range(r, 0.2, 0.45) * duration;
    if (!heldout && tf_rng_below(r, 2) == 0) {
        ramp_t = tf_rng_range(r, 0.02, 0.3);
        random_force(r, d, tf_rng_range(r, 0.2, 1.0), f);
        add_ramp(h, t, ramp_t, f);
        t += ramp_t + tf_rng_range(r, 0.05, 0.2) * duration;
    }
    add_ramp(h, t, tf_rng_range(r, 0.02, 0.5), zero);
}

/* One strike: up to level s over 1..4 ticks and straight back down over
 * 1..4 ticks (a cosine pulse), starting at t. */
static double strike(tf_rng *r, const tf_fitdata *d, double s, double t, double tick, history *h)
{
    double f[3];
    const double zero[3] = {0, 0, 0};
    const double up = tick * tf_rng_range(r, 1, 4), down = tick * tf_rng_range(r, 1, 4);
    random_force(r, d, s, f);
    add_ramp(h, t, up, f);
    add_ramp(h, t + up, down, zero);
    return t + up + down;
}

/* Dynamic histories for a body with inertia (the resonant family), forces
 * at most TF_HIST_DYNAMIC_LEVEL of the radius so that the overshoot stays
 * inside the envelope the static map is fitted on.  Training histories
 * cycle through four kinds: a strike (a pulse of 2..8 ticks, then free
 * ringing; sometimes a second one later), a press and release (up over
 * 2..20 ticks, held, released over 1..10), a slow ramp up and down, and a
 * smooth random force (cosine ramps between random levels over 3..60
 * ticks).  Held-out histories alternate strikes and smooth random forces
 * from another stream (other levels, directions and times). */
static void design_dynamic(tf_rng *r, const tf_fitdata *d, double duration, double tick,
                           size_t i, int heldout, history *h)
{
    const double top = TF_HIST_DYNAMIC_LEVEL, zero[3] = {0, 0, 0};
    double f[3];
    h->n = 0;
    double t = tf_rng_range(r, 0.02, 0.1) * duration;
    switch (heldout ? (i % 2 == 0 ? 0 : 3) : i % 4) {
    case 0: /* strike */
        t = strike(r, d, tf_rng_range(r, 0.3, 1.0) * top, t, tick, h);
        if (tf_rng_below(r, 2) == 0) {
            strike(r, d, tf_rng_range(r, 0.3, 1.0) * top, t + tf_rng_range(r, 0.3, 0.5) * duration,
                   tick, h);
        }
        break;
    case 1: { /* press and release */
        const double up = tick * tf_rng_range(r, 2, 20);
        random_force(r, d, tf_rng_range(r, 0.3, 1.0) * top, f);
        add_ramp(h, t, up, f);
        t += up + tf_rng_range(r, 0.1, 0.4) * duration;
        add_ramp(h, t, tick * tf_rng_range(r, 1, 10), zero);
        break;
    }
    case 2: { /* slow ramp up, hold, slow ramp down */
        const double up = tf_rng_range(r, 0.1, 0.3) * duration;
        random_force(r, d, tf_rng_range(r, 0.3, 1.0) * top, f);
        add_ramp(h, t, up, f);
        t += up + tf_rng_range(r, 0.05, 0.2) * duration;
        add_ramp(h, t, tf_rng_range(r, 0.1, 0.3) * duration, zero);
        break;
    }
    default: /* smooth random: ramps between random levels, ends at rest */
        for (int j = 0; j < MAX_RAMPS - 1 && t < 0.8 * duration; ++j) {
            const double dur = tick * tf_rng_range(r, 3, 60);
            random_force(r, d, tf_rng_range(r, 0.1, 1.0) * top, f);
            add_ramp(h, t, dur, f);
            t += dur + tick * tf_rng_range(r, 0, 30);
        }
        add_ramp(h, t, tick * tf_rng_range(r, 3, 30), zero);
        break;
    }
}

tf_history_design *tf_history_design_new(const tf_fitdata *d, size_t n_train, size_t n_heldout,
                                         size_t n_ticks, double tick, uint64_t seed)
{
    return tf_history_design_kind(d, TF_HIST_PRESS, n_train, n_heldout, n_ticks, tick, seed);
}

tf_history_design *tf_history_design_kind(const tf_fitdata *d, tf_history_kind kind,
                                          size_t n_train, size_t n_heldout, size_t n_ticks,
                                          double tick, uint64_t seed)
{
    tf_history_design *hd = malloc(sizeof *hd);
    if (hd == NULL) {
        return NULL;
    }
    hd->n = n_train + n_heldout;
    hd->h = malloc(hd->n * sizeof *hd->h);
    if (hd->h == NULL) {
        free(hd);
        return NULL;
    }
    tf_rng train = {seed}, held = {seed ^ 0x5eedf00dull};
    const double duration = (double)n_ticks * tick;
    for (size_t i = 0; i < hd->n; ++i) {
        tf_rng *r = i < n_train ? &train : &held;
        if (kind == TF_HIST_DYNAMIC) {
            design_dynamic(r, d, duration, tick, i, i >= n_train, &hd->h[i]);
        } else {
            design_one(r, d, duration, i >= n_train, &hd->h[i]);
        }
    }
    return hd;
}

void tf_history_design_free(tf_history_design *hd)
{
    if (hd != NULL) {
        free(hd->h);
        free(hd);
    }
}

void tf_history_design_force(const tf_history_design *hd, size_t i, double t, double f[3])
{
    const history *h = &hd->h[i];
    double from[3] = {0, 0, 0}; /* at rest under no force until the first ramp */
    memcpy(f, from, sizeof from);
    for (int j = 0; j < h->n; ++j) {
        const ramp *r = &h->r[j];
        if (t <= r->t0) {
            return;
        }
        const double s = t >= r->t0 + r->dur ? 1.0 : 0.5 * (1 - cos(M_PI * (t - r->t0) / r->dur));
        for (int k = 0; k < 3; ++k) {
            f[k] = from[k] + s * (r->to[k] - from[k]);
            from[k] = r->to[k];
        }
    }
}

static int alloc_set(tf_history_set *s, size_t n, size_t n_ticks, uint32_t n_out)
{
    s->n = n;
    s->n_ticks = n_ticks;
    s->n_out = n_out;
    s->force = malloc(n * n_ticks * sizeof *s->force);
    s->u = malloc(n * n_ticks * 3 * (size_t)n_out * sizeof *s->u);
    return s->force != NULL && s->u != NULL ? 0 : -1;
}

/* The forces of every tick, rounded to float (the firmware's input). */
static void sample_forces(const tf_history_design *hd, size_t first, tf_history_set *s,
                          double tick)
{
    for (size_t h = 0; h < s->n; ++h) {
        for (size_t n = 0; n < s->n_ticks; ++n) {
            double f[3];
            tf_history_design_force(hd, first + h, (double)n * tick, f);
            for (int k = 0; k < 3; ++k) {
                s->force[h * s->n_ticks + n][k] = (double)(float)f[k];
            }
        }
    }
}

/* One history of a linear viscoelastic body: y = f - sum_j w_j e_j with
 * e_j = int exp(-(t - s)/tau_j) df(s), integrated over substeps on which f
 * is taken linear (the exact update there); u = base + sum_k unit_k y_k.
 * The force at the ticks is the float one stored in s (the substeps in
 * between follow the design's continuous force). */
static void creep_one(const tf_cases *c, const tf_creep *cr, const tf_history_design *hd,
                      size_t which, tf_history_set *s, size_t h, double tick)
{
    const size_t rows = 3 * (size_t)s->n_out;
    const double dt = tick / TF_HIST_SUBSTEPS;
    double e[TF_CREEP_MAX_TERMS][3] = {{0}}, a[TF_CREEP_MAX_TERMS], dgain[TF_CREEP_MAX_TERMS];
    for (int j = 0; j < cr->n; ++j) {
        const double r = dt / cr->tau[j];
        a[j] = exp(-r);
        dgain[j] = -expm1(-r) / r;
    }
    double f_prev[3] = {0, 0, 0};
    for (size_t n = 0; n < s->n_ticks; ++n) {
        const double *fn = tf_history_force(s, h, n);
        for (int sub = 1; sub <= TF_HIST_SUBSTEPS && n > 0; ++sub) {
            double f[3];
            if (sub == TF_HIST_SUBSTEPS) {
                memcpy(f, fn, sizeof f);
            } else {
                tf_history_design_force(hd, which, ((double)(n - 1) + (double)sub / TF_HIST_SUBSTEPS) * tick, f);
            }
            for (int j = 0; j < cr->n; ++j) {
                for (int k = 0; k < 3; ++k) {
                    e[j][k] = a[j] * e[j][k] + dgain[j] * (f[k] - f_prev[k]);
                }
            }
            memcpy(f_prev, f, sizeof f);
        }
        if (n == 0) { /* the force at t = 0 is applied from rest: an instantaneous step */
            for (int j = 0; j < cr->n; ++j) {
                for (int k = 0; k < 3; ++k) {
                    e[j][k] = fn[k];
                }
            }
            memcpy(f_prev, fn, sizeof f_prev);
        }
        double y[3];
        for (int k = 0; k < 3; ++k) {
            y[k] = fn[k];
            for (int j = 0; j < cr->n; ++j) {
                y[k] -= cr->w[j] * e[j][k];
            }
        }
        double *u = s->u + (h * s->n_ticks + n) * rows;
        for (size_t o = 0; o < rows; ++o) {
            u[o] = c->base[o] + y[0] * c->unit[0][o] + y[1] * c->unit[1][o] + y[2] * c->unit[2][o];
        }
    }
}

static int start(tf_histories *h, const tf_cases *c, tf_history_kind kind, uint32_t tick_ns,
                 size_t n_train, size_t n_heldout, size_t n_ticks, uint64_t seed,
                 tf_history_design **hd)
{
    memset(h, 0, sizeof *h);
    h->tick_ns = tick_ns;
    h->tick = 1e-9 * tick_ns;
    *hd = tf_history_design_kind(&c->train, kind, n_train, n_heldout, n_ticks, h->tick, seed);
    if (*hd == NULL || alloc_set(&h->train, n_train, n_ticks, c->train.n_out) != 0 ||
        alloc_set(&h->heldout, n_heldout, n_ticks, c->train.n_out) != 0) {
        return -1;
    }
    sample_forces(*hd, 0, &h->train, h->tick);
    sample_forces(*hd, n_train, &h->heldout, h->tick);
    return 0;
}

int tf_histories_linear_creep(tf_ctx *ctx, const tf_cases *c, const tf_creep *creep,
                              uint32_t tick_ns, size_t n_train, size_t n_heldout, size_t n_ticks,
                              uint64_t seed, tf_histories *h)
{
    if (!c->affine || c->base == NULL) {
        return tf_fail(ctx, "linear creep histories need an affine solver's unit responses");
    }
    tf_history_design *hd;
    if (start(h, c, TF_HIST_PRESS, tick_ns, n_train, n_heldout, n_ticks, seed, &hd) != 0) {
        tf_history_design_free(hd);
        tf_histories_free(h);
        return tf_fail(ctx, "out of memory for %zu histories of %zu ticks", n_train + n_heldout,
                       n_ticks);
    }
    for (size_t i = 0; i < n_train; ++i) {
        creep_one(c, creep, hd, i, &h->train, i, h->tick);
    }
    for (size_t i = 0; i < n_heldout; ++i) {
        creep_one(c, creep, hd, n_train + i, &h->heldout, i, h->tick);
    }
    tf_history_design_free(hd);
    return 0;
}

/* One history of a linear body with the given modes, the force held over
 * each tick (as tf_solver_history applies it): per force axis a, y_a =
 * f_a + sum_k w_ka (x_ka - f_a), x_k the unit-gain oscillator's position,
 * stepped exactly over the tick (the matrix exponential of the oscillator
 * with the held force as a third, constant state; GSL via
 * tf_resonant_transition on the deviation); u = base + sum_a unit_a y_a. */
static void modes_one(const tf_cases *c, const tf_resonant_truth *tr, tf_history_set *s,
                      size_t h, double tick)
{
    const size_t rows = 3 * (size_t)s->n_out;
    double F[TF_RESONANT_TRUTH_MAX][4], x[TF_RESONANT_TRUTH_MAX][3] = {{0}},
                                        v[TF_RESONANT_TRUTH_MAX][3] = {{0}};
    for (int k = 0; k < tr->n; ++k) {
        tf_resonant_transition(tr->omega[k] * tick, tr->zeta[k], F[k]);
    }
    for (size_t n = 0; n < s->n_ticks; ++n) {
        const double *fn = tf_history_force(s, h, n);
        double y[3];
        for (int a = 0; a < 3; ++a) {
            y[a] = fn[a];
            for (int k = 0; k < tr->n; ++k) { /* deviation from the held force decays by F */
                const double e1 = x[k][a] - fn[a], e2 = v[k][a];
                x[k][a] = fn[a] + F[k][0] * e1 + F[k][1] * e2;
                v[k][a] = F[k][2] * e1 + F[k][3] * e2;
                y[a] += tr->w[k][a] * (x[k][a] - fn[a]);
            }
        }
        double *u = s->u + (h * s->n_ticks + n) * rows;
        for (size_t o = 0; o < rows; ++o) {
            u[o] = c->base[o] + y[0] * c->unit[0][o] + y[1] * c->unit[1][o] + y[2] * c->unit[2][o];
        }
    }
}

int tf_histories_linear_modes(tf_ctx *ctx, const tf_cases *c, const tf_resonant_truth *truth,
                              uint32_t tick_ns, size_t n_train, size_t n_heldout, size_t n_ticks,
                              uint64_t seed, tf_histories *h)
{
    if (!c->affine || c->base == NULL) {
        return tf_fail(ctx, "linear modal histories need an affine solver's unit responses");
    }
    tf_history_design *hd;
    if (start(h, c, TF_HIST_DYNAMIC, tick_ns, n_train, n_heldout, n_ticks, seed, &hd) != 0) {
        tf_history_design_free(hd);
        tf_histories_free(h);
        return tf_fail(ctx, "out of memory for %zu histories of %zu ticks", n_train + n_heldout,
                       n_ticks);
    }
    tf_history_design_free(hd);
    for (size_t i = 0; i < n_train; ++i) {
        modes_one(c, truth, &h->train, i, h->tick);
    }
    for (size_t i = 0; i < n_heldout; ++i) {
        modes_one(c, truth, &h->heldout, i, h->tick);
    }
    return 0;
}

/* The solver's forces of history h (design index which): the design at
 * every m-th tick, rounded to float; the ticks between two solver steps
 * take the force on the line between them (rounded to float: the
 * firmware's input), so that the force the solver integrates (linear in
 * time inside its step, docs/solver.md "Time stepping") is the one the
 * ticks see.  steps: 1 + ceil((n_ticks - 1) / m) solver forces. */
static void coarse_forces(const tf_history_design *hd, size_t which, tf_history_set *s, size_t h,
                          double tick, size_t m, size_t steps, double (*fs)[3])
{
    for (size_t j = 0; j < steps; ++j) {
        double f[3];
        tf_history_design_force(hd, which, (double)(j * m) * tick, f);
        for (int k = 0; k < 3; ++k) {
            fs[j][k] = (double)(float)f[k];
        }
    }
    for (size_t n = 0; n < s->n_ticks; ++n) {
        const size_t j = n / m;
        const double w = (double)(n % m) / (double)m;
        for (int k = 0; k < 3; ++k) {
            const double f = w == 0 ? fs[j][k] : (1 - w) * fs[j][k] + w * fs[j + 1][k];
            s->force[h * s->n_ticks + n][k] = (double)(float)f;
        }
    }
}

void tf_histories_outputs(const tf_outputs *o, const double *full, size_t dofs, size_t n_ticks,
                          size_t m, double *u)
{
    for (size_t n = 0; n < n_ticks; ++n, u += 3 * o->n_nodes) {
        const size_t j = n / m;
        const double w = (double)(n % m) / (double)m;
        const double *a = full + j * dofs, *b = w == 0 ? a : full + (j + 1) * dofs;
        for (size_t i = 0; i < o->n_nodes; ++i) {
            for (int k = 0; k < 3; ++k) {
                const size_t d = 3 * (size_t)o->nodes[i] + (size_t)k;
                u[3 * i + (size_t)k] = w == 0 ? a[d] : (1 - w) * a[d] + w * b[d];
            }
        }
    }
}

/* One history through the solver, a step every m ticks, keeping the output
 * rows: at the solver's steps its displacements, between them the line
 * between the two steps' (the error this adds is measured in
 * docs/fitting.md §7.6). */
static int solve_one(const tf_cases *c, const tf_history_design *hd, size_t which,
                     tf_history_set *s, size_t h, double tick, size_t m)
{
    const size_t dofs = 3 * tf_solver_node_count(c->solver);
    const size_t steps = 1 + (s->n_ticks - 1 + m - 1) / m;
    double *full = malloc(dofs * steps * sizeof *full);
    double(*fs)[3] = malloc(steps * sizeof *fs);
    if (full == NULL || fs == NULL) {
        free(full);
        free(fs);
        return tf_fail(c->solver->ctx, "out of memory for a history of %zu ticks", s->n_ticks);
    }
    if (m > 1) {
        coarse_forces(hd, which, s, h, tick, m, steps, fs);
    } else {
        memcpy(fs, s->force + h * s->n_ticks, steps * sizeof *fs);
    }
    int rc = tf_solver_history(c->solver, c->contact, (const double(*)[3])fs, steps,
                               (double)m * tick, full);
    if (rc == 0) {
        tf_histories_outputs(&c->problem->outputs, full, dofs, s->n_ticks, m,
                             s->u + h * s->n_ticks * 3 * (size_t)s->n_out);
    }
    free(full);
    free(fs);
    return rc;
}

int tf_histories_solve(const tf_cases *c, tf_history_kind kind, uint32_t tick_ns,
                       size_t solve_every, size_t n_train, size_t n_heldout, size_t n_ticks,
                       uint64_t seed, tf_histories *h)
{
    tf_history_design *hd;
    if (solve_every < 1 || n_ticks < 2) {
        return tf_fail(c->solver->ctx, "histories: a solver step every %zu ticks of %zu",
                       solve_every, n_ticks);
    }
    if (start(h, c, kind, tick_ns, n_train, n_heldout, n_ticks, seed, &hd) != 0) {
        tf_history_design_free(hd);
        tf_histories_free(h);
        return tf_fail(c->solver->ctx, "out of memory for %zu histories", n_train + n_heldout);
    }
    int rc = 0;
    for (size_t i = 0; rc == 0 && i < n_train + n_heldout; ++i) {
        const int held = i >= n_train;
        rc = solve_one(c, hd, i, held ? &h->heldout : &h->train, held ? i - n_train : i, h->tick,
                       solve_every);
    }
    tf_history_design_free(hd);
    if (rc != 0) {
        tf_histories_free(h);
        return -1;
    }
    return 0;
}

static void free_set(tf_history_set *s)
{
    free(s->force);
    free(s->u);
    s->force = NULL;
    s->u = NULL;
}

void tf_histories_free(tf_histories *h)
{
    free_set(&h->train);
    free_set(&h->heldout);
}
