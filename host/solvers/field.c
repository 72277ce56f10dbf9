/*
 * field.c — the displacement field between the nodes (field.h).
 */
#include "solvers/field.h"

#include <stdio.h>

int tf_shape_field(tf_ctx *ctx, const tf_shape *sh, const double *d, const double *x, size_t np,
                   double *uh, double *grad)
{
    tf_shape_work w;
    tf_shape_work_init(&w);
    int rc = 0;
    for (size_t p = 0; p < np && rc == 0; ++p) {
        const double *xp = x + 3 * p;
        double *up = uh + 3 * p, *gp = grad + 9 * p;
        rc = tf_shape_at(sh, &w, xp, tf_shape_cell(sh, xp), 1);
        if (rc != 0) {
            tf_fail(ctx, "%s", w.err);
            break;
        }
        for (int i = 0; i < 9; ++i) {
            gp[i] = 0;
        }
        up[0] = up[1] = up[2] = 0;
        for (size_t k = 0; k < w.n; ++k) {
            const double *ui = d + 3 * (size_t)w.idx[k];
            for (int i = 0; i < 3; ++i) {
                up[i] += w.phi[k] * ui[i];
                for (int j = 0; j < 3; ++j) {
                    gp[3 * i + j] += w.dphi[(size_t)j * w.n + k] * ui[i];
                }
            }
        }
    }
    tf_shape_work_free(&w);
    return rc;
}

int tf_nodal_field(tf_ctx *ctx, const tf_shape *sh, tf_nodal_map *map, const double *u,
                   const double *x, size_t np, double *uh, double *grad)
{
    if (map != NULL && (u = tf_nodal_map_params_of(ctx, map, u)) == NULL) {
        return -1;
    }
    return tf_shape_field(ctx, sh, u, x, np, uh, grad);
}
