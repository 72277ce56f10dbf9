/*
 * region_surface.h — the surface for the current contact
 * (TFIT_FAMILY_REGION_SURFACE) of an affine solver, fitted and evaluated in
 * double precision.
 *
 *   u_out = Phi a(g, F),  a(g, F) = A(g) f,  f = F / R_F,
 *
 * Phi (3 n_out x r) the POD modes of every fitted site's output responses
 * (its 3 columns per site, numerics/pod.h), A(g) (r x 3) the modal
 * amplitudes per unit normalised force, A_s = R_F Phi^T U_s at each site,
 * blended by the region's splines (numerics/grid_spline.h).  The site modes
 * Phi_site(g) (3 x r) are the modes' patch-averaged values at a site, so
 * that Phi_site(g1) a(g2, F2) is the patch-averaged displacement at g1
 * under F2 at g2 (the cross compliance C(g1, g2) = Phi_site(g1) A(g2) / R_F
 * of two instruments).  A mode is a combination of the site responses
 * (the POD's right singular vectors: Phi_k = sum_j U_j c_jk,
 * c = V Sigma^{-1} = U_out^T Phi Sigma^{-2}); extended to the whole field
 * with the same combination, Psi_k = K^{-1} sum_j L_j c_jk is one solve of
 * combined site loads per mode, and Phi_site(s) = L_s^T Psi (the patch
 * average, region_sites.h).
 *
 * Per control point the table holds {A (r x 3, row-major), Phi_site
 * (3 x r, row-major)}.
 *
 * The near field.  A probe's load makes a peak under it that moves with
 * the site; the modes shared by every site need about one mode per output
 * component to follow it (block48's whole top face: rank 256 for 2.6 %,
 * 19 % at rank 48).  The residual responses the modes leave at the sites,
 * R_s = U_s - Phi Phi^T U_s, are interpolated by the same splines, and
 * each control point keeps only the outputs within the near radius of it
 * (3-D distance in the chart frame, the control point at the height of its
 * nearest site; at most near_cap of them, the nearest): a table that grows
 * with the control points times the outputs near one, not with sites x
 * outputs.  Within the radius the correction is the spline of the true
 * residual; beyond it the modes alone answer.  Per control point the
 * near table holds n_near entries {output j, D (3 x 3, row-major, scene
 * component x chart force axis, mm/N)}, padded with j = 0, D = 0.
 */
#ifndef TF_REGION_SURFACE_H
#define TF_REGION_SURFACE_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "fitting/region_sites.h"
#include "solvers/solver.h"

/* Most modes a surface holds. */
#define TF_REGION_MAX_RANK 512

typedef struct tf_region_surface {
    unsigned nx, ny;
    double h[2];
    unsigned r;        /* modes */
    size_t n_out;
    double R_F;        /* force envelope radius, N */
    double *modes;     /* 3 n_out x r, column-major */
    double *ctrl;      /* (nx + 2)(ny + 2) x 6 r: per control point {A, Phi_site} */
    unsigned n_near;   /* near-field entries per control point (0: none) */
    double near_radius;/* mm */
    uint32_t *near_idx;/* (nx + 2)(ny + 2) x n_near output indices */
    double *near_D;    /* (nx + 2)(ny + 2) x n_near x 9, mm/N */
} tf_region_surface;

/* What a surface's near field is fitted from: the modes' sites (t, idx in
 * grid order, as tf_region_modes_build took them; borrowed), the outputs'
 * chart coordinates (3 n_out) and each site's (3 n, the chart frame: (a,
 * b, height)), owned by the modes; radius <= 0: no near field. */
typedef struct tf_region_near_spec {
    const tf_region_sites *t;
    const size_t *idx;
    double *out_q;
    double *site_q;
    double radius;
    unsigned cap;
} tf_region_near_spec;

/* Most near-field entries per control point (the device's
 * TFIT_REGION_MAX_NEAR). */
#define TF_REGION_MAX_NEAR 32

/* The POD of a set of sites' responses, and the site values of every
 * mode up to r_max: what a surface of any rank <= r_max is cut from. */
typedef struct tf_region_modes {
    size_t n_sites, n_out;
    unsigned r_max;
    double *phi;       /* 3 n_out x r_max, column-major */
    double *sigma;     /* r_max singular values */
    double *amp;       /* per site r_max x 3 (row-major): R_F Phi^T U_s */
    double *site;      /* per site 3 x r_max (row-major): L_s^T Psi */
    double seconds_solve; /* wall time of the r_max solves of combined loads */
    tf_region_near_spec near; /* radius 0 unless set after the build */
} tf_region_modes;

/* The modes of sites idx[0 .. n - 1] of t (their responses, loads), with
 * solver s for the site modes (every site's load kept in t).  r_max is
 * lowered to the data's rank.  Returns 0, or -1 with the message. */
int tf_region_modes_build(tf_ctx *ctx, tf_solver *s, const tf_region_sites *t, const size_t *idx,
                          size_t n, double R_F, unsigned r_max, tf_region_modes *m);
void tf_region_modes_free(tf_region_modes *m);

/* The surface of rank r <= m->r_max over the nx x ny grid whose sites are
 * the modes' sites in grid order (row-major, i fastest). */
int tf_region_surface_fit(tf_ctx *ctx, const tf_region_modes *m, unsigned nx, unsigned ny,
                          const double h[2], double R_F, unsigned r, tf_region_surface *out);
void tf_region_surface_free(tf_region_surface *s);

/* The outputs' displacements (3 n_out) under force F (chart frame, N) at
 * chart point (a, b). */
void tf_region_surface_eval(const tf_region_surface *s, double a, double b, const double F[3],
                            double *out);

/* The cross compliance C(g1, g2) (3 x 3, row-major, chart frame, mm/N):
 * the patch-averaged displacement at (a1, b1) per unit force at (a2, b2). */
void tf_region_surface_cross(const tf_region_surface *s, double a1, double b1, double a2,
                             double b2, double C[9]);

/* Table floats as the device stores it: the chart map (12), the scalars
 * {1/ha, 1/hb, 1/R_F} (3), the modes (3 n_out r), 6 r per control point
 * and 10 per near-field entry. */
size_t tf_region_surface_floats(const tf_region_surface *s);

#endif /* TF_REGION_SURFACE_H */
