/*
 * material.h — the material laws behind one interface: stress, consistent
 * tangent and (where it exists) stored energy at one quadrature point, from
 * the deformation gradient and that point's history.
 *
 * Convention (total Lagrangian): every law returns the second
 * Piola-Kirchhoff stress S (Voigt 6, tensor components) and the tangent
 * C = dS/dE (6 x 6, row major) with respect to the law's strain measure E
 * (Voigt 6, engineering shears; kinematics.h):
 *   TF_KIN_FINITE  E = (F^T F - I)/2, Green-St. Venant (seed 004 eq 4);
 *   TF_KIN_SMALL   E = sym(F - I), the small strain; S is then the Cauchy
 *                  stress of linear theory and the solver keeps linear
 *                  kinematics (B matrix of seed 001 eq 22, no geometric
 *                  stiffness).
 * C is symmetric for the hyperelastic laws (LINEAR, SVK, NEOHOOKE) and for
 * KELVIN_NH; KELVIN's is not when k != 0 (docs/solver.md, "Material laws").
 *
 * Laws (docs/solver.md derives each):
 *   LINEAR     S = D eps, D of elasticity.h (E, nu).
 *   SVK        St. Venant-Kirchhoff: S = lambda tr(E) I + 2 mu E.
 *   NEOHOOKE   compressible neo-Hookean with CalculiX's *HYPERELASTIC,
 *              NEO HOOKE energy W = C10 (I1bar - 3) + (J - 1)^2 / D1,
 *              I1bar = J^(-2/3) tr(F^T F), C10 = mu/2, D1 = 2/K (mu, K the
 *              shear and bulk moduli of E, nu).
 *   KELVIN     seed 001 eqs 9-13: the three-parameter solid of its Fig. 2
 *              (spring k1 in parallel with spring k2 in series with a
 *              dashpot eta), relaxation modulus
 *              E(t) = k1 + k2 exp(-t/tau), tau = eta/k2, acting on the
 *              adjusted strain N(eps) = eps + k eps^2 (eq 10), small strain.
 *              3-D (our choice): sigma(t) = int_0^t D(E(t-s), nu) dN/ds ds
 *              with N(eps) = eps + k eps.eps, the tensor square.
 *   KELVIN_NH  ours: the same relaxation function acting on the
 *              neo-Hookean S of the instantaneous moduli (E0 = k1 + k2,
 *              nu): S(t) = int_0^t g(t-s) dS0/ds ds, g = E(t)/E0; k unused.
 *
 * History: caller-owned, tf_material_history_size() doubles per point,
 * zero at the start (tf_material_history_init).  tf_material_eval reads the
 * state at the end of the last converged step (hold) and writes the state
 * that this F, reached over dt, would leave (hnew): Newton iterations call
 * it with the same hold, and the caller copies hnew to hold once the step
 * converges.  hold == hnew is allowed (no separate iterations).
 */
#ifndef TF_MATERIAL_H
#define TF_MATERIAL_H

#include <stddef.h>

typedef enum tf_law {
    TF_LAW_LINEAR,
    TF_LAW_SVK,
    TF_LAW_NEOHOOKE,
    TF_LAW_KELVIN,
    TF_LAW_KELVIN_NH,
} tf_law;

typedef enum tf_kinematics { TF_KIN_SMALL, TF_KIN_FINITE } tf_kinematics;

typedef struct tf_material {
    tf_law law;
    double young;   /* E, MPa: LINEAR, SVK, NEOHOOKE */
    double poisson; /* nu, every law */
    double k1;      /* KELVIN*: relaxed modulus E_inf, MPa (seed Fig. 2, K1) */
    double k2;      /* KELVIN*: Maxwell-arm spring, MPa: E_0 = k1 + k2 (K2) */
    double eta;     /* KELVIN*: dashpot, MPa s: tau = eta / k2 (eta) */
    double k;       /* KELVIN: adjustment N(eps) = eps + k eps^2, >= 0 (eq 10) */
} tf_material;

/* Results of tf_material_eval. */
enum { TF_MAT_OK = 0, TF_MAT_INVERTED = 1 };

const char *tf_law_name(tf_law law);
tf_kinematics tf_material_kinematics(const tf_material *m);
size_t tf_material_history_size(const tf_material *m);
void tf_material_history_init(const tf_material *m, double *h);
/* 1 when the law has a stored energy W (tf_material_eval writes it). */
int tf_material_has_energy(const tf_material *m);

/* Checks the parameters the law uses: finite, E > 0, -1 < nu < 0.5,
 * k1 > 0, k2 >= 0 (the relaxed modulus k1 not above the instantaneous
 * k1 + k2), eta > 0 and tau = eta/k2 finite when k2 > 0, k >= 0.  Returns
 * NULL, or the name of the first bad field ("young", "poisson", "k1", "k2",
 * "eta", "k") with a sentence in msg for the caller to prefix with file and
 * line. */
const char *tf_material_check(const tf_material *m, char *msg, size_t len);

/* Stress S[6] and, when C is not NULL, the tangent C[36] = dS/dE at the
 * deformation gradient F[9] (row major, dx_i/dX_j) reached over the time
 * step dt >= 0 (s; 0 is an instantaneous jump, ignored by elastic laws).
 * When W is not NULL it receives the stored energy per unit reference
 * volume (MPa = mJ/mm^3), or NaN for a law without one.  Returns TF_MAT_OK,
 * or TF_MAT_INVERTED when a finite-strain law meets det F <= 0 (S and C are
 * then not written). */
int tf_material_eval(const tf_material *m, const double F[9], double dt, const double *hold,
                     double *hnew, double S[6], double C[36], double *W);

/* CalculiX's NEO HOOKE constants for E, nu: C10 = mu/2, D1 = 2/K. */
void tf_neohooke_constants(double young, double poisson, double *c10, double *d1);

/* The Kelvin solid's instantaneous and relaxed moduli and time constant. */
void tf_kelvin_moduli(const tf_material *m, double *e0, double *einf, double *tau);

#endif /* TF_MATERIAL_H */
