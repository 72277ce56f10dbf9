/*
 * probe.c — displacements at output points and contact sites (probe.h).
 */
#include "solvers/probe.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The field at np points (gradients computed and dropped). */
static int field_at(tf_ctx *ctx, const tf_solver *s, const double *u, const double *x, size_t np,
                    double *out)
{
    double *grad = malloc(9 * np * sizeof *grad);
    if (grad == NULL) {
        return tf_fail(ctx, "out of memory for %zu output points", np);
    }
    int rc = tf_solver_field(ctx, s, u, x, np, out, grad);
    free(grad);
    return rc;
}

int tf_solver_probe_outputs(tf_ctx *ctx, const tf_solver *s, const tf_problem *p, const double *u,
                            double *out)
{
    const tf_outputs *o = &p->outputs;
    if (o->points != NULL) {
        return field_at(ctx, s, u, o->points, o->n_nodes, out);
    }
    for (size_t j = 0; j < o->n_nodes; ++j) {
        memcpy(out + 3 * j, u + 3 * (size_t)o->nodes[j], 3 * sizeof *out);
    }
    return 0;
}

int tf_solver_probe_contact(tf_ctx *ctx, const tf_solver *s, const tf_problem *p, int k,
                            const double *u, double out[3])
{
    const tf_contact *c = &p->contacts[k];
    if (!c->by_node) {
        return field_at(ctx, s, u, c->at, 1, out);
    }
    memcpy(out, u + 3 * (size_t)c->node, 3 * sizeof *out);
    return 0;
}
