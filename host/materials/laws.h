/*
 * laws.h — what the laws in host/materials share (internal to this folder:
 * the rest of the program reaches a law through the registry and
 * material.h).  Each law file defines its `const tf_law_ops tf_law_NAME`,
 * which only registry.c names.
 */
#ifndef TF_LAWS_H
#define TF_LAWS_H

#include <stddef.h>

#include "materials/material.h"

/* A sentence for parameter key = v (why, then the value), and the key:
 * what a law's check returns. */
const char *tf_law_bad(char *msg, size_t len, const char *key, double v, const char *why);

/* ---- the isotropic elastic parameters (elastic_params.c) ---- */

/* (E, nu), in this order: linear, svk, neo-hookean. */
enum { TF_ELASTIC_E, TF_ELASTIC_NU, TF_ELASTIC_PARAMS };
extern const tf_law_param tf_elastic_params[TF_ELASTIC_PARAMS];
void tf_elastic_moduli(const double *p, double *young, double *poisson);
/* E finite and > 0, -1 < nu < 0.5. */
const char *tf_elastic_check(const double *p, char *msg, size_t len);
/* nu alone (the Kelvin laws have no E). */
const char *tf_poisson_check(double nu, char *msg, size_t len);

/* ---- the Kelvin solid's parameters (kelvin.c) ---- */

/* (nu, k1, k2, eta, k), in this order: kelvin, kelvin-neo-hookean. */
enum { TF_KELVIN_NU, TF_KELVIN_K1, TF_KELVIN_K2, TF_KELVIN_ETA, TF_KELVIN_K, TF_KELVIN_PARAMS };
extern const tf_law_param tf_kelvin_params[TF_KELVIN_PARAMS];
/* The instantaneous moduli E_0 = k1 + k2, nu. */
void tf_kelvin_moduli(const double *p, double *young, double *poisson);
/* g_inf = k1 / (k1 + k2), tau = eta / k2 (infinite when k2 = 0). */
void tf_kelvin_relaxation(const double *p, double *g_inf, double *tau);
/* nu, k1 > 0, 0 <= k2, eta > 0 with tau finite when k2 > 0, k >= 0. */
const char *tf_kelvin_check(const double *p, char *msg, size_t len);

/* ---- evaluations one law borrows from another ---- */

/* St. Venant-Kirchhoff, Lame constants lambda, mu (svk.c). */
int tf_svk_eval(double lambda, double mu, const double F[9], double S[6], double C[36],
                double *W);

/* Compressible neo-Hookean, shear modulus mu, bulk modulus kappa
 * (neohooke.c). */
int tf_neohooke_eval(double mu, double kappa, const double F[9], double S[6], double C[36],
                     double *W);

/* CalculiX's NEO HOOKE constants for E, nu: C10 = mu/2, D1 = 2/K
 * (neohooke.c). */
void tf_neohooke_constants(double young, double poisson, double *c10, double *d1);

#endif /* TF_LAWS_H */
