/*
 * laws.h — the individual material laws behind material.h (internal to
 * host/materials; the solver calls tf_material_eval).  Arguments as in
 * tf_material_eval; C and W may be NULL.
 */
#ifndef TF_LAWS_H
#define TF_LAWS_H

/* The material's parameters (material.h): declared, not included, so that
 * material.c includes this header without a module cycle. */
struct tf_material;

/* St. Venant-Kirchhoff, Lame constants lambda, mu (svk.c). */
int tf_svk_eval(double lambda, double mu, const double F[9], double S[6], double C[36],
                double *W);

/* Compressible neo-Hookean, shear modulus mu, bulk modulus kappa
 * (neohooke.c). */
int tf_neohooke_eval(double mu, double kappa, const double F[9], double S[6], double C[36],
                     double *W);

/* Seed 001's small-strain Kelvin law; history [h(6), eps_n(6)] (kelvin.c). */
void tf_kelvin_eval(const struct tf_material *m, const double F[9], double dt, const double *hold,
                    double *hnew, double S[6], double C[36]);

/* The relaxation on a neo-Hookean base; history [h(6), S0_n(6)]
 * (kelvin_nh.c). */
int tf_kelvin_nh_eval(const struct tf_material *m, const double F[9], double dt, const double *hold,
                      double *hnew, double S[6], double C[36]);

/* Factors of the exact one-step update of a hereditary integral with
 * kernel exp(-t/tau) over a step of x = dt/tau in which the driving
 * quantity is linear (phi1) or has a quadratic part (phi2) in time:
 * decay = exp(-x), phi1 = (1 - exp(-x))/x, phi2 = (x - 1 + exp(-x))/x^2,
 * with their limits 1 and 1/2 at x = 0 (kelvin.c). */
void tf_relax_factors(double x, double *decay, double *phi1, double *phi2);

#endif /* TF_LAWS_H */
