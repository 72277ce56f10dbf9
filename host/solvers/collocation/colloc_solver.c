/*
 * colloc_solver.c — "mls-collocation" behind the solver interface
 * (colloc_solver.h).
 */
#include "solvers/collocation/colloc_solver.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/log.h"
#include "solvers/collocation/colloc.h"
#include "solvers/constraints.h"

typedef struct csolver {
    tf_solver base; /* first: a csolver is a tf_solver */
    tf_colloc *c;
    size_t n3;
    double *f0;    /* 3N: the problem's loads */
    double *unit;  /* n_contacts x (3N x 3): unit forces at each site */
    double *vol;   /* N tributary volumes */
    double dt_crit;
    size_t relax_steps, relax_cases, history_steps;
} csolver;

static csolver *of(tf_solver *s) { return (csolver *)s; }
static const csolver *of_const(const tf_solver *s) { return (const csolver *)s; }

/* The relaxation's tolerance behind the interface is tighter than the
 * core's 1e-6: the solver conformance suite asks every solver for
 * equilibrium to 1e-9 N under 1 N (about 1.7 times the steps). */
tf_colloc_settings tf_colloc_settings_default(void)
{
    tf_colloc_opts o;
    tf_colloc_defaults(&o);
    return (tf_colloc_settings){.neighbours = o.neighbours, .support = o.support,
                                .stabilisation = o.stab, .volume_constant = o.kv,
                                .density = 1e-9, .damping = 0, .tolerance = 1e-10};
}

/* A grid node's tributary volume: half a spacing each way, clipped to the
 * box (the unjittered position: a jittered grid keeps the same shares). */
static void tributary_volumes(const tf_cloud *c, double *vol)
{
    for (unsigned k = 0; k < c->grid[2]; ++k) {
        for (unsigned j = 0; j < c->grid[1]; ++j) {
            for (unsigned i = 0; i < c->grid[0]; ++i) {
                unsigned idx[3] = {i, j, k};
                double v = 1;
                for (int a = 0; a < 3; ++a) {
                    int edge = idx[a] == 0 || idx[a] == c->grid[a] - 1;
                    v *= edge ? c->spacing[a] / 2 : c->spacing[a];
                }
                vol[tf_cloud_index(c, i, j, k)] = v;
            }
        }
    }
}

static void destroy(tf_solver *s)
{
    csolver *cs = of(s);
    tf_colloc_free(cs->c);
    free(cs->f0);
    free(cs->unit);
    free(cs->vol);
    free(cs);
}

/* The problem's loads into f0 and the unit forces of each contact site. */
static int build_loads(csolver *cs, const tf_problem *p, tf_ctx *ctx)
{
    for (size_t k = 0; k < p->n_loads; ++k) {
        const tf_load *ld = &p->loads[k];
        int rc = ld->exact ? tf_colloc_exact_forces(ctx, p, &ld->patch, cs->f0)
                           : tf_colloc_patch_forces(ctx, p, &ld->patch, ld->force, cs->f0);
        if (rc != 0) {
            return -1;
        }
    }
    for (size_t k = 0; k < p->n_contacts; ++k) {
        if (tf_colloc_patch_forces(ctx, p, &p->contacts[k].patch, NULL,
                                   cs->unit + 3 * cs->n3 * k) != 0) {
            return -1;
        }
    }
    return 0;
}

/* Particles, prescribed components and values. */
static int build_body(csolver *cs, const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx)
{
    tf_constraints bc;
    unsigned char *mask = calloc(p->cloud.n + 1, 1);
    if (mask == NULL || tf_constraints_init(&bc, p) != 0) {
        free(mask);
        return tf_fail(ctx, "out of memory");
    }
    for (size_t d = 0; d < cs->n3; ++d) {
        mask[d / 3] |= (unsigned char)(bc.fixed[d] ? 1u << (d % 3) : 0);
    }
    tributary_volumes(&p->cloud, cs->vol);
    tf_colloc_body b = {.n = p->cloud.n, .X = p->cloud.xyz, .fixed = mask, .volume = cs->vol,
                        .material = p->material, .density = o->colloc.density};
    tf_colloc_opts co;
    tf_colloc_defaults(&co);
    co.neighbours = o->colloc.neighbours;
    co.support = o->colloc.support;
    co.stab = o->colloc.stabilisation;
    co.kv = o->colloc.volume_constant;
    co.threads = tf_ctx_threads(ctx);
    cs->c = tf_colloc_new(ctx, &b, &co);
    if (cs->c) {
        memcpy(tf_colloc_ubar(cs->c), bc.ubar, cs->n3 * sizeof(double));
        cs->base.info.unknowns = bc.n_free;
    }
    tf_constraints_release(&bc);
    free(mask);
    return cs->c ? 0 : tf_fail(ctx, "mls-collocation: %s", ctx->err);
}

static tf_solver *create(const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx)
{
    if (p->geometry.kind != TF_GEOMETRY_BOX) {
        tf_fail(ctx, "mls-collocation: only box geometries so far (particle volumes are the "
                     "grid's tributary volumes)");
        return NULL;
    }
    if (p->n_inclusions > 0) {
        tf_fail(ctx, "mls-collocation: not yet: material regions (inclusions); the Galerkin "
                     "solvers (rpim-galerkin, efg-galerkin) solve them");
        return NULL;
    }
    csolver *cs = calloc(1, sizeof *cs);
    if (cs == NULL) {
        tf_fail(ctx, "out of memory");
        return NULL;
    }
    cs->n3 = 3 * p->cloud.n;
    cs->f0 = calloc(cs->n3 + 1, sizeof *cs->f0);
    cs->unit = calloc(3 * cs->n3 * p->n_contacts + 1, sizeof *cs->unit);
    cs->vol = calloc(p->cloud.n + 1, sizeof *cs->vol);
    if (!cs->f0 || !cs->unit || !cs->vol) {
        destroy(&cs->base);
        tf_fail(ctx, "out of memory");
        return NULL;
    }
    cs->base.info.nodes = p->cloud.n;
    cs->base.info.dofs = cs->n3;
    if (build_body(cs, p, o, ctx) != 0 || build_loads(cs, p, ctx) != 0) {
        destroy(&cs->base);
        return NULL;
    }
    tf_info(ctx, "solver: MLS collocation, %zu particles (%u neighbours, support %g x mean "
                 "distance, stabilisation %g), %s, static cases by dynamic relaxation",
            p->cloud.n, o->colloc.neighbours, o->colloc.support, o->colloc.stabilisation,
            tf_material_name(&p->material));
    return &cs->base;
}

static unsigned caps(const tf_solver *s)
{
    (void)s;
    return TF_SOLVER_TIME_DEPENDENT;
}

/* fext = the problem's loads + force at site contact (none when < 0). */
static void external(csolver *cs, int contact, const double force[3])
{
    double *fext = tf_colloc_fext(cs->c);
    for (size_t d = 0; d < cs->n3; ++d) {
        fext[d] = cs->f0[d];
    }
    if (contact < 0 || force == NULL) {
        return;
    }
    const double *unit = cs->unit + 3 * cs->n3 * (size_t)contact;
    for (int a = 0; a < 3; ++a) {
        for (size_t d = 0; d < cs->n3; ++d) {
            fext[d] += force[a] * unit[(size_t)a * cs->n3 + d];
        }
    }
}

static int solve(tf_solver *s, int contact, const double (*forces)[3], size_t n, const double *u0,
                 double *u)
{
    csolver *cs = of(s);
    tf_colloc_relax_opts ro;
    tf_colloc_relax_defaults(&ro);
    ro.tol = s->opts.colloc.tolerance;
    for (size_t k = 0; k < n; ++k) {
        external(cs, contact, forces ? forces[k] : NULL);
        double *uc = tf_colloc_u(cs->c);
        if (u0) {
            memcpy(uc, u0 + k * cs->n3, cs->n3 * sizeof *uc);
        } else {
            memset(uc, 0, cs->n3 * sizeof *uc);
        }
        tf_colloc_relax_stats st;
        int rc = tf_colloc_relax(s->ctx, cs->c, &ro, &st);
        if (rc != 0) {
            return tf_fail(s->ctx, "mls-collocation, case %zu: %s", k + 1,
                           rc < 0 ? s->ctx->err : "the relaxation did not converge");
        }
        cs->relax_steps += st.steps;
        cs->relax_cases++;
        memcpy(u + k * cs->n3, uc, cs->n3 * sizeof *u);
    }
    return 0;
}

static int history(tf_solver *s, int contact, const double (*forces)[3], size_t n, double dt,
                   double *u)
{
    csolver *cs = of(s);
    if (cs->dt_crit == 0) {
        cs->dt_crit = tf_colloc_critical_dt(s->ctx, cs->c);
        if (!(cs->dt_crit > 0)) {
            cs->dt_crit = 0;
            return tf_fail(s->ctx, "mls-collocation: %s", s->ctx->err);
        }
    }
    double steps = ceil(dt / (0.9 * cs->dt_crit));
    size_t m = (size_t)steps;
    memset(tf_colloc_u(cs->c), 0, cs->n3 * sizeof(double));
    memset(tf_colloc_v(cs->c), 0, cs->n3 * sizeof(double));
    for (size_t k = 0; k < n; ++k) {
        external(cs, contact, forces ? forces[k] : NULL);
        if (tf_colloc_run(s->ctx, cs->c, dt / steps, m, s->opts.colloc.damping) != 0) {
            return tf_fail(s->ctx, "mls-collocation, history step %zu: %s", k + 1, s->ctx->err);
        }
        cs->history_steps += m;
        memcpy(u + k * cs->n3, tf_colloc_u(cs->c), cs->n3 * sizeof *u);
    }
    return 0;
}

static int reactions(const tf_solver *s, int contact, const double force[3], const double *u,
                     double *r)
{
    csolver *cs = (csolver *)of_const(s); /* the solver's scratch; results unchanged */
    external(cs, contact, force);
    if (tf_colloc_forces(s->ctx, cs->c, u, 0, r, NULL) != 0) {
        return tf_fail(s->ctx, "mls-collocation: %s", s->ctx->err);
    }
    const double *fext = tf_colloc_fext(cs->c);
    for (size_t d = 0; d < cs->n3; ++d) {
        r[d] = -(r[d] + fext[d]); /* K u - f */
    }
    return 0;
}

static int field(tf_ctx *ctx, const tf_solver *s, const double *u, const double *x, size_t np,
                 double *uh, double *grad)
{
    return tf_colloc_field(ctx, of_const(s)->c, u, x, np, uh, grad);
}

static size_t node_count(const tf_solver *s) { return s->problem->cloud.n; }
static const double *coords(const tf_solver *s) { return s->problem->cloud.xyz; }

static void report(const tf_solver *s)
{
    const csolver *cs = of_const(s);
    size_t at;
    double rc = tf_colloc_rcond(cs->c, &at);
    tf_info(s->ctx, "mls-collocation: %zu relaxation steps over %zu static cases, %zu explicit "
                    "steps of load histories (stable step %.3g s); smallest moment-matrix "
                    "reciprocal condition %.3g (particle %zu)",
            cs->relax_steps, cs->relax_cases, cs->history_steps, cs->dt_crit, rc, at);
}

const tf_solver_ops tf_colloc_ops = {
    .name = "mls-collocation",
    .summary = "MLS collocation with nodal integration and explicit dynamics ([Aras-MLS]); "
               "any material law; static cases by dynamic relaxation",
    .create = create,
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
