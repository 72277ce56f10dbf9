/*
 * galerkin.c — the RPIM Galerkin solver: build once, solve many
 * (galerkin.h).
 */
#include "solvers/galerkin/galerkin.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/log.h"
#include "base/peak_memory.h"
#include "problem/inclusions.h"
#include "solvers/assemble.h"
#include "solvers/cell_stiffness.h"
#include "solvers/boundary.h"
#include "solvers/cholmod_solve.h"
#include "solvers/constraints.h"
#include "solvers/field.h"
#include "solvers/load_vector.h"
#include "solvers/nodal_values.h"
#include "solvers/nonlinear/nonlinear.h"

typedef struct galerkin {
    tf_solver base;    /* first: a galerkin is a tf_solver (base.opts: its options) */
    tf_shape sh;
    int shape_ok;
    int efg;           /* MLS shape functions: the unknowns are parameters (nodal_values.h) */
    int weak;          /* essential conditions in weak form (boundary.h) */
    tf_boundary bnd;   /* weak: Gamma_u's points */
    tf_nodal_map map;  /* EFG: parameters -> nodal displacements */
    tf_csc k;          /* stiffness of the body, every DOF (weak terms not included) */
    tf_constraints bc; /* prescribed DOFs */
    double *f0;        /* 3N: the problem's loads */
    double *basis;     /* n_contacts x (3N x 3): unit forces at each site */
    double *rhs0;      /* system size: constant part of every right-hand side */
    tf_chol *chol;
    tf_galerkin_info detail;
} galerkin;

/* The material at a Gauss point (material regions, problem/inclusions.h). */
static tf_lame lame_at(const void *data, const double x[3])
{
    return tf_problem_lame_at(data, x);
}

static galerkin *of(tf_solver *s) { return (galerkin *)s; }
static const galerkin *of_const(const tf_solver *s) { return (const galerkin *)s; }

static int build_loads(galerkin *g, const tf_problem *p, tf_ctx *ctx)
{
    size_t n3 = g->k.n;
    for (size_t k = 0; k < p->n_loads; ++k) {
        const tf_load *ld = &p->loads[k];
        int rc = ld->exact ? tf_load_exact(ctx, &g->sh, p, &ld->patch, g->f0)
                           : tf_load_patch(ctx, &g->sh, &ld->patch, ld->force, g->f0);
        if (rc != 0) {
            return -1;
        }
    }
    for (size_t c = 0; c < p->n_contacts; ++c) {
        if (tf_load_patch(ctx, &g->sh, &p->contacts[c].patch, NULL, g->basis + 3 * n3 * c) != 0) {
            return -1;
        }
    }
    return 0;
}

/* K plus the weak boundary terms, and the loads plus theirs. */
static int weak_system(galerkin *g, tf_csc *a, tf_ctx *ctx)
{
    const tf_problem *p = g->base.problem;
    size_t n3 = g->k.n;
    tf_lame l = tf_material_lame(&p->material);
    double scale = tf_boundary_scale(&l, &p->cloud);
    tf_bc_method m = g->base.opts.bc;
    double factor = scale * (m == TF_BC_NITSCHE ? g->base.opts.nitsche : g->base.opts.penalty);
    g->rhs0 = malloc(n3 * sizeof *g->rhs0);
    a->n = g->k.n;
    a->nnz = g->k.nnz;
    a->p = malloc((n3 + 1) * sizeof *a->p);
    a->i = malloc(g->k.nnz * sizeof *a->i);
    a->x = malloc(g->k.nnz * sizeof *a->x);
    if (!g->rhs0 || !a->p || !a->i || !a->x) {
        tf_csc_free(a);
        return tf_fail(ctx, "out of memory");
    }
    memcpy(g->rhs0, g->f0, n3 * sizeof *g->rhs0);
    memcpy(a->p, g->k.p, (n3 + 1) * sizeof *a->p);
    memcpy(a->i, g->k.i, g->k.nnz * sizeof *a->i);
    memcpy(a->x, g->k.x, g->k.nnz * sizeof *a->x);
    if (tf_boundary_add_linear(ctx, &g->bnd, &g->sh, m, factor, &l, a, g->rhs0) != 0) {
        tf_csc_free(a);
        return -1;
    }
    return 0;
}

/* The system matrix and the constant part of every right-hand side, then
 * the factorisation. */
static int factorise(galerkin *g, tf_ctx *ctx)
{
    size_t n3 = g->k.n;
    tf_csc a = {0};
    tf_chol_info ci;
    if (g->weak) {
        if (weak_system(g, &a, ctx) != 0) {
            return -1;
        }
    } else if (g->base.opts.bc == TF_BC_PENALTY) {
        g->rhs0 = malloc(n3 * sizeof *g->rhs0);
        if (g->rhs0 == NULL) {
            return tf_fail(ctx, "out of memory");
        }
        memcpy(g->rhs0, g->f0, n3 * sizeof *g->rhs0);
        if (tf_constraints_penalise(&g->bc, &g->k, g->base.opts.penalty, &a, g->rhs0) != 0) {
            return tf_fail(ctx, "out of memory");
        }
    } else {
        double *ku = malloc(n3 * sizeof *ku);
        g->rhs0 = malloc((g->bc.n_free + 1) * sizeof *g->rhs0);
        if (ku == NULL || g->rhs0 == NULL || tf_constraints_reduce(&g->bc, &g->k, &a) != 0) {
            free(ku);
            return tf_fail(ctx, "out of memory");
        }
        /* F_f - K_fc u_bar_c */
        tf_csc_symv(&g->k, g->bc.ubar, ku, 1);
        for (size_t d = 0; d < n3; ++d) {
            if (!g->bc.fixed[d]) {
                g->rhs0[g->bc.free_index[d]] = g->f0[d] - ku[d];
            }
        }
        free(ku);
    }
    if (a.n == 0) {
        tf_csc_free(&a);
        return tf_fail(ctx, "every degree of freedom is fixed: nothing to solve");
    }
    double t = 0;
    g->chol = tf_chol_analyse(ctx, &a, (tf_ordering)g->base.opts.ordering, 0, &ci);
    int rc = g->chol ? tf_chol_refactor(ctx, g->chol, &a, &t) : -1;
    ci.t_factor = t;
    ci.rcond = rc == 0 ? tf_chol_rcond(g->chol) : 0;
    if (rc != 0) {
        if (rc == 1) {
            tf_fail(ctx, "the stiffness matrix is not positive definite: is the body held "
                         "by its fixed regions?");
        }
        tf_chol_free(g->chol);
        g->chol = NULL;
    }
    tf_csc_free(&a);
    if (g->chol == NULL) {
        return -1;
    }
    g->detail.t_factor = ci.t_analyse + ci.t_factor;
    g->detail.t_analyse = ci.t_analyse;
    g->detail.chol_mib = tf_chol_peak_bytes(g->chol) / (1024.0 * 1024.0);
    g->detail.nnz_l = ci.nnz_l;
    g->detail.flops = ci.flops;
    g->detail.ordering = ci.ordering;
    g->detail.rcond = ci.rcond;
    return 0;
}

static void announce(const galerkin *g, const tf_problem *p, const tf_ctx *ctx)
{
    const tf_solver_opts *o = &g->base.opts;
    const tf_cells *c = &g->sh.cells;
    if (c->tet) {
        tf_info(ctx,
                "solver: %zu nodes (%zu on the surface), %zu DOFs, %zu tetrahedra x %u Gauss "
                "points (degree %u), support %g x local spacing (%s-centred), %s, volumetric "
                "strain %s, BCs by %s",
                p->cloud.n, p->cloud.n_surface, 3 * p->cloud.n, c->ntet, c->rule.n,
                c->rule.degree, o->support, o->centre == TF_SUPPORT_CELL ? "cell" : "point",
                o->polynomial ? "RBF + linear polynomial" : "RBF only",
                o->volumetric == TF_VOLUMETRIC_CELL ? "averaged per cell" : "at every point",
                o->bc == TF_BC_PENALTY ? "penalty" : "elimination");
        return;
    }
    tf_info(ctx,
            "solver: %zu nodes, %zu DOFs, %zu cells x %u^3 Gauss points%s, support %g x spacing "
            "(%s-centred), %s, volumetric strain %s, BCs by %s",
            p->cloud.n, 3 * p->cloud.n, tf_cells_count(c), c->gauss,
            o->integration == TF_INTEGRATION_VCI ? " (VCI)" : "", o->support,
            o->centre == TF_SUPPORT_CELL ? "cell" : "point",
            g->efg ? "MLS (EFG)" : o->polynomial ? "RBF + linear polynomial" : "RBF only",
            o->volumetric == TF_VOLUMETRIC_CELL ? "averaged per cell" : "at every point",
            o->bc == TF_BC_NITSCHE   ? "Nitsche's method"
            : o->bc == TF_BC_PENALTY ? (g->weak ? "penalty (weak form)" : "penalty")
                                     : "elimination");
}

static void destroy(tf_solver *s)
{
    galerkin *g = of(s);
    if (g->shape_ok) {
        tf_shape_free(&g->sh);
    }
    tf_csc_free(&g->k);
    tf_constraints_release(&g->bc);
    tf_boundary_free(&g->bnd);
    tf_nodal_map_free(&g->map);
    free(g->f0);
    free(g->basis);
    free(g->rhs0);
    tf_chol_free(g->chol);
    free(g);
}

/* Shape functions and the stiffness K of every DOF. */
static int assemble(galerkin *g, const tf_problem *p, tf_ctx *ctx)
{
    double lo[3], hi[3];
    tf_problem_bounds(p, lo, hi);
    if (tf_shape_init(&g->sh, &p->cloud, lo, hi, &g->base.opts) != 0) {
        return tf_fail(ctx, "out of memory");
    }
    g->shape_ok = 1;
    const tf_mesh_geometry *m = tf_problem_mesh(p);
    if (m != NULL &&
        tf_shape_use_tets(ctx, &g->sh, m->tm.tet, m->tm.ntet, g->base.opts.tet_degree) != 0) {
        return -1;
    }
    if (g->efg && tf_shape_use_efg(ctx, &g->sh) != 0) {
        return -1;
    }
    /* After tf_shape_use_efg (the enriched nodes are the MLS domains that
     * meet a cut) and before the boundary terms, which evaluate the same
     * shape functions on the fixed faces. */
    if (tf_shape_set_cuts(ctx, &g->sh, p->cuts, p->n_cuts) != 0) {
        return -1;
    }
    if (g->weak && tf_boundary_build(ctx, &g->bnd, p, &g->sh) != 0) {
        return -1;
    }
    announce(g, p, ctx);
    tf_assembly_info ai;
    tf_lame l = tf_material_lame(&p->material);
    const tf_lame_field field = {p, lame_at};
    tf_assembly_extra ex = {g->base.opts.integration == TF_INTEGRATION_VCI,
                            g->weak ? &g->bnd : NULL, p->n_inclusions > 0 ? &field : NULL};
    if (ex.vci && ex.field != NULL) {
        return tf_fail(ctx, "not yet: material regions with VCI integration (solver.integration: "
                            "gauss integrates them point by point)");
    }
    int plain = !ex.vci && ex.bnd == NULL && ex.field == NULL; /* today's path, bit for bit */
    if (tf_assemble_stiffness(ctx, &g->sh, &l, g->base.opts.volumetric == TF_VOLUMETRIC_CELL,
                              plain ? NULL : &ex, tf_ctx_threads(ctx), &g->k, &ai) != 0) {
        return -1;
    }
    if (g->efg && tf_nodal_map_build(ctx, &g->map, &g->sh) != 0) {
        return -1;
    }
    g->detail.points = ai.points;
    g->detail.nnz_k = g->k.nnz;
    g->detail.t_pattern = ai.t_pattern;
    g->detail.t_shape = ai.t_values * ai.shape_fraction;
    g->detail.t_assemble = ai.t_values - g->detail.t_shape;
    g->detail.st = ai.st;
    tf_info(ctx, "solver: assembled %zu Gauss points in %.2f s (K has %zu stored entries)",
            ai.points, ai.t_pattern + ai.t_values, g->k.nnz);
    return 0;
}

/* (EFG's fixed regions are weak whatever the options say: tf_solver_create_as
 * turned elimination into Nitsche's method.) */
static tf_solver *create(const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx, int efg)
{
    if (!tf_material_linear_elastic(&p->material)) {
        const tf_solver_ops *from = efg ? &tf_efg_galerkin_ops : &tf_galerkin_ops;
        const tf_solver_ops *to = efg ? &tf_efg_newton_ops : &tf_rpim_newton_ops;
        tf_info(ctx, "%s: the %s law is not linear elastic: %s hands it to %s", p->name,
                tf_material_name(&p->material), from->name, to->name);
        return tf_nonlinear_create(p, o, ctx, efg);
    }
    galerkin *g = calloc(1, sizeof *g);
    if (g == NULL) {
        tf_fail(ctx, "out of memory");
        return NULL;
    }
    g->base.opts = *o;
    g->base.problem = p; /* (tf_solver_create_as sets it again) */
    g->efg = efg;
    g->weak = efg || o->bc == TF_BC_NITSCHE;
    tf_shape_stats_reset(&g->detail.st);
    if (assemble(g, p, ctx) != 0) {
        destroy(&g->base);
        return NULL;
    }
    double t0 = omp_get_wtime();
    size_t n3 = g->k.n;
    g->f0 = calloc(n3, sizeof *g->f0);
    g->basis = calloc(3 * n3 * (p->n_contacts + 1), sizeof *g->basis);
    if (!g->f0 || !g->basis || tf_constraints_init(&g->bc, p) != 0) {
        tf_fail(ctx, "out of memory");
        destroy(&g->base);
        return NULL;
    }
    if (build_loads(g, p, ctx) != 0) {
        destroy(&g->base);
        return NULL;
    }
    g->detail.t_loads = omp_get_wtime() - t0;
    size_t unknowns = g->weak || g->base.opts.bc == TF_BC_PENALTY ? n3 : g->bc.n_free;
    tf_info(ctx, "solver: factorising %zu unknowns (CHOLMOD)", unknowns);
    if (factorise(g, ctx) != 0) {
        destroy(&g->base);
        return NULL;
    }
    tf_info(ctx,
            "solver: factorised in %.2f s (%s ordering, %.3g entries in L, reciprocal "
            "condition about %.2g)",
            g->detail.t_factor, g->detail.ordering, g->detail.nnz_l, g->detail.rcond);
    g->base.info = (tf_solver_info){
        .nodes = p->cloud.n,
        .dofs = n3,
        .unknowns = unknowns,
        .t_setup = g->detail.t_pattern + g->detail.t_shape + g->detail.t_assemble +
                   g->detail.t_factor,
    };
    return &g->base;
}

static unsigned caps(const tf_solver *s)
{
    return TF_SOLVER_AFFINE | TF_SOLVER_CUTS |
           (tf_problem_unloaded(s->problem) ? TF_SOLVER_LINEAR : 0u);
}

/* Full load vector of one case: the problem's loads + the contact force. */
static void load_vector(const galerkin *g, int contact, const double *force, double *f)
{
    size_t n3 = g->k.n;
    memcpy(f, g->f0, n3 * sizeof *f);
    if (contact >= 0) {
        const double *b = g->basis + 3 * n3 * (size_t)contact;
        for (size_t d = 0; d < n3; ++d) {
            f[d] += b[d] * force[0] + b[n3 + d] * force[1] + b[2 * n3 + d] * force[2];
        }
    }
}

/* Right-hand side, in the factorised system's DOFs, of the full load
 * vector f (the problem's loads included). */
static void rhs_of_vector(const galerkin *g, const double *f, double *rhs)
{
    size_t n3 = g->k.n;
    const tf_constraints *bc = &g->bc;
    if (g->weak) {
        for (size_t d = 0; d < n3; ++d) {
            rhs[d] = g->rhs0[d] + (f[d] - g->f0[d]);
        }
    } else if (g->base.opts.bc == TF_BC_PENALTY) {
        for (size_t d = 0; d < n3; ++d) {
            rhs[d] = bc->fixed[d] ? g->rhs0[d] : f[d];
        }
    } else {
        for (size_t d = 0; d < n3; ++d) {
            if (!bc->fixed[d]) {
                rhs[bc->free_index[d]] = g->rhs0[bc->free_index[d]] + f[d] - g->f0[d];
            }
        }
    }
}

/* Right-hand side of one case in the factorised system's DOFs. */
static void rhs_of(const galerkin *g, int contact, const double *force, double *f, double *rhs)
{
    load_vector(g, contact, force, f);
    rhs_of_vector(g, f, rhs);
}

/* Size of the factorised system: every DOF, or the free ones when the
 * prescribed DOFs are eliminated. */
static size_t system_size(const galerkin *g)
{
    return g->weak || g->base.opts.bc == TF_BC_PENALTY ? g->k.n : g->bc.n_free;
}

/* Solves n right-hand sides b (system size) into x and the displacements u
 * (3N x n): the nodal values of the solution (EFG: mapped from its
 * parameters), prescribed DOFs at their values. */
static int solve_rhs(galerkin *g, const double *b, double *x, size_t n, double *u)
{
    tf_ctx *ctx = g->base.ctx;
    const tf_constraints *bc = &g->bc;
    size_t n3 = g->k.n, m = system_size(g);
    int rc = tf_chol_solve(ctx, g->chol, b, x, n);
    if (rc == 0 && g->efg) { /* displacements at the nodes, not parameters */
        tf_nodal_map_values(&g->map, x, u, n);
    }
    for (size_t k = 0; k < n && rc == 0 && !g->efg; ++k) {
        double *uk = u + k * n3;
        for (size_t d = 0; d < n3; ++d) {
            uk[d] = m == n3        ? x[k * m + d]
                    : bc->fixed[d] ? bc->ubar[d]
                                   : x[k * m + (size_t)bc->free_index[d]];
        }
    }
    return rc;
}

/* One CHOLMOD solve with n right-hand sides; u0 is not needed (linear). */
static int solve(tf_solver *s, int contact, const double (*forces)[3], size_t n,
                 const double *u0, double *u)
{
    (void)u0;
    if (n == 0) {
        return 0; /* (the interface never asks; this tells the compiler b is filled) */
    }
    galerkin *g = of(s);
    tf_ctx *ctx = s->ctx;
    size_t n3 = g->k.n, m = system_size(g);
    double *b = malloc(m * n * sizeof *b), *x = malloc(m * n * sizeof *x);
    double *f = malloc(n3 * sizeof *f);
    if (!b || !x || !f) {
        free(b);
        free(x);
        free(f);
        return tf_fail(ctx, "out of memory for %zu load cases of %zu DOFs", n, n3);
    }
    for (size_t k = 0; k < n; ++k) {
        rhs_of(g, contact, contact >= 0 ? forces[k] : NULL, f, b + k * m);
    }
    int rc = solve_rhs(g, b, x, n, u);
    free(b);
    free(x);
    free(f);
    return rc;
}

/* n nodal load vectors (3N x n) added to the problem's loads, one CHOLMOD
 * solve with n right-hand sides. */
static int solve_loads(tf_solver *s, const double *fl, size_t n, double *u)
{
    galerkin *g = of(s);
    size_t n3 = g->k.n, m = system_size(g);
    double *b = malloc(m * n * sizeof *b), *x = malloc(m * n * sizeof *x);
    double *f = malloc(n3 * sizeof *f);
    if (!b || !x || !f) {
        free(b);
        free(x);
        free(f);
        return tf_fail(s->ctx, "out of memory for %zu load vectors of %zu DOFs", n, n3);
    }
    for (size_t k = 0; k < n; ++k) {
        for (size_t d = 0; d < n3; ++d) {
            f[d] = g->f0[d] + fl[k * n3 + d];
        }
        rhs_of_vector(g, f, b + k * m);
    }
    int rc = solve_rhs(g, b, x, n, u);
    free(b);
    free(x);
    free(f);
    return rc;
}

/* The unit-force load vectors of a patch with this solver's shape
 * functions, as build_loads makes a contact site's. */
static int patch_loads(tf_ctx *ctx, const tf_solver *s, const tf_patch *p, double *f)
{
    const galerkin *g = of_const(s);
    memset(f, 0, 3 * g->k.n * sizeof *f);
    return tf_load_patch(ctx, &g->sh, p, NULL, f);
}

static int reactions(const tf_solver *s, int contact, const double force[3], const double *u,
                     double *r)
{
    const galerkin *g = of_const(s);
    size_t n3 = g->k.n;
    double *f = malloc(n3 * sizeof *f);
    if (f == NULL) {
        return tf_fail(s->ctx, "out of memory");
    }
    load_vector(g, contact, force, f);
    tf_csc_symv(&g->k, u, r, 1); /* (RPIM: u are the nodal parameters) */
    for (size_t q = 0; q < n3; ++q) {
        r[q] -= f[q];
    }
    free(f);
    return 0;
}

/* u_h = sum_I phi_I u_I and its gradient (RPIM interpolant; EFG: the MLS
 * approximation of the parameters of u). */
static int field(tf_ctx *ctx, const tf_solver *s, const double *u, const double *x, size_t np,
                 double *uh, double *grad)
{
    const galerkin *g = of_const(s);
    return tf_nodal_field(ctx, &g->sh, g->efg ? (tf_nodal_map *)&g->map : NULL, u, x, np, uh, grad);
}

static size_t node_count(const tf_solver *s) { return s->problem->cloud.n; }
static const double *coords(const tf_solver *s) { return s->problem->cloud.xyz; }

/* Time split and memory (progress), and a warning when local systems were
 * ill-conditioned: how many, the worst place and what to change. */
static void report(const tf_solver *s)
{
    const galerkin *g = of_const(s);
    const tf_galerkin_info *in = &g->detail;
    tf_info(s->ctx,
            "solver: times (s): pattern %.3f, shape functions %.3f, assembly %.3f, loads %.3f, "
            "factorisation %.3f, solves %.3f (%zu right-hand sides); peak memory %.0f MiB",
            in->t_pattern, in->t_shape, in->t_assemble, in->t_loads, in->t_factor,
            s->info.t_solve, s->info.solves, tf_peak_mib());
    tf_info(s->ctx,
            "solver: %zu local systems of %zu to %zu nodes, smallest reciprocal condition %.2g",
            in->st.systems, in->st.min_nodes, in->st.max_nodes, in->st.min_rcond);
    if (s->problem->n_cuts > 0) {
        tf_info(s->ctx,
                "solver: %zu cut(s): shape functions recomputed at %zu of %zu points whose "
                "support meets a cut",
                s->problem->n_cuts, in->st.cut_points, in->st.points);
    }
    if (in->st.ill > 0) {
        tf_warn(s->ctx,
                "%s: %zu of %zu local RPIM systems are ill-conditioned (reciprocal condition "
                "below %.2g; worst %.2g near (%g, %g, %g) mm); the shape functions lose about "
                "%.0f digits: lower solver.rbf.spacings (or d_c) or solver.support",
                s->problem->source, in->st.ill, in->st.systems, g->base.opts.rcond_warn,
                in->st.min_rcond, in->st.worst_at[0], in->st.worst_at[1], in->st.worst_at[2],
                in->st.min_rcond > 0 ? -log10(in->st.min_rcond) : 16.0);
    }
}

static tf_solver *create_rpim(const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx)
{
    return create(p, o, ctx, 0);
}

static tf_solver *create_efg(const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx)
{
    return create(p, o, ctx, 1);
}

const tf_solver_ops tf_galerkin_ops = {
    .name = "rpim-galerkin",
    .summary = "RPIM Galerkin ([Zhou2017] §2): a linear elastic law by one CHOLMOD "
               "factorisation, any other law by rpim-newton",
    .create = create_rpim,
    .caps = caps,
    .solve = solve,
    .history = NULL,
    .reactions = reactions,
    .field = field,
    .node_count = node_count,
    .coords = coords,
    .report = report,
    .destroy = destroy,
    .patch_loads = patch_loads,
    .solve_loads = solve_loads,
};

const tf_solver_ops tf_efg_galerkin_ops = {
    .name = "efg-galerkin",
    .summary = "element-free Galerkin (MLS, [EFG-Kelvin] §2), weak essential conditions: a linear "
               "elastic law by one CHOLMOD factorisation, any other law by efg-newton",
    .weak_bc = 1,
    .create = create_efg,
    .caps = caps,
    .solve = solve,
    .history = NULL,
    /* none: the fixed regions are held weakly, their reaction is a traction
     * over the face whose Galerkin forces fall on every node whose support
     * meets it, not on the region's nodes (docs/solver.md, Known limits) */
    .reactions = NULL,
    .field = field,
    .node_count = node_count,
    .coords = coords,
    .report = report,
    .destroy = destroy,
    /* no patch_loads: its displacements are nodal values, not the parameters
     * the load vectors weight, so f^T u would not be a patch average */
    .patch_loads = NULL,
    .solve_loads = solve_loads,
};

static int is_galerkin(const tf_solver *s)
{
    return s->ops == &tf_galerkin_ops || s->ops == &tf_efg_galerkin_ops;
}

const tf_galerkin_info *tf_galerkin_info_of(const tf_solver *s)
{
    return is_galerkin(s) ? &of_const(s)->detail : NULL;
}

const tf_shape *tf_galerkin_shape(const tf_solver *s)
{
    return is_galerkin(s) ? &of_const(s)->sh : NULL;
}
