/*
 * problem.c — what a problem owns and a few questions about it (problem.h).
 */
#include "problem/problem.h"

#include <stdlib.h>
#include <string.h>

void tf_problem_release(tf_problem *p)
{
    tf_cloud_free(&p->cloud);
    for (size_t k = 0; p->fixed && k < p->n_fixed; ++k) {
        free(p->fixed[k].nodes);
    }
    free(p->fixed);
    free(p->loads);
    free(p->contacts);
    free(p->outputs.nodes);
    free(p->cuts);
    memset(p, 0, sizeof *p);
}

int tf_problem_contact(const tf_problem *p, const char *name)
{
    for (size_t k = 0; k < p->n_contacts; ++k) {
        if (strcmp(p->contacts[k].name, name) == 0) {
            return (int)k;
        }
    }
    return -1;
}

void tf_problem_bounds(const tf_problem *p, double lo[3], double hi[3])
{
    switch (p->geometry.kind) {
    case TF_GEOMETRY_BOX:
        memcpy(lo, p->geometry.as.box.min, 3 * sizeof *lo);
        memcpy(hi, p->geometry.as.box.max, 3 * sizeof *hi);
        return;
    }
    memcpy(lo, p->cloud.lo, 3 * sizeof *lo); /* not reached: every kind is listed */
    memcpy(hi, p->cloud.hi, 3 * sizeof *hi);
}

void tf_problem_fixed_dofs(const tf_problem *p, unsigned char *mask)
{
    memset(mask, 0, 3 * p->cloud.n);
    for (size_t r = 0; r < p->n_fixed; ++r) {
        const tf_fixed *fx = &p->fixed[r];
        for (size_t q = 0; q < fx->n_nodes; ++q) {
            for (int a = 0; a < 3; ++a) {
                if (fx->components & (1u << a)) {
                    mask[3 * (size_t)fx->nodes[q] + (size_t)a] = 1;
                }
            }
        }
    }
}

int tf_problem_unloaded(const tf_problem *p)
{
    if (p->n_loads > 0) {
        return 0;
    }
    for (size_t r = 0; r < p->n_fixed; ++r) {
        const tf_fixed *fx = &p->fixed[r];
        for (int a = 0; a < 3; ++a) {
            if ((fx->components & (1u << a)) && (fx->exact || fx->value[a] != 0)) {
                return 0;
            }
        }
    }
    return 1;
}
