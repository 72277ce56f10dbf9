/*
 * nonlinear.c — the nonlinear Galerkin solver behind the solver interface
 * (nonlinear.h).
 */
#include "solvers/nonlinear/nonlinear.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/log.h"
#include "base/peak_memory.h"
#include "meshfree/quadrature.h"
#include "solvers/field.h"
#include "solvers/nonlinear/nl_internal.h"

static nl_solver *of(tf_solver *s) { return (nl_solver *)s; }
static const nl_solver *of_const(const tf_solver *s) { return (const nl_solver *)s; }

static void destroy(tf_solver *s)
{
    nl_model_free(of(s));
    free(s);
}

static unsigned caps(const tf_solver *s)
{
    return of_const(s)->relaxes ? TF_SOLVER_TIME_DEPENDENT : 0u;
}

/* The current state's nodal displacements. */
static void outputs(nl_solver *s, double *u)
{
    if (s->efg) {
        tf_nodal_map_values(&s->map, s->d, u, 1);
    } else {
        memcpy(u, s->d, 3 * s->sh.cloud->n * sizeof *u);
    }
}

/* d from nodal displacements u (EFG: through Lambda^-1). */
static int start_from(nl_solver *s, const double *u)
{
    size_t n3 = 3 * s->sh.cloud->n;
    if (!s->efg) {
        memcpy(s->d, u, n3 * sizeof *u);
        return 0;
    }
    const double *d = tf_nodal_map_params_of(s->base.ctx, &s->map, u);
    if (d == NULL) {
        return -1;
    }
    memcpy(s->d, d, n3 * sizeof *d);
    return 0;
}

static int solve(tf_solver *sv, int contact, const double (*forces)[3], size_t n,
                 const double *u0, double *u)
{
    nl_solver *s = of(sv);
    size_t n3 = 3 * s->sh.cloud->n;
    for (size_t k = 0; k < n; ++k) {
        nl_target to = {1, contact, {0, 0, 0}};
        if (contact >= 0) {
            memcpy(to.force, forces[k], sizeof to.force);
        }
        nl_reset(s);
        /* and no factorisation but the rest tangent's (nl_factor_for_rest):
         * the case then depends on its own start alone, not on the cases
         * this solver solved before (modified Newton and BFGS keep factors
         * across iterations), so the bits are the same whatever the order
         * of the cases (the MPI runner's partition; check-mpi).  From a
         * guess, BFGS from the rest tangent's factor instead of a tangent
         * assembled and factorised at the guess: on the liver in
         * neo-Hookean tissue those took 12 of a case's 15 s */
        if (nl_factor_for_rest(s, u0 == NULL) != 0) {
            return -1;
        }
        int rc = 1;
        if (u0 != NULL) { /* continue from the caller's guess, at the full load */
            if (start_from(s, u0 + k * n3) != 0) {
                return -1;
            }
            rc = nl_polish(s, &to, -1);
            if (rc < 0) {
                return -1;
            }
            if (rc == 1) { /* from rest, with no factor of the start that failed */
                nl_reset(s);
                s->chol_ok = 0;
            }
        }
        if (rc == 1 && nl_advance(s, &to, -1) != 0) {
            return -1;
        }
        outputs(s, u + k * n3);
    }
    return 0;
}

static int history(tf_solver *sv, int contact, const double (*forces)[3], size_t n, double dt,
                   double *u)
{
    nl_solver *s = of(sv);
    size_t n3 = 3 * s->sh.cloud->n;
    nl_reset(s);
    for (size_t k = 0; k < n; ++k) {
        nl_target to = {1, contact, {0, 0, 0}};
        if (contact >= 0) {
            memcpy(to.force, forces[k], sizeof to.force);
        }
        if (nl_advance(s, &to, dt) != 0) {
            return -1;
        }
        outputs(s, u + k * n3);
    }
    return 0;
}

/* r = internal forces - loads, at the current histories, relaxed for a
 * time-dependent law (the state a static solve leaves). */
static int reactions(const tf_solver *sv, int contact, const double force[3], const double *u,
                     double *r)
{
    nl_solver *s = (nl_solver *)of_const(sv);
    size_t n3 = 3 * s->sh.cloud->n;
    double *save = malloc(n3 * sizeof *save), *fext = malloc(n3 * sizeof *fext);
    if (save == NULL || fext == NULL) {
        free(save);
        free(fext);
        return tf_fail(sv->ctx, "out of memory");
    }
    memcpy(save, s->d, n3 * sizeof *save);
    nl_target t = {1, contact, {0, 0, 0}};
    if (contact >= 0) {
        memcpy(t.force, force, sizeof t.force);
    }
    nl_fault f = {0};
    int rc = start_from(s, u);
    if (rc == 0) {
        double *tmp = malloc(n3 * sizeof *tmp);
        rc = tmp ? nl_assemble(s, s->d, &t, s->relaxes ? s->dt_relaxed : 0, 0, tmp, r, &f) : -1;
        free(tmp);
        if (rc == 1) {
            rc = tf_fail(sv->ctx, "J = %g <= 0 at (%g, %g, %g) mm", f.j, f.x[0], f.x[1], f.x[2]);
        }
    }
    nl_external(s, &t, fext);
    for (size_t i = 0; rc == 0 && i < n3; ++i) {
        r[i] -= fext[i];
    }
    memcpy(s->d, save, n3 * sizeof *save);
    free(save);
    free(fext);
    return rc;
}

static int field(tf_ctx *ctx, const tf_solver *sv, const double *u, const double *x, size_t np,
                 double *uh, double *grad)
{
    nl_solver *s = (nl_solver *)of_const(sv);
    return tf_nodal_field(ctx, &s->sh, s->efg ? &s->map : NULL, u, x, np, uh, grad);
}

static size_t node_count(const tf_solver *s) { return s->problem->cloud.n; }
static const double *coords(const tf_solver *s) { return s->problem->cloud.xyz; }

static void report(const tf_solver *sv)
{
    const nl_solver *s = of_const(sv);
    const nl_stats *st = &s->st;
    tf_info(sv->ctx,
            "solver: Newton: %zu load steps (%zu cuts), %zu iterations, %zu tangents, %zu "
            "residuals, %zu factorisations (%s, %.3g entries in L), %zu Krylov iterations",
            st->steps, st->cuts, st->iterations, st->tangents, st->residuals, st->factorisations,
            s->chol ? tf_chol_ordering(s->chol) : "-", s->ci.nnz_l, st->krylov);
    tf_info(sv->ctx,
            "solver: times (s): shape functions %.3f, residuals %.3f, tangents %.3f, "
            "factorisations %.3f, linear solves %.3f; peak memory %.0f MiB",
            s->t_setup_shape, st->t_residual, st->t_tangent, st->t_factor,
            st->t_solve - st->t_factor, tf_peak_mib());
}

static tf_solver *create_rpim(const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx)
{
    return tf_nonlinear_create(p, o, ctx, 0);
}

static tf_solver *create_efg(const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx)
{
    return tf_nonlinear_create(p, o, ctx, 1);
}

const tf_solver_ops tf_rpim_newton_ops = {
    .name = "rpim-newton",
    .summary = "RPIM Galerkin, total-Lagrangian Newton-Raphson for any law (rpim-galerkin "
               "hands it every law but the linear one)",
    .create = create_rpim,
    .caps = caps,
    .solve = solve,
    .history = history,
    .reactions = reactions,
    .field = field,
    .node_count = node_count,
    .coords = coords,
    .report = report,
    .destroy = destroy,
};

const tf_solver_ops tf_efg_newton_ops = {
    .name = "efg-newton",
    .summary = "EFG (MLS) Galerkin, total-Lagrangian Newton-Raphson for any law, weak "
               "essential conditions (efg-galerkin hands it every law but the linear one)",
    .weak_bc = 1,
    .create = create_efg,
    .caps = caps,
    .solve = solve,
    .history = history,
    .reactions = NULL, /* weak fixed regions (as tf_efg_galerkin_ops) */
    .field = field,
    .node_count = node_count,
    .coords = coords,
    .report = report,
    .destroy = destroy,
};

static int is_nonlinear(const tf_solver *s)
{
    return s->ops == &tf_rpim_newton_ops || s->ops == &tf_efg_newton_ops;
}

static void announce(const nl_solver *s, const tf_problem *p, tf_ctx *ctx)
{
    const tf_solver_opts *o = &s->base.opts;
    static const char *tangents[] = {"full Newton", "modified Newton", "Newton-Krylov",
                                    "quasi-Newton (BFGS)",
                                    "quasi-Newton (BFGS), the patch tangent where it applies"};
    char cells[96];
    tf_cells_describe(&s->sh.cells, cells, sizeof cells);
    tf_info(ctx,
            "solver: %s, %s law, %s kinematics, %zu nodes, %s%s, "
            "%s, volumetric %s, BCs by %s, %s",
            s->base.ops->name, tf_material_name(&p->material), s->small ? "small-strain" : "total-Lagrangian",
            p->cloud.n, cells, s->vci ? " (VCI)" : "",
            s->efg ? "MLS (EFG)" : "RPIM", s->bbar ? "averaged per cell" : "at every point",
            o->bc == TF_BC_NITSCHE   ? "Nitsche's method"
            : o->bc == TF_BC_PENALTY ? "penalty (weak form)"
                                     : "elimination",
            tangents[o->newton.tangent]);
}

tf_solver *tf_nonlinear_create(const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx,
                               int efg)
{
    if (!efg && o->bc == TF_BC_PENALTY) {
        tf_fail(ctx,
                "%s: the seed's nodal penalty (eq 28) is for the linear law and rpim-galerkin; "
                "rpim-newton takes solver.bc elimination or nitsche",
                p->name);
        return NULL;
    }
    nl_solver *s = calloc(1, sizeof *s);
    if (s == NULL) {
        tf_fail(ctx, "out of memory");
        return NULL;
    }
    s->base.ops = efg ? &tf_efg_newton_ops : &tf_rpim_newton_ops;
    s->base.problem = p;
    s->base.opts = *o;
    s->base.ctx = ctx;
    s->efg = efg;
    s->weak = efg || o->bc == TF_BC_NITSCHE;
    double t0 = omp_get_wtime();
    if (nl_model_build(s, p, ctx) != 0) {
        destroy(&s->base);
        return NULL;
    }
    announce(s, p, ctx);
    nl_reset(s);
    s->base.info = (tf_solver_info){
        .nodes = p->cloud.n,
        .dofs = 3 * p->cloud.n,
        .unknowns = 3 * p->cloud.n,
        .t_setup = omp_get_wtime() - t0,
    };
    return &s->base;
}

int tf_nonlinear_info_of(const tf_solver *sv, tf_nonlinear_info *info)
{
    if (!is_nonlinear(sv)) {
        return -1;
    }
    const nl_solver *s = of_const(sv);
    const nl_stats *st = &s->st;
    *info = (tf_nonlinear_info){
        .steps = st->steps,
        .cuts = st->cuts,
        .iterations = st->iterations,
        .residuals = st->residuals,
        .tangents = st->tangents,
        .factorisations = st->factorisations,
        .indefinite = st->indefinite,
        .kept = st->kept,
        .shifted = st->shifted,
        .shift = s->shift,
        .krylov = st->krylov,
        .patch_dofs = s->patch.m,
        .patches = st->patches,
        .patch_kept = st->patch_kept,
        .t_patch = st->t_patch,
        .t_gradients = s->t_setup_shape,
        .t_residual = st->t_residual,
        .t_tangent = st->t_tangent,
        .t_factor = st->t_factor,
        .t_solve = st->t_solve,
        .nnz_l = s->ci.nnz_l,
        .ordering = s->chol ? tf_chol_ordering(s->chol) : "-",
    };
    return 0;
}

int tf_nonlinear_reset(tf_solver *sv)
{
    if (!is_nonlinear(sv)) {
        return tf_fail(sv->ctx, "solver %s is not the nonlinear solver", sv->ops->name);
    }
    nl_reset(of(sv));
    return 0;
}

int tf_nonlinear_advance(tf_solver *sv, double scale, int contact, const double force[3],
                         double dt)
{
    if (!is_nonlinear(sv)) {
        return tf_fail(sv->ctx, "solver %s is not the nonlinear solver", sv->ops->name);
    }
    nl_target to = {scale, contact, {0, 0, 0}};
    if (contact >= 0) {
        memcpy(to.force, force, sizeof to.force);
    }
    double t0 = omp_get_wtime();
    int rc = nl_advance(of(sv), &to, dt);
    sv->info.t_solve += omp_get_wtime() - t0;
    sv->info.solves += rc == 0;
    return rc;
}

int tf_nonlinear_displacements(tf_solver *sv, double *u)
{
    if (!is_nonlinear(sv)) {
        return tf_fail(sv->ctx, "solver %s is not the nonlinear solver", sv->ops->name);
    }
    outputs(of(sv), u);
    return 0;
}

int tf_nonlinear_region_force(tf_solver *sv, size_t region, double force[3])
{
    if (!is_nonlinear(sv) || region >= sv->problem->n_fixed) {
        return tf_fail(sv->ctx, "no fixed region %zu in the nonlinear solver's problem", region);
    }
    nl_solver *s = of(sv);
    if (s->weak) {
        return nl_region_force(s, region, force);
    }
    size_t n3 = 3 * s->sh.cloud->n;
    double *r = malloc(n3 * sizeof *r), *fext = malloc(n3 * sizeof *fext);
    nl_fault f = {0};
    int rc = r && fext ? nl_assemble(s, s->d, &s->at, 0, 0, r, s->fint, &f) : -1;
    if (rc == 0) {
        nl_external(s, &s->at, fext);
        const tf_fixed *fx = &sv->problem->fixed[region];
        force[0] = force[1] = force[2] = 0;
        for (size_t k = 0; k < fx->n_nodes; ++k) {
            for (int a = 0; a < 3; ++a) {
                size_t dof = 3 * (size_t)fx->nodes[k] + (size_t)a;
                force[a] += (fx->components >> a) & 1u ? s->fint[dof] - fext[dof] : 0;
            }
        }
    }
    free(r);
    free(fext);
    return rc == 0 ? 0 : tf_fail(sv->ctx, "the reactions could not be evaluated");
}

int tf_nonlinear_stability_of(tf_solver *sv, double tol, tf_nonlinear_stability *out)
{
    if (!is_nonlinear(sv)) {
        return tf_fail(sv->ctx, "solver %s is not the nonlinear solver", sv->ops->name);
    }
    if (!(tol > 0)) {
        return tf_fail(sv->ctx, "stability: the tolerance must be positive");
    }
    return nl_stability(of(sv), tol, out);
}
