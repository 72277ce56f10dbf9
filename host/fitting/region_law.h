/*
 * region_law.h — the contact law over a region (TFIT_FAMILY_REGION) as the
 * host fits and evaluates it, in double precision.
 *
 * At grid coordinates g the law is a potential of the contact displacement
 * u (chart frame, mm), a polynomial of degree 2 .. P in the normalised
 * displacement v = s_u u:
 *
 *   E(g, u) = sum_t e_t(g) m_t(v),  m_t = v_a^i v_b^j v_c^k, 2 <= i + j + k <= P,
 *
 * ordered by degree, then by decreasing i, then decreasing j (the order of
 * the target's basis, tfit_basis.c): for P = 2, v_a^2, v_a v_b, v_a v_c,
 * v_b^2, v_b v_c, v_c^2.  T = C(P + 3, 3) - 4 terms.  The force is its
 * gradient, F = s_u grad_v E.  P = 2 is linear elasticity: E = u^T K u / 2,
 * e = (K_aa / 2, K_ab, K_ac, K_bb / 2, K_bc, K_cc / 2) / s_u^2.
 *
 * Per control point (numerics/grid_spline.h) the law holds {h, e_1 .. e_T}: the
 * rest surface's height and the potential's coefficients, blended by the
 * same B-spline weights (a blend of convex potentials is convex).
 */
#ifndef TF_REGION_LAW_H
#define TF_REGION_LAW_H

#include <stddef.h>

#include "base/context.h"

#define TF_REGION_MAX_P 4
#define TF_REGION_MAX_TERMS 31 /* C(4 + 3, 3) - 4 */

typedef struct tf_region_law {
    unsigned nx, ny;  /* sites per axis */
    double h[2];      /* site spacing along a and b, mm */
    unsigned P;       /* degree */
    size_t T;         /* potential terms */
    double s_u;       /* 1 / the displacement scale, 1/mm */
    double mu;        /* friction coefficient */
    double *ctrl;     /* (nx + 2)(ny + 2) x (1 + T): per control point {h, e_1 .. e_T} */
} tf_region_law;

/* Number of potential terms of degree 2 .. P. */
size_t tf_region_terms(unsigned P);

/* Exponents (i, j, k) of the T terms, in order. */
void tf_region_exponents(unsigned P, unsigned (*ex)[3]);

/* The terms m_t(v) (T) and their gradients dm[t][a] = d m_t / d v_a. */
void tf_region_monomials(unsigned P, const double v[3], double *m, double (*dm)[3]);

/* Potential coefficients (6) of E = u^T K u / 2 in v = s_u u. */
void tf_region_quadratic_coefs(const double K[9], double s_u, double e[6]);

/* K (3 x 3) of quadratic coefficients e (6) in v = s_u u. */
void tf_region_quadratic_stiffness(const double e[6], double s_u, double K[9]);

/* The law at chart coordinates (a, b): F = s_u grad_v E (3, N) for contact
 * displacement u (mm), and optionally the height h (NULL to skip). */
void tf_region_law_force(const tf_region_law *law, double a, double b, const double u[3],
                         double F[3], double *h);

/* The stiffness of the law's quadratic part at (a, b) (the tangent at
 * u = 0), N/mm. */
void tf_region_law_stiffness(const tf_region_law *law, double a, double b, double K[9]);

/* The smallest eigenvalue of the quadratic part's stiffness over the
 * control points (> 0: every control point's quadratic part SPD). */
double tf_region_law_min_stiffness(const tf_region_law *law);

/* The smallest eigenvalue of the blended stiffness K(g) over a sampling
 * of the domain, per_cell points per site interval along each axis (the
 * check when some control point is not SPD: the blend may still be). */
double tf_region_law_min_stiffness_sampled(const tf_region_law *law, unsigned per_cell);

void tf_region_law_free(tf_region_law *law);

/* Table floats of the law as the device stores it: the chart map (12),
 * the scalars {1/ha, 1/hb, s_u, mu} (4), and 1 + T per control point. */
size_t tf_region_law_floats(const tf_region_law *law);

/* Symmetric 3 x 3 helpers: eigenvalues ascending (Jacobi), and the
 * inverse (returns -1 when singular). */
void tf_sym3_eigenvalues(const double A[9], double lam[3]);
int tf_mat3_inverse(const double A[9], double inv[9]);

#endif /* TF_REGION_LAW_H */
