/*
 * material.h — the material laws behind one interface: a law is a table of
 * operations (tf_law_ops) registered by name (registry.c), and a material
 * is a value, a law and its parameter values (tf_material), that a solver
 * may hold once per problem or once per integration point.  Solvers ask a
 * material what it can do (its capabilities and the quantities below),
 * never which law it is.
 *
 * Convention (total Lagrangian): every law returns the second
 * Piola-Kirchhoff stress S (Voigt 6, tensor components) and the tangent
 * C = dS/dE (6 x 6, row major) with respect to the law's strain measure E
 * (Voigt 6, engineering shears; kinematics.h):
 *   finite strain (TF_MATERIAL_FINITE)  E = (F^T F - I)/2, Green-St. Venant
 *                  (seed 004 eq 4);
 *   small strain   E = sym(F - I); S is then the Cauchy stress of linear
 *                  theory and the solver keeps linear kinematics (B matrix
 *                  of seed 001 eq 22, no geometric stiffness).
 *
 * The registered laws (docs/solver.md, "Material laws", derives each):
 *   linear              S = D eps, D of elasticity.h (E, nu)       linear.c
 *   svk                 St. Venant-Kirchhoff, S = lambda tr(E) I + 2 mu E   svk.c
 *   neo-hookean         CalculiX's *HYPERELASTIC, NEO HOOKE energy  neohooke.c
 *   kelvin              seed 001 eqs 9-13, small strain             kelvin.c
 *   kelvin-neo-hookean  ours: kelvin's relaxation on neo-Hookean S  kelvin_nh.c
 *
 * History: caller-owned, tf_material_history_size() doubles per point,
 * set by tf_material_history_init before the first step.
 * tf_material_eval reads the state at the end of the last converged step
 * (hold) and writes the state that this F, reached over dt, would leave
 * (hnew): Newton iterations call it with the same hold, and the caller
 * copies hnew to hold once the step converges.  hold == hnew is allowed
 * (no separate iterations).
 */
#ifndef TF_MATERIAL_H
#define TF_MATERIAL_H

#include <stddef.h>

#include "materials/elasticity.h"

/* Parameters of one law at most. */
#define TF_MATERIAL_MAX_PARAMS 8

/* What a material lets a solver assume (tf_material_caps):
 *   FINITE       finite-strain kinematics (E Green-St. Venant, S the second
 *                Piola-Kirchhoff stress); without it, small strain;
 *   HISTORY      time-dependent: a history per point
 *                (tf_material_history_size > 0) and a relaxation function
 *                (tf_material_relaxation); a static solve is the fully
 *                relaxed equilibrium;
 *   ENERGY       a stored energy W (tf_material_eval writes it);
 *   HOOKE        S = lambda tr(E) I + 2 mu E in the law's strain measure,
 *                lambda and mu those of tf_material_lame, and nothing else
 *                (no history): the tangent is that constant D.  With small
 *                strain the response is linear and a solver may assemble D
 *                once; with finite strain a solver may evaluate S inline;
 *   UNSYMMETRIC  C may be unsymmetric (for these parameter values): the
 *                solver needs an unsymmetric tangent. */
enum {
    TF_MATERIAL_FINITE = 1u << 0,
    TF_MATERIAL_HISTORY = 1u << 1,
    TF_MATERIAL_ENERGY = 1u << 2,
    TF_MATERIAL_HOOKE = 1u << 3,
    TF_MATERIAL_UNSYMMETRIC = 1u << 4,
};

/* The volume measure theta a law's volumetric energy is quadratic in: what
 * a volumetric correction (B-bar, the Newton solver's cell-averaged theta)
 * must average to be consistent with the law.  At small strain both are
 * div u. */
typedef enum tf_volume_measure {
    TF_VOLUME_JACOBIAN,    /* theta = J - 1 */
    TF_VOLUME_GREEN_TRACE, /* theta = tr E (St. Venant-Kirchhoff: lambda (tr E)^2 / 2) */
} tf_volume_measure;

typedef enum tf_kinematics { TF_KIN_SMALL, TF_KIN_FINITE } tf_kinematics;

/* One parameter of a law. */
typedef struct tf_law_param {
    const char *key;  /* its scene key under material: ("E", "nu", "k1", ...) */
    const char *what; /* what it is, with its unit: "Young's modulus, MPa" */
    double fallback;  /* its value when not given; NaN: it must be given */
} tf_law_param;

/* A law.  p holds the parameter values in the order of params. */
typedef struct tf_law_ops {
    const char *name;    /* the scene's material.law */
    const char *summary; /* one line: what it is, where it comes from */
    unsigned caps;       /* TF_MATERIAL_* that hold for every parameter value */
    /* Capabilities these parameter values add (NULL: none). */
    unsigned (*caps_at)(const double *p);
    tf_volume_measure volume;
    size_t n_params;
    const tf_law_param *params;
    size_t history; /* doubles of history per point (0 without HISTORY) */
    /* The history before the first step (NULL: zeros). */
    void (*history_init)(const double *p, double *h);
    /* The small-strain moduli of the initial (instantaneous) response: what
     * a solver scales a penalty or a correction with, and what the law is
     * at small strain and no time. */
    void (*moduli)(const double *p, double *young, double *poisson);
    /* HISTORY: the relaxation function g(t) = g_inf + (1 - g_inf) e^(-t/tau)
     * that takes the instantaneous response to the relaxed one (NULL
     * otherwise). */
    void (*relaxation)(const double *p, double *g_inf, double *tau);
    /* NULL, or the key of the first bad parameter with a sentence in msg. */
    const char *(*check)(const double *p, char *msg, size_t len);
    /* As tf_material_eval (W already NaN; C and W may be NULL). */
    int (*eval)(const double *p, const double F[9], double dt, const double *hold, double *hnew,
                double S[6], double C[36], double *W);
} tf_law_ops;

/* A material: a law and its parameter values (p[i] for law->params[i]). */
typedef struct tf_material {
    const tf_law_ops *law;
    double p[TF_MATERIAL_MAX_PARAMS];
} tf_material;

/* Results of tf_material_eval. */
enum { TF_MAT_OK = 0, TF_MAT_INVERTED = 1 };

/* ---- registry (registry.c) ------------------------------------------------ */

size_t tf_law_count(void);
const tf_law_ops *tf_law_at(size_t i);
/* The law registered under name, or NULL. */
const tf_law_ops *tf_law_find(const char *name);
/* The law of a scene that names none: the first registered, "linear". */
const tf_law_ops *tf_law_default(void);
/* "linear, svk, ...": every registered name, for messages. */
void tf_law_names(char *out, size_t outlen);
/* Every parameter key of the registered laws, each once, in the order the
 * laws and their parameters are listed ("E, nu, k1, ..."). */
size_t tf_law_key_count(void);
const char *tf_law_key_at(size_t i);

/* ---- a material's parameters ---------------------------------------------- */

/* The index of key among law's parameters, or -1. */
int tf_law_param_index(const tf_law_ops *law, const char *key);
/* "E and nu": the keys of law's parameters (required: those without a
 * fallback only), for messages. */
void tf_law_param_list(const tf_law_ops *law, int required, char *out, size_t outlen);

/* law with every parameter at its fallback (NaN for those that must be
 * given). */
tf_material tf_material_of(const tf_law_ops *law);
/* Sets parameter key; returns 0, or -1 when the law has none of that name. */
int tf_material_set(tf_material *m, const char *key, double v);
/* The value of parameter key, or NaN when the law has none of that name. */
double tf_material_get(const tf_material *m, const char *key);

/* ---- what a solver asks --------------------------------------------------- */

const char *tf_material_name(const tf_material *m);
unsigned tf_material_caps(const tf_material *m);
/* HOOKE at small strain: the response is linear in the load (a linear
 * solver factorises once; the Galerkin solvers hand any other material to
 * Newton's method). */
int tf_material_linear_elastic(const tf_material *m);
/* Whether m can be a material region (problem/inclusions.h) of a body of
 * material body in one solve: NULL, or why not (a static string).  The
 * body's law, or another of the same kinematics and volume measure (the
 * Newton solvers' constants) when the body's law is not linear elastic
 * (a linear elastic body is solved by the linear solvers, which take
 * linear elastic regions only). */
const char *tf_material_region_misfit(const tf_material *body, const tf_material *m);
tf_kinematics tf_material_kinematics(const tf_material *m);
tf_volume_measure tf_material_volume(const tf_material *m);
size_t tf_material_history_size(const tf_material *m);
void tf_material_history_init(const tf_material *m, double *h);
/* The small-strain moduli of the initial response (tf_law_ops.moduli), and
 * their Lame constants. */
void tf_material_moduli(const tf_material *m, double *young, double *poisson);
tf_lame tf_material_lame(const tf_material *m);
/* g_inf and tau of the relaxation function; 1 and infinity for a material
 * without HISTORY. */
void tf_material_relaxation(const tf_material *m, double *g_inf, double *tau);

/* Checks the parameters the law uses (finite, in range, consistent).
 * Returns NULL, or the key of the first bad one with a sentence in msg for
 * the caller to prefix with file, line and field. */
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

/* Factors of the exact one-step update of a hereditary integral with
 * kernel exp(-t/tau) over a step of x = dt/tau in which the driving
 * quantity is linear (phi1) or has a quadratic part (phi2) in time:
 * decay = exp(-x), phi1 = (1 - exp(-x))/x, phi2 = (x - 1 + exp(-x))/x^2,
 * with their limits 1 and 1/2 at x = 0 (kelvin.c). */
void tf_relax_factors(double x, double *decay, double *phi1, double *phi2);

#endif /* TF_MATERIAL_H */
