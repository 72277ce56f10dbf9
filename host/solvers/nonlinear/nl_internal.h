/*
 * nl_internal.h — the nonlinear Galerkin solver's state, shared by the files
 * of this folder (nonlinear.h is the public part).
 *
 * Total Lagrangian: the unknowns d are nodal displacements (RPIM) or nodal
 * parameters (EFG) in the reference configuration; shape-function gradients
 * at every Gauss point are computed once and kept per background cell.  A
 * state is d, every point's material history, and the target (load factor,
 * contact force) it is in equilibrium with.
 */
#ifndef TF_NL_INTERNAL_H
#define TF_NL_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "materials/elasticity.h"
#include "meshfree/shape.h"
#include "solvers/boundary.h"
#include "solvers/cholmod_solve.h"
#include "solvers/constraints.h"
#include "solvers/nodal_values.h"
#include "solvers/solver.h"
#include "solvers/sparsity.h"

/* What loads the body: the problem's loads and prescribed displacements
 * times scale, and a force at one contact site (contact -1: none). */
typedef struct nl_target {
    double scale;
    int contact;
    double force[3];
} nl_target;

/* Where an evaluation failed (J <= 0 at a point). */
typedef struct nl_fault {
    int inverted;
    double x[3], j;
} nl_fault;

/* Counters for the report and the benchmark. */
typedef struct nl_stats {
    size_t steps, cuts, iterations, residuals, tangents, factorisations, krylov, indefinite;
    size_t kept; /* tangents found not positive definite while an older factor was kept */
    size_t patches, patch_kept; /* patch tangent updates; of them, not positive definite */
    size_t shifted;             /* factorisations of a shifted tangent (nl_linear.c) */
    double t_residual, t_tangent, t_factor, t_solve, t_patch;
} nl_stats;

/* The patch tangent (nl_patch.c): the m DOFs A within the patch radius of
 * a contact site come last in the factor, whose trailing block L_AA is
 * replaced every iteration by chol(S0 + K_t,AA - K0,AA), S0 = L_AA0
 * L_AA0^T of the last full factorisation (of K0), K_t,AA and K0,AA the
 * tangents of the patch's cells alone. */
typedef struct nl_patch {
    int on;              /* the strategy is patch and it applies to this problem */
    size_t m;            /* |A| */
    unsigned char *dof;  /* 3N: in A */
    unsigned char *cell; /* per cell: its support holds a node of A */
    uint32_t *list;      /* A's DOFs, in the factor's order (once a base is set) */
    int *pos;            /* 3N: position in A's block, or -1 */
    double *s0, *k0, *w; /* m x m: S0, K0's AA block, work (lower triangles) */
    int base;            /* s0, k0, list belong to the factor in s->chol */
    int want_k0;         /* a new base factor: k0 at its state still to assemble */
    size_t fallbacks;    /* factors whose last supernode did not hold A: BFGS instead */
} nl_patch;

typedef struct nl_solver {
    tf_solver base; /* first */
    tf_shape sh;
    int shape_ok, efg, weak, small, bbar, vci, unsym;
    /* The materials: mats[0] the body's; with material regions
     * (problem/inclusions.h) mats[1 + k] inclusion k's, of the body's law; pmat (per cell point) and bmat (per boundary point)
     * the index of each point's material, NULL when the body is one material. */
    tf_material mats[1 + TF_INCLUSIONS_MAX];
    double lambda_m[1 + TF_INCLUSIONS_MAX]; /* each material's lambda_v */
    size_t n_mats;
    int vol_corr;       /* some material's lambda_v is not 0 */
    unsigned char *pmat, *bmat;
    tf_lame lin;        /* small-strain moduli of the initial response (the body's) */
    double lambda_v;    /* modulus of the volumetric correction (B-bar for finite strain) */
    int trace_volume;   /* the correction's volume measure is tr E (TF_VOLUME_GREEN_TRACE),
                         * else J - 1 */
    int relaxes;        /* time-dependent law (TF_MATERIAL_HISTORY) */
    /* each material's relaxation function g(t) = g_inf + (1 - g_inf) e^(-t/tau) */
    double g_inf[1 + TF_INCLUSIONS_MAX], tau[1 + TF_INCLUSIONS_MAX];
    size_t nh, hb;      /* material history per point; history block per point */
    double dt_relaxed;  /* a time step after which a time-dependent law is relaxed */
    /* cells */
    size_t ncell, np;
    tf_nodesets cs, bp;
    size_t *gptr;       /* cell c's gradients at grad + gptr[c]: np x 3 x m */
    double *grad;
    double *wts;        /* np weights per cell */
    size_t maxm;
    tf_csc k;           /* tangent (its symmetric part), lower triangle */
    double *kskew;      /* unsymmetric tangents: the skew part below the diagonal */
    double *kbc;        /* weak boundary terms' constant part (penalty, beta), k's pattern */
    tf_csc kf;          /* what CHOLMOD factorises: k without the fixed DOFs' couplings */
    size_t *kf_at;      /* kf's entry q is k's entry kf_at[q] (NULL: kf is k, weak BCs) */
    /* state */
    double *d;          /* 3N */
    double *hist, *hist_new; /* hb per Gauss point */
    double *bhist, *bhist_new; /* nh per boundary point (Nitsche) */
    nl_target at;
    /* boundary and loads */
    tf_boundary bnd;
    size_t *bptr;       /* boundary point q's support: bidx[bptr[q] ..], values and gradients */
    uint32_t *bidx;
    double *bphi, *bdphi;
    double bc_factor;   /* alpha or beta, MPa/mm */
    tf_constraints bc;  /* RPIM elimination */
    tf_nodal_map map;   /* EFG */
    double *f0, *basis; /* loads (3N), unit contact columns (3 x 3N per site) */
    /* linear algebra */
    tf_chol *chol;      /* Cholesky of the tangent */
    tf_chol *spare;     /* a second Cholesky handle (nl_linear.c: keeps_factor) */
    tf_chol *ldl;       /* LDL^T, when the tangent is not positive definite */
    int indef_kept;     /* the last tangent was not positive definite: an older factor kept */
    int eager;          /* a load step of this case failed: BFGS refreshes sooner */
    int chol_ok;        /* holds a usable factor */
    int k_rest;         /* s->k was last assembled at rest: d = 0, zero histories, dt_relaxed */
    int chol_rest;      /* s->chol holds the Cholesky factor of that rest tangent */
    int rest_factor;    /* that factor is kept for the case's first iteration, as if just made */
    int rest_guess;     /* BFGS from a guess on that factor, no other made since (nl_newton.c) */
    int use_ldl;        /* the usable factor is the LDL^T one */
    double shift;       /* the last positive definite shift (indefinite: shift), 0: none yet */
    int shifted;        /* the usable factor is of a shifted tangent */
    tf_chol_info ci;
    nl_patch patch;
    /* quasi-Newton (BFGS): pairs s_i = dd, y_i = dr since the last factorisation */
    double *qs, *qy, *qrho;
    size_t qn, qmax;
    /* work */
    double *r, *fint, *du, *dtrial, *rtrial, *wk; /* 3N each; wk: Krylov space */
    size_t wk_cols;
    nl_stats st;
    double t_setup_shape;
} nl_solver;

/* The material of cell point p (c np + its index) and of boundary point q. */
static inline unsigned nl_point_mat(const nl_solver *s, size_t p)
{
    return s->pmat ? s->pmat[p] : 0u;
}
static inline unsigned nl_bpoint_mat(const nl_solver *s, size_t q)
{
    return s->bmat ? s->bmat[q] : 0u;
}

/* ---- nl_model.c: cells, gradients, pattern, loads ---- */
int nl_model_build(nl_solver *s, const tf_problem *p, tf_ctx *ctx);
void nl_model_free(nl_solver *s);

/* ---- nl_assemble.c ---- */
/* Internal forces (plus the weak boundary terms) at d reached over dt
 * under target t into r (3N), the body's internal forces alone into fint
 * (may be NULL), and, when tangent, the tangent into s->k (and s->kskew);
 * new histories into s->hist_new, s->bhist_new.  Returns 0; 1 when a point
 * inverts (fault filled); -1 with a message in ctx. */
int nl_assemble(nl_solver *s, const double *d, const nl_target *t, double dt, int tangent,
                double *r, double *fint, nl_fault *fault);

/* The tangent on the patch's cells only (s->patch.cell) into s->k's
 * columns of the patch's DOFs, at d over dt (the cells' histories into
 * s->hist_new); the other columns keep what they held.  Returns as
 * nl_assemble. */
int nl_assemble_patch(nl_solver *s, const double *d, double dt, nl_fault *fault);

/* The support's force (N) on the body from fixed region `region` in the
 * committed state, weak essential conditions.  Returns 0, or -1. */
int nl_region_force(nl_solver *s, size_t region, double force[3]);

/* External forces of a target (3N). */
void nl_external(const nl_solver *s, const nl_target *t, double *f);

/* ---- nl_linear.c: the linear systems of Newton's method ---- */
/* Before a static case, after nl_reset: the factor its first iteration
 * uses.  Where nothing prescribed differs from 0 and the strategy uses the
 * factor alone (BFGS, modified Newton, a symmetric tangent), that is the
 * factor of the rest tangent (nl_reset's state at the relaxed time step),
 * the same bits for every case: kept from an earlier case, or made here
 * for a case that starts from a guess (from_rest 0), or left to the case's
 * first iteration from rest.  Otherwise none (the case factorises its
 * first tangent).  Returns 0, or -1 with a message. */
int nl_factor_for_rest(nl_solver *s, int from_rest);
/* Prepares the factorisation of the current s->k (after elimination rows
 * are set).  Returns 0, 1 (not positive definite), -1 (message). */
int nl_factor(nl_solver *s);
/* Solves K du = -r with the strategy of the options; refactorises when the
 * strategy says so.  Returns 0, 1 (no usable factor: the tangent is not
 * positive definite), -1 (message). */
int nl_linear_solve(nl_solver *s, const double *r, double *du, int fresh_tangent);
/* fresh_tangent: NL_TANGENT_NONE, _ALL or _PATCH (the patch's block only). */
/* Quasi-Newton: forget the pairs (a new factorisation), or remember the
 * step s and the residual's change y of an iteration. */
void nl_qn_reset(nl_solver *s);
void nl_qn_update(nl_solver *s, const double *step, const double *dr);
/* y = K x with the assembled tangent (symmetric part + skew part). */
void nl_tangent_apply(const nl_solver *s, const double *x, double *y);

/* Fixed DOFs (direct elimination): unit rows and columns of s->k. */
void nl_eliminate(nl_solver *s);
/* The eliminated tangent as CHOLMOD factorises it (nl_linear.c): k's values
 * gathered into kf's pattern, or k itself. */
const tf_csc *nl_factored(nl_solver *s);

/* ---- nl_stability.c ---- */
/* tf_nonlinear_stability_of on the solver's current state. */
struct tf_nonlinear_stability; /* nonlinear.h; not included: nonlinear.c includes us */
int nl_stability(nl_solver *s, double tol, struct tf_nonlinear_stability *out);

/* ---- nl_patch.c: the patch tangent ---- */
/* What a Newton iteration assembles: nothing new, the whole tangent, or
 * the tangent on the patch's cells (nl_assemble_patch). */
enum { NL_TANGENT_NONE = 0, NL_TANGENT_ALL = 1, NL_TANGENT_PATCH = 2 };
/* Chooses A and its cells when the strategy is patch and the problem
 * allows it (a symmetric, time-independent law with the fixed DOFs
 * eliminated); else leaves the patch off (BFGS).  Returns 0, or -1. */
int nl_patch_init(nl_solver *s);
void nl_patch_free(nl_patch *p);
/* After a full Cholesky factorisation of s->k into s->chol: S0 from it
 * (then want_k0: nl_patch_k0 at the state of that tangent); a factor whose
 * last supernode does not hold A turns the patch off (counted).  Returns 0,
 * or -1. */
int nl_patch_base(nl_solver *s);
/* K0's block: the patch cells' tangent at d (the base's state) over dt,
 * through s->k.  Returns as nl_assemble. */
int nl_patch_k0(nl_solver *s, const double *d, double dt, nl_fault *fault);
/* The factor's trailing block for the patch tangent now in s->k's AA
 * block.  Returns 0; 1 when S0 + dK is not positive definite (the factor
 * is unchanged). */
int nl_patch_update(nl_solver *s);

/* ---- nl_newton.c ---- */
/* Equilibrium under target `to`, reached from the current state over dt
 * seconds (dt < 0: every step relaxed, the Kelvin laws' static
 * equilibrium), with load stepping and cuts; commits the state.  Returns
 * 0, or -1 with a message naming the step, the force and the place. */
int nl_advance(nl_solver *s, const nl_target *to, double dt);
/* The rest state (zero displacements and histories, zero load). */
void nl_reset(nl_solver *s);
/* One Newton solve at target t from the current d (a starting guess), no
 * stepping; commits on success.  Returns 0, 1 (did not converge: d is then
 * some iterate), -1.  dt < 0: relaxed, as in nl_advance. */
int nl_polish(nl_solver *s, const nl_target *t, double dt);

#endif /* TF_NL_INTERNAL_H */
