/*
 * registry.c — every solver type, by name (solver.h).  Adding a solver: its
 * folder under solvers/ with a tf_solver_ops, and one line in this table.
 */
#include <stdio.h>
#include <string.h>

#include "solvers/collocation/colloc_solver.h"
#include "solvers/galerkin/galerkin.h"
#include "solvers/nonlinear/nonlinear.h"
#include "solvers/solver.h"

static const tf_solver_ops *const types[] = {
    &tf_galerkin_ops,
    &tf_efg_galerkin_ops,
    &tf_rpim_newton_ops,
    &tf_efg_newton_ops,
    &tf_colloc_ops,
};

size_t tf_solver_type_count(void) { return sizeof types / sizeof types[0]; }

const tf_solver_ops *tf_solver_type_at(size_t i)
{
    return i < tf_solver_type_count() ? types[i] : NULL;
}

const tf_solver_ops *tf_solver_type_find(const char *name)
{
    for (size_t i = 0; i < tf_solver_type_count(); ++i) {
        if (strcmp(types[i]->name, name) == 0) {
            return types[i];
        }
    }
    return NULL;
}

void tf_solver_type_names(char *out, size_t outlen)
{
    size_t k = 0;
    out[0] = '\0';
    for (size_t i = 0; i < tf_solver_type_count() && k < outlen; ++i) {
        int n = snprintf(out + k, outlen - k, "%s%s", i ? ", " : "", types[i]->name);
        k += n > 0 ? (size_t)n : 0;
    }
}
