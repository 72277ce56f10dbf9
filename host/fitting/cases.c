/*
 * cases.c — the solved load cases of a fit (cases.h).
 */
#include "fitting/cases.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/log.h"
#include "fitting/force_samples.h"

static void *keep(tf_cases *c, void *p)
{
    if (p != NULL && c->n_blocks < (int)(sizeof c->blocks / sizeof c->blocks[0])) {
        c->blocks[c->n_blocks++] = p;
        return p;
    }
    free(p);
    return NULL;
}

/* The output rows and the contact site of a 3N solution. */
static void extract(const tf_cases *c, const double *full, double *u, double contact[3])
{
    const tf_outputs *o = &c->problem->outputs;
    for (size_t j = 0; u != NULL && j < o->n_nodes; ++j) {
        for (int k = 0; k < 3; ++k) {
            u[3 * j + (size_t)k] = full[3 * (size_t)o->nodes[j] + (size_t)k];
        }
    }
    for (int k = 0; contact != NULL && k < 3; ++k) {
        contact[k] = full[3 * (size_t)c->contact_node + (size_t)k];
    }
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
        extract(c, full + i * dofs, u ? u + i * rows : NULL, contact ? contact[i] : NULL);
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
        c->node_ids[j] = tf_problem_node_number(p, p->outputs.nodes[j]);
        memcpy(c->rest[j], xyz + 3 * (size_t)p->outputs.nodes[j], sizeof c->rest[j]);
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

/* Training and single-axis cases: superposed or solved. */
static int training(tf_cases *c, size_t n_heldout, int direct)
{
    tf_ctx *ctx = c->solver->ctx;
    const char *name = tf_solver_name(c->solver);
    if (c->affine && unit_responses(c) != 0) {
        return -1;
    }
    c->superposed = c->affine && !direct;
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
    tf_info(ctx, "fit: solving all %zu training cases directly%s", c->train.n_cases,
            c->affine ? "" : " (the solver's response is not affine in the force)");
    int rc = solve_data(c, &c->train);
    for (int a = 0; rc == 0 && a < 3; ++a) {
        rc = solve_data(c, &c->axis[a]);
    }
    return rc;
}

int tf_cases_build(const tf_problem *p, tf_solver *solver, int contact, size_t n_train,
                   size_t n_heldout, uint64_t seed, int direct, tf_cases *c)
{
    memset(c, 0, sizeof *c);
    c->solver = solver;
    c->problem = p;
    c->contact = contact;
    c->contact_node = p->contacts[contact].node;
    c->affine = (tf_solver_caps_of(solver) & TF_SOLVER_AFFINE) != 0;
    if (design(c, n_train, n_heldout, seed) != 0) {
        tf_cases_free(c);
        return tf_fail(solver->ctx, "out of memory for the load cases");
    }
    int rc = training(c, n_heldout, direct);
    if (rc == 0) {
        rc = solve_data(c, &c->heldout);
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
