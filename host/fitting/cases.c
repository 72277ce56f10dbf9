/*
 * cases.c — the solved load cases of a fit (cases.h).
 */
#include "fitting/cases.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/log.h"
#include "fitting/case_graph.h"
#include "fitting/case_runner.h"
#include "fitting/force_samples.h"
#include "solvers/probe.h"

#define TABLE_CASES (3 * TF_FAMILY_LEVELS)

static void *keep(tf_cases *c, void *p)
{
    if (p != NULL && c->n_blocks < (int)(sizeof c->blocks / sizeof c->blocks[0])) {
        c->blocks[c->n_blocks++] = p;
        return p;
    }
    free(p);
    return NULL;
}

/* The output rows and the contact site of a 3N solution (solvers/probe.h:
 * nodal values, or the field at points between nodes). */
static int extract(const tf_cases *c, const double *full, double *u, double contact[3])
{
    tf_ctx *ctx = c->solver->ctx;
    if (u != NULL && tf_solver_probe_outputs(ctx, c->solver, c->problem, full, u) != 0) {
        return -1;
    }
    if (contact != NULL &&
        tf_solver_probe_contact(ctx, c->solver, c->problem, c->contact, full, contact) != 0) {
        return -1;
    }
    return 0;
}

/* Solves forces[n][3] at the contact site into output rows u (3 n_out x n)
 * and contact displacements (n x 3); either may be NULL. */
static int solve_into(tf_cases *c, const double (*f)[3], size_t n, double *u,
                      double (*contact)[3])
{
    const size_t dofs = 3 * tf_solver_node_count(c->solver);
    const size_t rows = 3 * c->problem->outputs.n_nodes;
    double *full = malloc(dofs * n * sizeof *full);
    if (full == NULL) {
        return tf_fail(c->solver->ctx, "out of memory for %zu load cases of %zu DOFs", n, dofs);
    }
    int rc = tf_solver_solve(c->solver, c->contact, f, n, NULL, full);
    for (size_t i = 0; rc == 0 && i < n; ++i) {
        rc = extract(c, full + i * dofs, u ? u + i * rows : NULL, contact ? contact[i] : NULL);
    }
    c->solves += n;
    free(full);
    return rc;
}

static void superposed(const tf_cases *c, const double f[3], double *u, double contact[3])
{
    const size_t rows = 3 * (size_t)c->train.n_out;
    for (size_t o = 0; u != NULL && o < rows; ++o) {
        u[o] = c->base[o] + f[0] * c->unit[0][o] + f[1] * c->unit[1][o] + f[2] * c->unit[2][o];
    }
    for (int k = 0; contact != NULL && k < 3; ++k) {
        contact[k] = c->base_contact[k] + f[0] * c->unit_contact[0][k] +
                     f[1] * c->unit_contact[1][k] + f[2] * c->unit_contact[2][k];
    }
}

int tf_cases_response(tf_cases *c, const double f[3], double *u, double contact[3])
{
    if (c->affine) {
        superposed(c, f, u, contact);
        return 0;
    }
    const double (*one)[3] = (const double(*)[3])f;
    double at[1][3];
    int rc = solve_into(c, one, 1, u, contact ? at : NULL);
    if (rc == 0 && contact != NULL) {
        memcpy(contact, at[0], sizeof at[0]);
    }
    return rc;
}

/* Unit responses: no contact force, then e_x, e_y, e_z. */
static int unit_responses(tf_cases *c)
{
    const size_t rows = 3 * c->problem->outputs.n_nodes;
    const double f[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    double *u = keep(c, malloc(4 * rows * sizeof *u));
    double contact[4][3];
    if (u == NULL) {
        return tf_fail(c->solver->ctx, "out of memory for the unit responses");
    }
    if (solve_into(c, f, 4, u, contact) != 0) {
        return -1;
    }
    c->base = u;
    memcpy(c->base_contact, contact[0], sizeof contact[0]);
    for (int k = 0; k < 3; ++k) {
        c->unit[k] = u + (size_t)(k + 1) * rows;
        for (size_t o = 0; o < rows; ++o) {
            c->unit[k][o] -= c->base[o];
        }
        for (int a = 0; a < 3; ++a) {
            c->unit_contact[k][a] = contact[k + 1][a] - contact[0][a];
        }
    }
    return 0;
}

/* A tf_fitdata of n cases with room for their displacements. */
static int make_data(tf_cases *c, tf_fitdata *d, size_t n, double (*forces)[3])
{
    const tf_problem *p = c->problem;
    const size_t rows = 3 * p->outputs.n_nodes;
    *d = (tf_fitdata){.n_cases = n, .force = (const double(*)[3])forces,
                      .n_out = (uint32_t)p->outputs.n_nodes, .node_ids = c->node_ids,
                      .rest = (const double(*)[3])c->rest, .radius = p->envelope.radius};
    memcpy(d->centre, p->envelope.centre, sizeof d->centre);
    d->u = keep(c, malloc(n * rows * sizeof(double)));
    d->contact = keep(c, malloc(n * sizeof(double[3])));
    return (d->u != NULL && d->contact != NULL) ? 0 : -1;
}

static void superpose(const tf_cases *c, tf_fitdata *d)
{
    const size_t rows = 3 * (size_t)d->n_out;
    for (size_t i = 0; i < d->n_cases; ++i) {
        superposed(c, d->force[i], (double *)d->u + i * rows, (double *)d->contact[i]);
    }
}

static int solve_data(tf_cases *c, tf_fitdata *d)
{
    return solve_into(c, d->force, d->n_cases, (double *)d->u, (double(*)[3])d->contact);
}

/* The forces: training and held-out cases in the envelope, rounded to
 * float, and zhou2017's single-axis cases (each training force's component
 * alone); then room for their displacements. */
static int design(tf_cases *c, size_t n_train, size_t n_heldout, uint64_t seed)
{
    const tf_problem *p = c->problem;
    const size_t n_out = p->outputs.n_nodes;
    c->node_ids = keep(c, malloc(n_out * sizeof *c->node_ids));
    c->rest = keep(c, malloc(n_out * sizeof *c->rest));
    double (*train)[3] = keep(c, malloc(n_train * sizeof *train));
    double (*held)[3] = keep(c, malloc(n_heldout * sizeof *held));
    double (*axes)[3] = keep(c, malloc(3 * n_train * sizeof *axes));
    if (!c->node_ids || !c->rest || !train || !held || !axes) {
        return -1;
    }
    const double *xyz = tf_solver_coords(c->solver);
    for (size_t j = 0; j < n_out; ++j) {
        /* output points between nodes are numbered 1, 2, ... in the header */
        const double *x = p->outputs.points ? p->outputs.points + 3 * j
                                            : xyz + 3 * (size_t)p->outputs.nodes[j];
        c->node_ids[j] = p->outputs.points ? (uint32_t)j + 1
                                           : tf_problem_node_number(p, p->outputs.nodes[j]);
        memcpy(c->rest[j], x, sizeof c->rest[j]);
    }
    tf_force_samples(p->envelope.centre, p->envelope.radius, n_train, n_heldout, seed, train,
                     held);
    tf_forces_to_float(train, n_train);
    tf_forces_to_float(held, n_heldout);
    for (int a = 0; a < 3; ++a) {
        for (size_t i = 0; i < n_train; ++i) {
            double *f = axes[(size_t)a * n_train + i];
            f[0] = f[1] = f[2] = 0;
            f[a] = train[i][a];
        }
    }
    int rc = make_data(c, &c->train, n_train, train) | make_data(c, &c->heldout, n_heldout, held);
    for (int a = 0; a < 3; ++a) {
        rc |= make_data(c, &c->axis[a], n_train, axes + (size_t)a * n_train);
    }
    return rc;
}

/* Training and single-axis cases of an affine solver: superposed, or
 * solved in batches (--direct). */
static int training(tf_cases *c, size_t n_heldout, int direct)
{
    tf_ctx *ctx = c->solver->ctx;
    const char *name = tf_solver_name(c->solver);
    if (unit_responses(c) != 0) {
        return -1;
    }
    c->superposed = !direct;
    if (c->superposed) {
        tf_info(ctx,
                "fit: the %s solver's response is affine in the contact force, so %s3 unit "
                "solves span all %zu training cases; the %zu held-out cases are solved directly",
                name, c->problem->n_loads > 0 ? "the scene-load solve and " : "",
                c->train.n_cases, n_heldout);
        superpose(c, &c->train);
        for (int a = 0; a < 3; ++a) {
            superpose(c, &c->axis[a]);
        }
        return 0;
    }
    tf_info(ctx, "fit: solving all %zu training cases directly", c->train.n_cases);
    int rc = solve_data(c, &c->train);
    for (int a = 0; rc == 0 && a < 3; ++a) {
        rc = solve_data(c, &c->axis[a]);
    }
    return rc;
}

/* The DOFs a case keeps: the outputs' rows, then the contact site's. */
static void kept_dofs(const tf_cases *c, size_t *keep)
{
    const tf_outputs *o = &c->problem->outputs;
    for (size_t j = 0; j < o->n_nodes; ++j) {
        for (size_t k = 0; k < 3; ++k) {
            keep[3 * j + k] = 3 * (size_t)o->nodes[j] + k;
        }
    }
    for (size_t k = 0; k < 3; ++k) {
        keep[3 * o->n_nodes + k] = 3 * (size_t)c->contact_node + k;
    }
}

/* The list's kept values back into the data sets and the table. */
static void unpack(tf_cases *c, tf_fitdata *const *sets, const double *kept)
{
    const size_t rows = 3 * c->problem->outputs.n_nodes, stride = rows + 3;
    for (int s = 0; s < 5; ++s) {
        tf_fitdata *d = sets[s];
        for (size_t i = 0; i < d->n_cases; ++i, kept += stride) {
            memcpy((double *)d->u + i * rows, kept, rows * sizeof *kept);
            memcpy((double *)d->contact[i], kept + rows, 3 * sizeof *kept);
        }
    }
    for (size_t i = 0; i < TABLE_CASES; ++i, kept += stride) {
        memcpy(c->table + i * rows, kept, rows * sizeof *kept);
    }
}

/* 1 when every output and the contact site is a node: a case then keeps
 * those nodes' values (kept_dofs).  Else it keeps every DOF and the sites
 * are read from the solver's field there (probe_kept), as the affine path
 * reads them; a solver without a field between nodes is refused, naming
 * the point, rather than read at the nearest node.  Returns 1, 0, or -1. */
static int sites_on_nodes(const tf_cases *c)
{
    const tf_problem *p = c->problem;
    const tf_contact *k = &p->contacts[c->contact];
    const double *xyz = tf_solver_coords(c->solver);
    const double *at = NULL;
    for (size_t j = 0; at == NULL && p->outputs.points != NULL && j < p->outputs.n_nodes; ++j) {
        const double *x = p->outputs.points + 3 * j, *n = xyz + 3 * (size_t)p->outputs.nodes[j];
        at = fabs(x[0] - n[0]) + fabs(x[1] - n[1]) + fabs(x[2] - n[2]) > 1e-9 ? x : NULL;
    }
    const double *n = xyz + 3 * (size_t)k->node;
    if (at == NULL && !k->by_node &&
        fabs(k->at[0] - n[0]) + fabs(k->at[1] - n[1]) + fabs(k->at[2] - n[2]) > 1e-9) {
        at = k->at;
    }
    if (at == NULL) {
        return 1;
    }
    if (tf_solver_has_field(c->solver)) {
        return 0;
    }
    return tf_fail(c->solver->ctx,
                   "fit: the %s solver's response is not affine and it has no displacement "
                   "field between nodes: the point (%g, %g, %g) mm lies between nodes; choose "
                   "a grid with a node there",
                   tf_solver_name(c->solver), at[0], at[1], at[2]);
}

/* Every case's whole solution (n_all values) in kept, compacted in place to
 * the outputs' and the contact site's displacements (stride values). */
static int probe_kept(tf_cases *c, size_t n, size_t n_all, double *kept)
{
    const size_t stride = 3 * c->problem->outputs.n_nodes + 3;
    double *row = malloc(stride * sizeof *row);
    if (row == NULL) {
        return tf_fail(c->solver->ctx, "out of memory for %zu output points", stride / 3);
    }
    int rc = 0;
    for (size_t i = 0; rc == 0 && i < n; ++i) {
        const double *u = kept + i * n_all;
        rc = tf_solver_probe_outputs(c->solver->ctx, c->solver, c->problem, u, row);
        if (rc == 0) {
            rc = tf_solver_probe_contact(c->solver->ctx, c->solver, c->problem, c->contact, u,
                                         row + stride - 3);
        }
        if (rc == 0) { /* row first: case i's values overlap its own compacted place */
            memcpy(kept + i * stride, row, stride * sizeof *row);
        }
    }
    free(row);
    return rc;
}

/* A solver that is not affine: every case, one by one, as one list with
 * the anchored continuation graph, by the plan's runner. */
static int solve_all(tf_cases *c, const tf_case_runner *runner)
{
    const int on_nodes = sites_on_nodes(c);
    if (on_nodes < 0) {
        return -1;
    }
    tf_fitdata *const sets[5] = {&c->train, &c->axis[0], &c->axis[1], &c->axis[2], &c->heldout};
    static const char *const names[6] = {"training", "x-axis", "y-axis", "z-axis", "held-out",
                                         "seed-table"};
    /* The single-axis cases serve zhou2017 alone, which needs the outputs on
     * one plane: on any other output set (every organ's) they are not
     * solved, three times the training cases saved */
    double zlo, zhi;
    if (!tf_fitdata_flat(&c->train, &zlo, &zhi)) {
        for (int a = 0; a < 3; ++a) {
            c->axis[a].n_cases = 0;
        }
    }
    const size_t rows = 3 * c->problem->outputs.n_nodes;
    tf_case_segment seg[6];
    size_t n = 0;
    for (int s = 0; s < 6; ++s) {
        seg[s] = (tf_case_segment){names[s], n};
        n += s < 5 ? sets[s]->n_cases : TABLE_CASES;
    }
    const size_t n_keep = on_nodes ? rows + 3 : 3 * tf_solver_node_count(c->solver);
    double (*forces)[3] = malloc(n * sizeof *forces);
    long *from = malloc(n * sizeof *from);
    size_t *dofs = malloc(n_keep * sizeof *dofs);
    double *kept = malloc(n * n_keep * sizeof *kept);
    c->table = keep(c, malloc(TABLE_CASES * rows * sizeof *c->table));
    int rc = -1;
    if (forces && from && dofs && kept && c->table) {
        size_t i = 0;
        for (int s = 0; s < 5; ++s) {
            memcpy(forces + i, sets[s]->force, sets[s]->n_cases * sizeof *forces);
            i += sets[s]->n_cases;
        }
        for (int a = 0; a < 3; ++a) {
            for (int level = 1; level <= TF_FAMILY_LEVELS; ++level) {
                tf_cases_level_force(&c->train, a, level, forces[i++]);
            }
        }
        size_t anchors = tf_case_graph_anchors(n);
        tf_case_graph_anchored((const double(*)[3])forces, n, anchors, from);
        if (on_nodes) {
            kept_dofs(c, dofs);
        } else {
            for (size_t j = 0; j < n_keep; ++j) {
                dofs[j] = j;
            }
        }
        const tf_case_list list = {.contact = c->contact, .n = n,
                                   .force = (const double(*)[3])forces, .from = from,
                                   .n_keep = n_keep, .keep = dofs, .n_seg = 6, .seg = seg};
        tf_info(c->solver->ctx,
                "fit: the %s solver's response is not affine in the contact force: solving all "
                "%zu load cases one by one (%s), each from rest or from the nearest of %zu "
                "anchor cases",
                tf_solver_name(c->solver), n, runner != NULL ? runner->name : "here", anchors);
        rc = tf_case_run(runner, c->solver, &list, kept);
        if (rc == 0 && !on_nodes) {
            rc = probe_kept(c, n, n_keep, kept);
        }
        if (rc == 0) {
            unpack(c, sets, kept);
            c->solves += n;
        }
    } else {
        tf_fail(c->solver->ctx, "out of memory for %zu load cases", n);
    }
    free(forces);
    free(from);
    free(dofs);
    free(kept);
    return rc;
}

void tf_cases_level_force(const tf_fitdata *d, int a, int level, double f[3])
{
    double s = d->radius * level / TF_FAMILY_LEVELS;
    for (int k = 0; k < 3; ++k) {
        f[k] = (double)(float)d->centre[k];
    }
    f[a] = (double)(float)(d->centre[a] + s);
}

void tf_cases_level_response(const tf_cases *c, int a, int level, double *u)
{
    if (c->affine) {
        double f[3];
        tf_cases_level_force(&c->train, a, level, f);
        superposed(c, f, u, NULL);
        return;
    }
    const size_t rows = 3 * (size_t)c->train.n_out;
    memcpy(u, c->table + ((size_t)a * TF_FAMILY_LEVELS + (size_t)(level - 1)) * rows,
           rows * sizeof *u);
}

/* tf_cases.contact_id: an output point at the contact point (1e-9 of the
 * body's size: the same point written twice) names it; else its node. */
static uint32_t contact_id(const tf_problem *p, int contact)
{
    const tf_contact *k = &p->contacts[contact];
    const double *lo = p->cloud.lo, *hi = p->cloud.hi;
    const double tol = 1e-9 * hypot(hypot(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
    for (size_t j = 0; !k->by_node && p->outputs.points != NULL && j < p->outputs.n_nodes; ++j) {
        const double *x = p->outputs.points + 3 * j;
        if (fabs(x[0] - k->at[0]) <= tol && fabs(x[1] - k->at[1]) <= tol &&
            fabs(x[2] - k->at[2]) <= tol) {
            return (uint32_t)j + 1;
        }
    }
    return tf_problem_node_number(p, k->node);
}

int tf_cases_build(const tf_problem *p, tf_solver *solver, const tf_fit_plan *plan,
                   tf_cases *c)
{
    memset(c, 0, sizeof *c);
    c->solver = solver;
    c->problem = p;
    c->contact = plan->contact;
    c->contact_node = p->contacts[plan->contact].node;
    c->contact_id = contact_id(p, plan->contact);
    c->affine = (tf_solver_caps_of(solver) & TF_SOLVER_AFFINE) != 0;
    if (design(c, plan->n_train, plan->n_heldout, plan->seed) != 0) {
        tf_cases_free(c);
        return tf_fail(solver->ctx, "out of memory for the load cases");
    }
    int rc;
    if (c->affine) {
        rc = training(c, plan->n_heldout, plan->direct);
        if (rc == 0) {
            rc = solve_data(c, &c->heldout);
        }
    } else {
        rc = solve_all(c, plan->runner);
    }
    if (rc != 0) {
        tf_cases_free(c);
    }
    return rc;
}

void tf_cases_free(tf_cases *c)
{
    for (int i = 0; i < c->n_blocks; ++i) {
        free(c->blocks[i]);
    }
    c->n_blocks = 0;
}
