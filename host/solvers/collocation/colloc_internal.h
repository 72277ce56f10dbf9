/*
 * colloc_internal.h — the particle data shared by the collocation files
 * (not for use outside host/solvers/collocation/).
 *
 * Layout, chosen for the step (colloc_force.c, docs/collocation.md "Speed"):
 *   forward pairs  particle i's neighbours k at start[i] .. start[i+1]:
 *                  nbr (index), y = w_ik X_ik (3), w (kernel), and the two
 *                  side by side for the step, yw (y, w: 4 doubles, one
 *                  32-byte record per pair);
 *   reverse pairs  the pairs (i, k) grouped by k, ascending i, at
 *                  rstart[k] .. rstart[k+1]: rsrc (i), ryc (y of the pair,
 *                  3, then beta_i w_ik: one record of 4): what particle k
 *                  gathers in a step;
 *   per particle   ainv (A_i^-1, 9), s = sum_k y_ik, beta (residual energy
 *                  factor), bsum = sum of beta_i w_ik over k's reverse pairs (also
 *                  for images), and per step the values phase 1 leaves for
 *                  phase 2 (ph1: Q_i, 9, the particle's own force, 3, and its
 *                  displacement, 3: a record of 16, 64-byte aligned).
 */
#ifndef TF_COLLOC_INTERNAL_H
#define TF_COLLOC_INTERNAL_H

#include "base/context.h"
#include "solvers/collocation/colloc.h"

/* Values per particle that phase 1 of a force evaluation leaves:
 * Q = v P A^-1 - beta G (9), the particle's own force (3), its
 * displacement (3: what phase 2 reads of particle i beside Q_i, so one
 * record of two cache lines holds it all), one unused. */
enum { TF_COLLOC_PH1 = 16 };

typedef struct tf_colloc_ball {
    int on;
    tf_colloc_sphere s;
    double travel, speed; /* along s.dir */
    double force;         /* contact force against dir, N */
    size_t contacts;
} tf_colloc_ball;

struct tf_colloc {
    size_t n;  /* particles */
    size_t na; /* particles and their mirror images (ghosts n .. na - 1) */
    double *X; /* na */
    unsigned char *fixed;
    tf_material mat;
    int small; /* small-strain law: P = sigma */
    int hooke; /* HOOKE at finite strain (St. Venant-Kirchhoff's form, materials/material.h):
                * the step evaluates S = lambda tr(E) I + 2 mu E inline */
    double lame_lambda, lame_mu;
    size_t hsize;
    double density;
    tf_colloc_opts opts;

    /* mirror images: ghost n + g is particle gsrc[g] reflected (gsign, 3
     * per ghost: -1 across a plane normal to that axis, else 1); particle
     * i's images are glist[gstart[i] .. gstart[i+1]] (ghost numbers g) */
    tf_colloc_mirror mirror[3];
    size_t n_mirrors;
    double mtol; /* on a plane: within this distance */
    uint32_t *gsrc, *gstart, *glist;
    double *gsign;
    double *ue, *fe; /* 3 na: displacements with the images', forces on all */

    /* supports */
    uint32_t *start, *nbr;
    double *y, *w, *yw;
    double *h, *rbar, *rmin;
    double *vol, *mass;
    double *ainv, *s, *beta, *bsum;
    double rcond;
    size_t rcond_at;
    uint32_t *rstart, *rsrc;
    double *ryc;

    /* state */
    double *u, *v, *fext, *ubar, *f;
    double *hold, *hnew;
    double time;
    tf_colloc_ball ball;

    /* scratch of a force evaluation */
    double *ph1, *epart;
    int *bad;

    /* dynamic relaxation: fictitious masses (made on first use), scratch */
    double *mdr, *u0, *f0, *res;
};

/* Mirror images (colloc_mirror.c): made from the first supports' reach
 * (the largest k-th neighbour distance); ue from u; fe folded into f. */
int tf_colloc_make_ghosts(tf_ctx *ctx, tf_colloc *c, const double *reach);
/* Drops the images no support holds; renumbers the k-nearest lists (cnt[i]
 * entries at lists + i cap).  Returns 0, or -1 when out of memory. */
int tf_colloc_drop_ghosts(tf_colloc *c, uint32_t *lists, const size_t *cnt, size_t cap);
void tf_colloc_ghost_fill(const tf_colloc *c, const double *u, double *ue);
void tf_colloc_ghost_fold(const tf_colloc *c, const double *fe, double *f);
/* The part of particle i's volume on the body's side: 1/2 per plane it
 * lies on. */
double tf_colloc_mirror_share(const tf_colloc *c, size_t i);

/* The thread count of the parallel loops (colloc_setup.c). */
int tf_colloc_threads(const tf_colloc *c);

/* Seed 004 eq 1 (colloc_setup.c). */
double tf_colloc_kernel(double r);

/* Moment matrices, gradient weights, residual factors and reverse pairs
 * (colloc_mls.c). */
int tf_colloc_setup_mls(tf_ctx *ctx, tf_colloc *c);

/* Phase 1 and 2 of a force evaluation (colloc_force.c); the history goes
 * from hold to hnew. */
int tf_colloc_eval(tf_ctx *ctx, tf_colloc *c, const double *u, double dt, double *f,
                   double *energy);

/* Puts displacement components back on their prescribed values and zeroes
 * their velocity (colloc_dynamics.c). */
void tf_colloc_impose(tf_colloc *c, double *u, double *v);

/* One central-difference step with masses m (n), damping alpha, the force
 * f already evaluated at u (colloc_dynamics.c). */
void tf_colloc_kick_drift(tf_colloc *c, const double *m, double dt, double alpha);

/* The sphere after a drift (colloc_contact.c): under the force drive it
 * moves first (mass ms > 0, damping alpha, the last step's contact force;
 * ms = 0: it stays);
 * then particles inside are put back, and the momentum they give the
 * sphere over dt is its contact force.  m: the particle masses in use. */
void tf_colloc_contact(tf_colloc *c, const double *m, double dt, double alpha, double ms);

/* The sum of the masses m of the particles touching the sphere. */
double tf_colloc_contact_mass(const tf_colloc *c, const double *m);

/* The static contact force and the residual with the contact reactions
 * removed (colloc_contact.c): res = f at free components, minus the
 * inward normal part at particles on the sphere. */
double tf_colloc_contact_static(tf_colloc *c, double *res);

/* Largest eigenvalue of M^-1 K (free components, reference configuration)
 * by Lanczos (colloc_dynamics.c); negative on failure. */
double tf_colloc_omega2_max(tf_ctx *ctx, tf_colloc *c, const double *m);

#endif /* TF_COLLOC_INTERNAL_H */
