/*
 * palpate_replay.h — make demo-palpate's firmware loop and its replay
 * against true solves (palpate.h lists the program's parts).
 */
#ifndef PALPATE_REPLAY_H
#define PALPATE_REPLAY_H

#include <stddef.h>
#include <stdint.h>

#include "coeffs/palpate/palpate.h"
#include "problem/problem.h"
#include "solvers/solver.h"

/* The display's rate: the surface every DISPLAY_EVERY ticks (60 Hz-ish at
 * 1 kHz). */
#define PALPATE_DISPLAY_EVERY 16

/* The device's view of the two models and what the replay needs of them. */
typedef struct palpate_models {
    const char *name;         /* the scene's, for the pictures */
    const tfit_model *law, *surf;
    const tf_model *law_host; /* the law's tables on the host (its rest surface) */
    palpate_grid grid;
    double R_F;               /* envelope radius, N */
    double peak;              /* the largest output displacement of an envelope force, mm */
    size_t n_out;
} palpate_models;

/* What the loop records at every tick, and the surface at display ticks. */
typedef struct palpate_run {
    size_t n;
    float (*state)[2][TFIT_REGION_STATE_WORDS];
    float (*force)[2][3];
    int32_t *status;
    float *surface;          /* n / DISPLAY_EVERY x 3 n_out: at ticks k % EVERY == EVERY - 1 */
    int32_t *surface_status;
    double tick_ns, tick_ns_worst; /* the median and worst force tick (ns) */
    double frame_ns;               /* the median surface frame (ns) */
} palpate_run;

/* The script through the firmware's calls: tfit_region_force (one
 * instrument) or tfit_region_pair (two) every tick, the caller's states
 * carried from tick to tick; tfit_region_surface (or _surface_pair) at the
 * display ticks.  0, or -1 when out of memory. */
int palpate_loop(tf_ctx *ctx, const palpate_models *m, const palpate_tick *t, size_t n,
                 palpate_run *run);
void palpate_run_free(palpate_run *run);

/* The replay's result: the largest errors over the sampled display ticks
 * in contact whose status was TFIT_OK (% of R_F, % of the peak). */
typedef struct palpate_errors {
    double force, surface;
    size_t ticks, pair_ticks, skipped; /* sampled; with two instruments; not TFIT_OK */
    size_t sites;                      /* site solves */
    double seconds;
} palpate_errors;

/* Replays every `every`-th display tick against true solves: the sites of
 * the proxies solved with the probe's patch loads (tf_region_sites_solve;
 * the two instruments' cross compliances recorded as they are solved),
 * the true force at the firmware's contact displacement and the true
 * surface under the firmware's force. */
int palpate_replay(tf_ctx *ctx, tf_solver *sv, const tf_problem *p, const tf_contact_region *r,
                   const palpate_models *m, const palpate_tick *t, const palpate_run *run,
                   size_t every, palpate_errors *e);

#endif /* PALPATE_REPLAY_H */
