/*
 * solver.c — the solver interface's entry points (solver.h): argument checks
 * every implementation shares, solve statistics, and the static history of
 * a solver that is not time-dependent.
 */
#include "solvers/solver.h"

#include <omp.h>
#include <stdio.h>
#include <string.h>

#include "base/log.h"

tf_solver *tf_solver_create(const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx)
{
    if (o == NULL) {
        o = &p->solver;
    }
    const tf_solver_ops *type = tf_solver_type_find(o->method);
    if (type == NULL) {
        char names[256];
        tf_solver_type_names(names, sizeof names);
        tf_fail(ctx, "no solver '%s' (the solvers are: %s)", o->method, names);
        return NULL;
    }
    return tf_solver_create_as(type, p, o, ctx);
}

tf_solver *tf_solver_create_as(const tf_solver_ops *type, const tf_problem *p,
                               const tf_solver_opts *o, tf_ctx *ctx)
{
    if (o == NULL) {
        o = &p->solver;
    }
    /* A scene asking for elimination with such a type is refused where it
     * is read (scene_build.c); options made for another type (the
     * conformance suite's) get its own way of holding the fixed regions. */
    tf_solver_opts weak = *o;
    if (type->weak_bc && o->bc == TF_BC_ELIMINATION) {
        weak.bc = TF_BC_NITSCHE;
        o = &weak;
        tf_info(ctx, "%s: %s holds the fixed regions by Nitsche's method (its shape functions "
                     "do not interpolate: nothing can be eliminated)", p->name, type->name);
    }
    double t0 = omp_get_wtime();
    tf_solver *s = type->create(p, o, ctx);
    if (s == NULL) {
        return NULL;
    }
    if (s->ops == NULL) { /* (a type may hand over to another implementation) */
        s->ops = type;
    }
    s->problem = p;
    if (s->opts.method[0] == '\0') { /* (an implementation may resolve an option: keep its) */
        s->opts = *o;
    }
    s->ctx = ctx;
    /* The implementation's capabilities, not the type's: rpim-galerkin and
     * efg-galerkin hand a nonlinear law over to the Newton solvers, which
     * have no cuts. */
    if (p->n_cuts > 0 && !(s->ops->caps(s) & TF_SOLVER_CUTS)) {
        tf_fail(ctx, "%s: solver %s (%s) does not support cuts (remove cuts: or choose a solver "
                "with the CUTS capability)", p->source, s->ops->name, s->ops->summary);
        s->ops->destroy(s);
        return NULL;
    }
    if (s->info.t_setup == 0) {
        s->info.t_setup = omp_get_wtime() - t0;
    }
    return s;
}

void tf_solver_destroy(tf_solver *s)
{
    if (s != NULL) {
        s->ops->destroy(s);
    }
}

unsigned tf_solver_caps_of(const tf_solver *s) { return s->ops->caps(s); }
const char *tf_solver_name(const tf_solver *s) { return s->ops->name; }
size_t tf_solver_node_count(const tf_solver *s) { return s->ops->node_count(s); }
const double *tf_solver_coords(const tf_solver *s) { return s->ops->coords(s); }
const tf_solver_info *tf_solver_info_of(const tf_solver *s) { return &s->info; }
void tf_solver_report(const tf_solver *s) { s->ops->report(s); }

/* A contact index the problem has, with forces when it is not -1. */
static int check_contact(const tf_solver *s, int contact, const void *forces)
{
    if (contact < -1 || contact >= (int)s->problem->n_contacts ||
        (contact >= 0 && forces == NULL)) {
        return tf_fail(s->ctx, "no contact site %d in %s", contact, s->problem->name);
    }
    return 0;
}

int tf_solver_solve(tf_solver *s, int contact, const double (*forces)[3], size_t n,
                    const double *u0, double *u)
{
    if (check_contact(s, contact, forces) != 0) {
        return -1;
    }
    if (n == 0) {
        return 0;
    }
    double t0 = omp_get_wtime();
    int rc = s->ops->solve(s, contact, forces, n, u0, u);
    s->info.t_solve += omp_get_wtime() - t0;
    s->info.solves += rc == 0 ? n : 0;
    return rc;
}

/* Static steps: one batch when the response is affine (no step depends on
 * another), else step by step, each from the one before. */
static int static_history(tf_solver *s, int contact, const double (*forces)[3], size_t n,
                          double *u)
{
    if (s->ops->caps(s) & TF_SOLVER_AFFINE) {
        return tf_solver_solve(s, contact, forces, n, NULL, u);
    }
    const size_t dofs = 3 * tf_solver_node_count(s);
    for (size_t k = 0; k < n; ++k) {
        const double *start = k > 0 ? u + (k - 1) * dofs : NULL;
        if (tf_solver_solve(s, contact, forces ? forces + k : NULL, 1, start, u + k * dofs) != 0) {
            return -1;
        }
    }
    return 0;
}

int tf_solver_history(tf_solver *s, int contact, const double (*forces)[3], size_t n, double dt,
                      double *u)
{
    if (check_contact(s, contact, forces) != 0) {
        return -1;
    }
    if (!(dt > 0)) {
        return tf_fail(s->ctx, "a load history needs a positive time step (got %g s)", dt);
    }
    if (!(s->ops->caps(s) & TF_SOLVER_TIME_DEPENDENT)) {
        return static_history(s, contact, forces, n, u);
    }
    if (s->ops->history == NULL) {
        return tf_fail(s->ctx, "solver %s declares itself time-dependent but solves no history",
                       s->ops->name);
    }
    double t0 = omp_get_wtime();
    int rc = s->ops->history(s, contact, forces, n, dt, u);
    s->info.t_solve += omp_get_wtime() - t0;
    s->info.solves += rc == 0 ? n : 0;
    return rc;
}

int tf_solver_reactions(const tf_solver *s, int contact, const double force[3], const double *u,
                        double *r)
{
    if (s->ops->reactions == NULL) {
        return tf_fail(s->ctx, "solver %s gives no reactions", s->ops->name);
    }
    if (check_contact(s, contact, force) != 0) {
        return -1;
    }
    return s->ops->reactions(s, contact, force, u, r);
}

int tf_solver_field(tf_ctx *ctx, const tf_solver *s, const double *u, const double *x, size_t np,
                    double *uh, double *grad)
{
    if (s->ops->field == NULL) {
        return tf_fail(ctx, "solver %s gives no displacement field between its nodes",
                       s->ops->name);
    }
    return s->ops->field(ctx, s, u, x, np, uh, grad);
}

int tf_solver_has_field(const tf_solver *s)
{
    return s->ops->field != NULL;
}

int tf_solver_patch_loads(tf_ctx *ctx, const tf_solver *s, const tf_patch *p, double *f)
{
    if (s->ops->patch_loads == NULL) {
        return tf_fail(ctx,
                       "solver %s gives no load vectors whose product with its displacements "
                       "is a patch average (a contact region needs rpim-galerkin)",
                       s->ops->name);
    }
    return s->ops->patch_loads(ctx, s, p, f);
}

int tf_solver_solve_loads(tf_solver *s, const double *f, size_t n, double *u)
{
    if (s->ops->solve_loads == NULL) {
        return tf_fail(s->ctx, "solver %s solves no arbitrary load vectors (it keeps no "
                       "factorisation: its response is not affine)", s->ops->name);
    }
    if (n == 0) {
        return 0;
    }
    double t0 = omp_get_wtime();
    int rc = s->ops->solve_loads(s, f, n, u);
    s->info.t_solve += omp_get_wtime() - t0;
    s->info.solves += rc == 0 ? n : 0;
    return rc;
}
