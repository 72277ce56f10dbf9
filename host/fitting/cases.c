/*
 * cases.c — see fit_cases.h.
 */
#include "fitting/cases.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fitting/fit_common.h"
#include "fitting/loadcases.h"
#include "base/log.h"

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
static void extract(const tf_scene *s, const tf_cases *c, const double *full, double *u,
                    double contact[3])
{
    for (size_t j = 0; j < s->outputs.n_nodes; ++j) {
        for (int k = 0; k < 3; ++k) {
            u[3 * j + (size_t)k] = full[3 * (size_t)s->outputs.nodes[j] + (size_t)k];
        }
    }
    for (int k = 0; k < 3; ++k) {
        contact[k] = full[3 * (size_t)c->contact_node + (size_t)k];
    }
}

/* Solves forces[n][3] at the contact site into the outputs of d. */
static int solve_into(const tf_scene *s, tf_solver *solver, tf_cases *c, const double (*f)[3],
                      size_t n, double *u, double (*contact)[3], char *err, size_t errlen)
{
    const size_t dofs = 3 * tf_solver_node_count(solver), rows = 3 * s->outputs.n_nodes;
    double *full = malloc(dofs * n * sizeof *full);
    if (full == NULL) {
        snprintf(err, errlen, "out of memory for %zu load cases of %zu DOFs", n, dofs);
        return -1;
    }
    int rc = tf_solver_solve(solver, c->contact, &f[0][0], n, full, err, errlen);
    for (size_t i = 0; rc == 0 && i < n; ++i) {
        extract(s, c, full + i * dofs, u + i * rows, contact[i]);
    }
    c->solves += n;
    free(full);
    return rc;
}

void tf_cases_response(const tf_cases *c, const double f[3], double *u, double contact[3])
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

/* Unit responses: no contact force, then e_x, e_y, e_z. */
static int unit_responses(const tf_scene *s, tf_solver *solver, tf_cases *c, char *err,
                          size_t errlen)
{
    const size_t rows = 3 * s->outputs.n_nodes;
    const double f[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    double *u = keep(c, malloc(4 * rows * sizeof *u));
    double contact[4][3];
    if (u == NULL || solve_into(s, solver, c, f, 4, u, contact, err, errlen) != 0) {
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
static int make_data(tf_cases *c, const tf_scene *s, tf_fitdata *d, size_t n, double (*forces)[3])
{
    const size_t rows = 3 * s->outputs.n_nodes;
    *d = (tf_fitdata){.n_cases = n, .force = (const double(*)[3])forces,
                      .n_out = (uint32_t)s->outputs.n_nodes, .node_ids = c->node_ids,
                      .rest = (const double(*)[3])c->rest, .radius = s->envelope_radius};
    memcpy(d->centre, s->envelope_centre, sizeof d->centre);
    d->u = keep(c, malloc(n * rows * sizeof(double)));
    d->contact = keep(c, malloc(n * sizeof(double[3])));
    return (d->u != NULL && d->contact != NULL) ? 0 : -1;
}

static void superpose(const tf_cases *c, tf_fitdata *d)
{
    const size_t rows = 3 * (size_t)d->n_out;
    for (size_t i = 0; i < d->n_cases; ++i) {
        tf_cases_response(c, d->force[i], (double *)d->u + i * rows, (double *)d->contact[i]);
    }
}

int tf_cases_build(const tf_scene *s, tf_solver *solver, int contact, size_t n_train,
                   size_t n_heldout, uint64_t seed, int direct, tf_cases *c, char *err,
                   size_t errlen)
{
    memset(c, 0, sizeof *c);
    c->contact = contact;
    c->contact_node = s->contacts[contact].node;
    const size_t n_out = s->outputs.n_nodes;
    c->node_ids = keep(c, malloc(n_out * sizeof *c->node_ids));
    c->rest = keep(c, malloc(n_out * sizeof *c->rest));
    double (*train)[3] = keep(c, malloc(n_train * sizeof *train));
    double (*held)[3] = keep(c, malloc(n_heldout * sizeof *held));
    double (*axes)[3] = keep(c, malloc(3 * n_train * sizeof *axes));
    if (!c->node_ids || !c->rest || !train || !held || !axes) {
        snprintf(err, errlen, "out of memory for the load cases");
        tf_cases_free(c);
        return -1;
    }
    const double *xyz = tf_solver_coords(solver);
    for (size_t j = 0; j < n_out; ++j) {
        c->node_ids[j] = tf_solver_node_number(solver, s->outputs.nodes[j]);
        memcpy(c->rest[j], xyz + 3 * (size_t)s->outputs.nodes[j], sizeof c->rest[j]);
    }
    tf_loadcases(s->envelope_centre, s->envelope_radius, n_train, n_heldout, seed, train, held);
    tf_round_to_float(train, n_train);
    tf_round_to_float(held, n_heldout);
    /* zhou2017's single-axis cases: each training force's component alone */
    for (int a = 0; a < 3; ++a) {
        for (size_t i = 0; i < n_train; ++i) {
            double *f = axes[(size_t)a * n_train + i];
            f[0] = f[1] = f[2] = 0;
            f[a] = train[i][a];
        }
    }
    int rc = make_data(c, s, &c->train, n_train, train) | make_data(c, s, &c->heldout, n_heldout, held);
    for (int a = 0; a < 3; ++a) {
        rc |= make_data(c, s, &c->axis[a], n_train, axes + (size_t)a * n_train);
    }
    if (rc != 0) {
        snprintf(err, errlen, "out of memory for the load cases");
        tf_cases_free(c);
        return -1;
    }
    rc = unit_responses(s, solver, c, err, errlen);
    c->superposed = !direct;
    if (rc == 0 && c->superposed) {
        tf_info("fit: the response is affine in the contact force (linear elasticity), so %s"
                "3 unit solves span all %zu training cases; the %zu held-out cases are solved "
                "directly",
                s->n_loads > 0 ? "the scene-load solve and " : "", n_train, n_heldout);
        superpose(c, &c->train);
        for (int a = 0; a < 3; ++a) {
            superpose(c, &c->axis[a]);
        }
    } else if (rc == 0) {
        tf_info("fit: solving all %zu training cases directly", n_train);
        rc = solve_into(s, solver, c, (const double(*)[3])train, n_train, (double *)c->train.u,
                        (double(*)[3])c->train.contact, err, errlen);
        for (int a = 0; rc == 0 && a < 3; ++a) {
            rc = solve_into(s, solver, c, c->axis[a].force, n_train, (double *)c->axis[a].u,
                            (double(*)[3])c->axis[a].contact, err, errlen);
        }
    }
    if (rc == 0) {
        rc = solve_into(s, solver, c, (const double(*)[3])held, n_heldout, (double *)c->heldout.u,
                        (double(*)[3])c->heldout.contact, err, errlen);
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
