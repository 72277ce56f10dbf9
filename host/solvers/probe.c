/*
 * probe.c — displacements at output points and contact sites (probe.h).
 */
#include "solvers/probe.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The field at np points (gradients computed and dropped). */
static int field_at(const tf_solver *s, const double *u, const double *x, size_t np, double *out,
                    char *err, size_t errlen)
{
    double *grad = malloc(9 * np * sizeof *grad);
    if (grad == NULL) {
        snprintf(err, errlen, "out of memory for %zu output points", np);
        return -1;
    }
    int rc = tf_solver_field(s, u, x, np, out, grad, err, errlen);
    free(grad);
    return rc;
}

int tf_solver_probe_outputs(const tf_solver *s, const tf_problem *p, const double *u, double *out,
                     char *err, size_t errlen)
{
    const tf_outputs *o = &p->outputs;
    if (o->points != NULL) {
        return field_at(s, u, o->points, o->n_nodes, out, err, errlen);
    }
    for (size_t j = 0; j < o->n_nodes; ++j) {
        memcpy(out + 3 * j, u + 3 * (size_t)o->nodes[j], 3 * sizeof *out);
    }
    return 0;
}

int tf_solver_probe_contact(const tf_solver *s, const tf_problem *p, int k, const double *u,
                     double out[3], char *err, size_t errlen)
{
    const tf_contact *c = &p->contacts[k];
    if (!c->by_node) {
        return field_at(s, u, c->at, 1, out, err, errlen);
    }
    memcpy(out, u + 3 * (size_t)c->node, 3 * sizeof *out);
    return 0;
}
