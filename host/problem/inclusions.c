/*
 * inclusions.c — see inclusions.h.
 */
#include "problem/inclusions.h"

int tf_inclusion_holds(const tf_inclusion *c, const double x[3])
{
    const tf_region *r = &c->where;
    if (r->kind == TF_REGION_SPHERE) { /* sum ((x - c) / r_a)^2 <= 1 */
        double q = 0;
        for (int a = 0; a < 3; ++a) {
            const double t = (x[a] - r->centre[a]) / c->radii[a];
            q += t * t;
        }
        return q <= 1;
    }
    for (int a = 0; a < 3; ++a) {
        if (!(x[a] >= r->min[a] && x[a] <= r->max[a])) {
            return 0;
        }
    }
    return 1;
}

size_t tf_problem_region_at(const tf_problem *p, const double x[3])
{
    for (size_t k = 0; k < p->n_inclusions; ++k) {
        if (tf_inclusion_holds(&p->inclusions[k], x)) {
            return k + 1;
        }
    }
    return 0;
}

tf_lame tf_problem_lame_at(const tf_problem *p, const double x[3])
{
    size_t r = tf_problem_region_at(p, x);
    return tf_material_lame(r ? &p->inclusions[r - 1].material : &p->material);
}
