/*
 * colloc.h — MLS collocation with explicit dynamics (seed 004 §2, after
 * Müller et al. 2004, "Point based animation of elastic, plastic and
 * melting objects"): a body is a cloud of particles; each particle's
 * deformation gradient is the moving-least-squares fit of its neighbours'
 * displacements (eqs 6-9), its stress comes from a material law
 * (materials/material.h: St. Venant-Kirchhoff is the seed's), and the
 * nodal forces are the derivatives of the stored energy summed over the
 * particles (eqs 10-12: nodal integration).  Time runs explicitly
 * (central differences); a static answer is the end of a dynamic
 * relaxation.  Method, choices and measurements: docs/collocation.md.
 *
 * This is the core with plain arrays in and out: particle positions, which
 * displacement components are prescribed, nodal forces, a rigid sphere.  It
 * includes nothing from scene/ or fitting/.
 *
 * Units: mm, N, MPa, s; masses in t (1 t = 1 N s^2/mm), densities in
 * t/mm^3 (water: 1e-9).  Displacements, velocities and forces are 3 per
 * particle (component a of particle i at 3 i + a).
 *
 * Determinism: every sum runs in an order fixed at set-up (a particle
 * gathers the forces its neighbours' stresses put on it, in ascending
 * particle order), so results are the same bits for any OpenMP thread
 * count.
 */
#ifndef TF_COLLOC_H
#define TF_COLLOC_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "materials/material.h"

typedef struct tf_colloc_opts {
    unsigned neighbours; /* k nearest (default 10), plus ties at the k-th distance */
    double support;      /* h_i = support x mean distance to the neighbours (default 1.5) */
    double rcond_min;    /* smallest reciprocal condition of a moment matrix (1e-6) */
    double kv;           /* volume-conservation constant of eq 12, MPa (default 0) */
    double stab;         /* weight of the fit-residual energy (ours, default 0.2; see
                          * docs/collocation.md: 0 is the seed's method) */
    int threads;         /* OpenMP threads of the parallel loops; 0: OpenMP's default */
} tf_colloc_opts;

void tf_colloc_defaults(tf_colloc_opts *o);

/* Bits of a particle's `fixed` mask: component a is prescribed. */
enum { TF_COLLOC_FIX_X = 1, TF_COLLOC_FIX_Y = 2, TF_COLLOC_FIX_Z = 4, TF_COLLOC_FIX_ALL = 7 };

/* A plane of mirror symmetry: coordinate `axis` (0, 1, 2) = at. */
typedef struct tf_colloc_mirror {
    int axis;
    double at;
} tf_colloc_mirror;

typedef struct tf_colloc_body {
    size_t n;
    const double *X;            /* 3n reference positions, mm */
    const unsigned char *fixed; /* n masks (TF_COLLOC_FIX_*), or NULL: none */
    /* Particle volumes (quadrature weights), mm^3: given (a grid's tributary
     * volumes), or NULL for the seed's eqs 2-3 (masses from the mean
     * neighbour distance, densities from the kernel, v = m / rho), scaled
     * so that they sum to total_volume when that is > 0. */
    const double *volume;
    double total_volume;
    tf_material material;
    double density; /* t/mm^3 */
    /* Up to 3 planes of symmetry (x = at, ...), the body lying on one side:
     * a quarter block with the planes through the indenter's axis is the
     * whole block.  Each particle near a plane gets a mirror image that the
     * supports see (so a particle on the plane has a full, symmetric
     * support), whose displacement is the particle's reflected, and whose
     * force goes back to it.  Particles on a plane have their normal
     * component fixed at 0.  Given volumes are those of the modelled part
     * (half for a particle on one plane); eqs 2-3 volumes are halved per
     * plane a particle lies on. */
    const tf_colloc_mirror *mirrors;
    size_t n_mirrors;
} tf_colloc_body;

typedef struct tf_colloc tf_colloc;

/* Builds the particles: supports, kernel weights, volumes and masses, MLS
 * gradient weights (reference configuration).  Returns NULL with a message
 * (a bad option or material, a moment matrix near singular: the particle,
 * its position and neighbour count). */
tf_colloc *tf_colloc_new(tf_ctx *ctx, const tf_colloc_body *b, const tf_colloc_opts *o);
void tf_colloc_free(tf_colloc *c);

/* ---- the particles (read-only) ---------------------------------------- */

size_t tf_colloc_count(const tf_colloc *c);
/* Mirror images made for the symmetry planes. */
size_t tf_colloc_ghosts(const tf_colloc *c);
const double *tf_colloc_volumes(const tf_colloc *c); /* n, mm^3 */
const double *tf_colloc_masses(const tf_colloc *c);  /* n, t */
const double *tf_colloc_radii(const tf_colloc *c);   /* n support radii h_i, mm */
/* Particle i's neighbours (ascending distance) and their count. */
const uint32_t *tf_colloc_neighbours(const tf_colloc *c, size_t i, size_t *count);
/* Smallest reciprocal condition of the moment matrices, and where. */
double tf_colloc_rcond(const tf_colloc *c, size_t *at);

/* ---- the state ---------------------------------------------------------- */

/* Displacement u, velocity v, external nodal forces fext (N) and
 * prescribed values ubar (used at fixed components), each 3n, owned by c
 * and zero after tf_colloc_new; the caller reads and writes them. */
double *tf_colloc_u(tf_colloc *c);
double *tf_colloc_v(tf_colloc *c);
double *tf_colloc_fext(tf_colloc *c);
double *tf_colloc_ubar(tf_colloc *c);

/* Elastic forces f = -dU/du (3n, N) at displacement u and, when energy is
 * not NULL, the stored energy U (mJ).  Fixed components get their force
 * too (with the external force added, the support's reaction is its
 * negative).  dt is the material's time step (0 for elastic laws); the
 * history is read, not advanced.  Returns 0, or -1 with a message when a
 * particle's deformation gradient has det F <= 0. */
int tf_colloc_forces(tf_ctx *ctx, tf_colloc *c, const double *u, double dt, double *f,
                     double *energy);

/* Every particle's deformation gradient F_i = I + grad u|_i (eqs 6-9;
 * 9 per particle, row major dx_a/dX_b) at displacement u. */
void tf_colloc_deformation(tf_colloc *c, const double *u, double *F);

/* The displacement field of particle displacements u (3n) between the
 * particles, at np points x: at each point the nearest particle's value
 * carried by its MLS gradient, u_i + G_i (x - X_i) (eqs 6-9: it reproduces
 * a linear field exactly, and is u_i at the particle), uh (3 np); grad (9 np,
 * row major du_a/dx_b) is G_i, or NULL.  Thread-safe.  Returns 0, or -1
 * with a message (out of memory). */
int tf_colloc_field(tf_ctx *ctx, const tf_colloc *c, const double *u, const double *x, size_t np,
                    double *uh, double *grad);

/* ---- rigid sphere ------------------------------------------------------- */

typedef enum tf_colloc_drive {
    TF_COLLOC_INDENT, /* the sphere's travel is prescribed (tf_colloc_sphere_travel) */
    TF_COLLOC_FORCE,  /* a force along dir pushes a sphere of the given mass */
} tf_colloc_drive;

typedef struct tf_colloc_sphere {
    double centre[3]; /* at travel 0, mm */
    double dir[3];    /* direction of travel (into the body), normalised by the callee */
    double radius;    /* mm */
    tf_colloc_drive drive;
    double force;     /* TF_COLLOC_FORCE: N along dir */
    double mass;      /* TF_COLLOC_FORCE in dynamics: the indenter's mass, t (> 0) */
} tf_colloc_sphere;

/* Puts a frictionless rigid sphere into the scene (replacing any), at
 * travel 0 and at rest.  Contact is a constraint: a particle that moves
 * into the sphere is put back on its surface along the radius and loses
 * its velocity into the sphere (docs/collocation.md).  Returns 0, or -1
 * with a message. */
int tf_colloc_set_sphere(tf_ctx *ctx, tf_colloc *c, const tf_colloc_sphere *s);
void tf_colloc_remove_sphere(tf_colloc *c);
/* The sphere's travel along dir (mm): set (indentation drive) or read. */
void tf_colloc_set_travel(tf_colloc *c, double travel);
double tf_colloc_travel(const tf_colloc *c);
/* TF_COLLOC_FORCE: the pushing force (N). */
void tf_colloc_set_push(tf_colloc *c, double force);
/* The force the body puts on the sphere against dir (N): in equilibrium,
 * the sum over the particles on the sphere of their inward force
 * (tf_colloc_relax); after tf_colloc_run, the momentum the sphere took from
 * the particles in the last step over dt. */
double tf_colloc_contact_force(const tf_colloc *c);
/* How many particles touch the sphere. */
size_t tf_colloc_contacts(const tf_colloc *c);

/* ---- explicit dynamics -------------------------------------------------- */

/* The largest stable step of the central-difference scheme without
 * damping, 2 / omega_max, omega_max^2 the largest eigenvalue of M^-1 K
 * over the free components (K the stiffness at the reference
 * configuration; Lanczos, 40 steps).  Returns it (s), or a negative value
 * with a message. */
double tf_colloc_critical_dt(tf_ctx *ctx, tf_colloc *c);

/* The same bound from the P-wave speed: min_i r_i / c_p, r_i the distance
 * to the nearest neighbour, c_p = sqrt((lambda + 2 mu) / rho). */
double tf_colloc_wave_dt(const tf_colloc *c);

/* `steps` central-difference steps of dt (s) with mass-proportional
 * damping alpha (1/s): v += dt (M^-1 f - alpha v) (the damping term
 * centred in time), u += dt v, then prescribed values and the sphere.
 * `fext` acts throughout; a history law's state advances every step.
 * Returns 0, or -1 with a message (a particle inverted, the motion not
 * finite: the step was too large). */
int tf_colloc_run(tf_ctx *ctx, tf_colloc *c, double dt, size_t steps, double alpha);

/* Simulated time so far (s). */
double tf_colloc_time(const tf_colloc *c);

/* ---- static answer: dynamic relaxation ---------------------------------- */

typedef struct tf_colloc_relax_opts {
    double tol;       /* residual force / (applied + reaction forces), 2-norms (1e-6) */
    size_t max_steps; /* (200000) */
} tf_colloc_relax_opts;

typedef struct tf_colloc_relax_stats {
    size_t steps;
    double residual; /* relative, as tol */
    int converged;
} tf_colloc_relax_stats;

void tf_colloc_relax_defaults(tf_colloc_relax_opts *o);

/* The equilibrium under fext, the prescribed values and the sphere, from
 * the current displacement: central differences with fictitious masses
 * (each particle's stable step the same) and damping adapted to the
 * lowest mode (docs/collocation.md).  Velocities are zero afterwards.
 * Returns 0 (converged), 1 (not converged within max_steps: the state is
 * the last iterate), or -1 with a message. */
int tf_colloc_relax(tf_ctx *ctx, tf_colloc *c, const tf_colloc_relax_opts *o,
                    tf_colloc_relax_stats *st);

#endif /* TF_COLLOC_H */
