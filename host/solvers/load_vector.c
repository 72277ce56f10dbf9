/*
 * load_vector.c — nodal force vectors of patch tractions and point forces
 * (load_vector.h; seed eq 25).
 */
#include "solvers/load_vector.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "meshfree/tet_cells.h"
#include "problem/analytic.h"

/* Traction at x: a uniform force per area (ncol = 1), the three unit
 * columns (ncol = 3, force NULL), or the reference solution's (exact). */
typedef struct traction {
    const tf_problem *pr; /* exact: whose analytic solution */
    const tf_patch *p;
    const double *force;
    double area;
    int exact;
} traction;

static void traction_at(const traction *t, const double x[3], double out[9], size_t *ncol)
{
    if (t->exact) {
        tf_analytic_traction(t->pr, t->p->face, x, out);
        *ncol = 1;
    } else if (t->force) {
        for (int a = 0; a < 3; ++a) {
            out[a] = t->force[a] / t->area;
        }
        *ncol = 1;
    } else {
        for (int k = 0; k < 9; ++k) {
            out[k] = k % 4 == 0 ? 1 / t->area : 0; /* column a: e_a / area */
        }
        *ncol = 3;
    }
}

/* A TF_PATCH_POINTS patch's own quadrature points, copied. */
static tf_qpoint *given_points(const tf_patch *p, size_t *n)
{
    tf_qpoint *q = malloc((p->n_pts + 1) * sizeof *q);
    for (size_t k = 0; q != NULL && k < p->n_pts; ++k) {
        memcpy(q[k].x, p->pts + 4 * k, sizeof q[k].x);
        q[k].w = p->pts[4 * k + 3];
    }
    *n = q != NULL ? p->n_pts : 0;
    return q;
}

static int integrate(tf_ctx *ctx, const tf_shape *sh, const traction *t, double *f)
{
    size_t n3 = 3 * sh->cloud->n;
    if (t->p->shape == TF_PATCH_POINT) {
        double tr[9];
        size_t ncol;
        traction tp = *t;
        tp.area = 1; /* a point force is its own total */
        traction_at(&tp, sh->cloud->xyz + 3 * (size_t)t->p->node, tr, &ncol);
        for (size_t c = 0; c < ncol; ++c) {
            for (int a = 0; a < 3; ++a) {
                f[c * n3 + 3 * (size_t)t->p->node + (size_t)a] += tr[3 * c + (size_t)a];
            }
        }
        return 0;
    }
    size_t nq = 0;
    tf_qpoint *q = t->p->shape == TF_PATCH_AT        ? malloc(sizeof *q)
                   : t->p->shape == TF_PATCH_SURFACE ? tf_patch_surface_points(t->p, sh->cloud, &nq)
                   : t->p->shape == TF_PATCH_POINTS  ? given_points(t->p, &nq)
                                                     : tf_patch_points(t->p, sh->cloud, &sh->cells, &nq);
    if (q != NULL && t->p->shape == TF_PATCH_AT) {
        /* a point force: the Galerkin load phi_I(x) F (eq 25 with a point traction) */
        memcpy(q->x, t->p->at, sizeof q->x);
        q->w = 1;
        nq = 1;
    }
    if (q == NULL) {
        return tf_fail(ctx, "out of memory");
    }
    tf_shape_work w;
    tf_shape_work_init(&w);
    int rc = 0;
    for (size_t k = 0; k < nq && rc == 0; ++k) {
        rc = tf_shape_at(sh, &w, q[k].x, tf_shape_cell(sh, q[k].x), 0);
        if (rc != 0) {
            tf_fail(ctx, "load patch: %s", w.err);
            break;
        }
        double tr[9];
        size_t ncol;
        traction_at(t, q[k].x, tr, &ncol);
        for (size_t i = 0; i < w.n; ++i) {
            double wphi = q[k].w * w.phi[i];
            for (size_t c = 0; c < ncol; ++c) {
                for (int a = 0; a < 3; ++a) {
                    f[c * n3 + 3 * (size_t)w.idx[i] + (size_t)a] += wphi * tr[3 * c + (size_t)a];
                }
            }
        }
    }
    tf_shape_work_free(&w);
    free(q);
    return rc;
}

int tf_load_patch(tf_ctx *ctx, const tf_shape *sh, const tf_patch *p, const double *force,
                  double *f)
{
    traction t = {NULL, p, force, p->shape == TF_PATCH_AT ? 1 : tf_patch_area(p, sh->cloud), 0};
    return integrate(ctx, sh, &t, f);
}

int tf_load_exact(tf_ctx *ctx, const tf_shape *sh, const tf_problem *pr, const tf_patch *p,
                  double *f)
{
    traction t = {pr, p, NULL, tf_patch_area(p, sh->cloud), 1};
    return integrate(ctx, sh, &t, f);
}
