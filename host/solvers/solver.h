/*
 * solver.h — the solver interface: a problem in, displacements out.
 *
 * A solver is a table of operations (tf_solver_ops, in the style of a vtable
 * or CHOLMOD's common object) and an instance that begins with struct
 * tf_solver.  The registry (registry.c) lists every solver type by name; a
 * problem's solver options name the one to use (scene key solver.method).
 * Callers use only the tf_solver_* functions below, which check the
 * arguments every implementation shares and keep the solve statistics.
 *
 * Loads: every solve applies the problem's loads plus, at one contact site
 * (0 .. n_contacts - 1), a force per load case, spread as the site's patch
 * says; contact -1 applies the problem's loads only (forces may be NULL).
 * Displacements are per node index (problem.h numbering), DOF 3 i + a =
 * component a of node i, in mm; a batch of n cases is 3N x n, column major.
 *
 * Capabilities (tf_solver_caps) tell a caller what it may assume:
 *   AFFINE          u(f) = u(0) + L f in the contact force f, so unit solves
 *                   superpose into any case (the fitting pipeline relies on
 *                   it only when this is declared);
 *   LINEAR          affine with u(0) = 0 (no load always acts, every
 *                   prescribed displacement is zero);
 *   TIME_DEPENDENT  the response depends on the force history: use
 *                   tf_solver_history; tf_solver_solve gives the equilibrium
 *                   under a force held for ever (fully relaxed);
 *   CUTS            the solver supports cuts (topology changes) of its body.
 *
 * Errors: a function returns non-zero (or NULL) with the message in the
 * context's error buffer (base/context.h).  Messages and progress go to the
 * context's log; the context must outlive the solver.
 */
#ifndef TF_SOLVER_H
#define TF_SOLVER_H

#include <stddef.h>

#include "base/context.h"
#include "problem/problem.h"

typedef enum tf_solver_caps {
    TF_SOLVER_AFFINE = 1u << 0,
    TF_SOLVER_LINEAR = 1u << 1,
    TF_SOLVER_TIME_DEPENDENT = 1u << 2,
    TF_SOLVER_CUTS = 1u << 3,
} tf_solver_caps;

/* What every solver reports about itself. */
typedef struct tf_solver_info {
    size_t nodes, dofs;
    size_t unknowns;   /* size of the system actually solved */
    double t_setup;    /* s, wall: building (assembly, factorisation) */
    double t_solve;    /* s, wall: every solve so far */
    size_t solves;     /* load cases (or history steps) solved so far */
} tf_solver_info;

typedef struct tf_solver tf_solver;

typedef struct tf_solver_ops {
    const char *name;    /* the scene's solver.method */
    const char *summary; /* one line: method, materials, what it assumes */
    /* Its shape functions do not interpolate, so it holds the fixed regions
     * in weak form: a scene's solver.bc defaults to nitsche and refuses
     * elimination, and options asking for elimination (made for another
     * type) get Nitsche's method. */
    int weak_bc;
    /* Builds a solver of the problem (which must outlive it) with these
     * options; NULL with a message in ctx->err.  tf_solver_create fills
     * the instance's struct tf_solver (problem, ctx, and ops and opts
     * unless the implementation set them: a type may hand a problem to
     * another registered type, as the Galerkin solvers hand every material
     * but a linear elastic one to the Newton solvers, and resolve an
     * option) after this returns; the implementation fills its info. */
    tf_solver *(*create)(const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx);
    unsigned (*caps)(const tf_solver *s);
    /* n static load cases at one contact site (arguments already checked);
     * u0: NULL or a starting displacement per case (3N x n), which a
     * nonlinear solver continues from and a linear one ignores. */
    int (*solve)(tf_solver *s, int contact, const double (*forces)[3], size_t n,
                 const double *u0, double *u);
    /* A force history at steps of dt seconds into a displacement history
     * (3N x n); NULL for a solver that is not time-dependent (then
     * tf_solver_history solves each step statically). */
    int (*history)(tf_solver *s, int contact, const double (*forces)[3], size_t n, double dt,
                   double *u);
    /* r = K u - f for a displacement solved with (contact, force): at a fixed
     * DOF the reaction of the support (N), elsewhere the residual.  NULL
     * when the solver has no reactions. */
    int (*reactions)(const tf_solver *s, int contact, const double force[3], const double *u,
                     double *r);
    /* The displacement field of nodal values u at np points x (3 np):
     * uh (3 np) and its gradient grad (9 np, row-major du_i/dx_j per point).
     * Callable from several threads at once, each passing a context of its
     * own (base/context.h): a failure's message goes to that ctx, not the
     * solver's.  NULL when not available. */
    int (*field)(tf_ctx *ctx, const tf_solver *s, const double *u, const double *x, size_t np,
                 double *uh, double *grad);
    size_t (*node_count)(const tf_solver *s);
    const double *(*coords)(const tf_solver *s); /* 3 per node, mm */
    /* The time split and any warnings, through the context's log. */
    void (*report)(const tf_solver *s);
    void (*destroy)(tf_solver *s);
    /* Loads anywhere (contact regions: a probe's patch at any site).  The
     * three unit-force load vectors of a patch (3N x 3, column a: 1 N along
     * axis a spread as a uniform traction over it), overwriting f, such
     * that f^T u of a displacement u this solver returns is the patch's
     * average displacement (the work-conjugate of the force: the returned
     * displacements are the unknowns the vectors weight).  Callable from
     * several threads at once, each with its own context.  NULL when not
     * available. */
    int (*patch_loads)(tf_ctx *ctx, const tf_solver *s, const tf_patch *p, double *f);
    /* n nodal load vectors f (3N x n), each added to the problem's loads,
     * into displacements u (3N x n) through the factorisation the solver
     * holds.  NULL for a solver that does not keep one (not affine). */
    int (*solve_loads)(tf_solver *s, const double *f, size_t n, double *u);
} tf_solver_ops;

/* The part every instance shares (an implementation's struct starts with
 * it); read-only outside solver.c. */
struct tf_solver {
    const tf_solver_ops *ops;
    const tf_problem *problem;
    tf_solver_opts opts; /* the options it was built with */
    tf_ctx *ctx;
    tf_solver_info info;
};

/* ---- registry (registry.c) ---------------------------------------------- */

size_t tf_solver_type_count(void);
const tf_solver_ops *tf_solver_type_at(size_t i);
/* The type registered under name, or NULL. */
const tf_solver_ops *tf_solver_type_find(const char *name);
/* "rpim-galerkin, ...": every registered name, for messages. */
void tf_solver_type_names(char *out, size_t outlen);

/* ---- use ----------------------------------------------------------------- */

/* The solver the options name (NULL options: the problem's own).  Returns
 * NULL with a message in ctx->err. */
tf_solver *tf_solver_create(const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx);

/* The same with a given type, registered or not (a test's variant of one);
 * type must outlive the solver. */
tf_solver *tf_solver_create_as(const tf_solver_ops *type, const tf_problem *p,
                               const tf_solver_opts *o, tf_ctx *ctx);
void tf_solver_destroy(tf_solver *s);

unsigned tf_solver_caps_of(const tf_solver *s);
const char *tf_solver_name(const tf_solver *s);

/* n static load cases (forces[n][3] at site contact, or contact -1 and
 * forces NULL), optional starting displacements u0 (3N x n or NULL), into
 * u (3N x n).  Returns 0, or -1 with a message. */
int tf_solver_solve(tf_solver *s, int contact, const double (*forces)[3], size_t n,
                    const double *u0, double *u);

/* A force history (n steps of dt seconds) into displacements u (3N x n).
 * A solver that is not time-dependent solves each step statically, each
 * from the previous step's displacement.  Returns 0, or -1. */
int tf_solver_history(tf_solver *s, int contact, const double (*forces)[3], size_t n, double dt,
                      double *u);

/* Reactions and residual (see tf_solver_ops.reactions).  Returns 0, or -1
 * (no reactions from this solver, a bad contact index, out of memory). */
int tf_solver_reactions(const tf_solver *s, int contact, const double force[3], const double *u,
                        double *r);

/* The displacement field at points (see tf_solver_ops.field; thread-safe
 * with a context per thread, the message in ctx->err).  Returns 0, or -1
 * (no field from this solver, a failed evaluation). */
int tf_solver_field(tf_ctx *ctx, const tf_solver *s, const double *u, const double *x, size_t np,
                    double *uh, double *grad);

/* 1 when tf_solver_field can evaluate this solver's field between nodes. */
int tf_solver_has_field(const tf_solver *s);

/* A patch's unit-force load vectors (see tf_solver_ops.patch_loads;
 * thread-safe with a context per thread).  Returns 0, or -1 (not available
 * from this solver, a failed evaluation). */
int tf_solver_patch_loads(tf_ctx *ctx, const tf_solver *s, const tf_patch *p, double *f);

/* n nodal load vectors (3N x n) into displacements u (3N x n) (see
 * tf_solver_ops.solve_loads).  Returns 0, or -1 with a message. */
int tf_solver_solve_loads(tf_solver *s, const double *f, size_t n, double *u);

size_t tf_solver_node_count(const tf_solver *s);
const double *tf_solver_coords(const tf_solver *s);
const tf_solver_info *tf_solver_info_of(const tf_solver *s);
void tf_solver_report(const tf_solver *s);

#endif /* TF_SOLVER_H */
