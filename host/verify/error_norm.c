/*
 * error_norm.c — relative L2 and energy errors against a reference
 * solution (error_norm.h).
 */
#include "verify/error_norm.h"

#include <cblas.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#include "materials/elasticity.h"
#include "verify/reference.h"

/* Four sums per cell: error and reference, L2 and energy. */
typedef struct sums {
    double e2, u2, ee, ue;
} sums;

static double energy_density(const double d[36], const double g[9])
{
    double eps[6], e = 0;
    tf_strain(g, eps);
    for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) {
            e += eps[i] * d[6 * i + j] * eps[j];
        }
    }
    return e;
}

static int cell_sums(const tf_shape *sh, const tf_scene *s, const double *u, const tf_cells *q,
                     const double d[36], tf_shape_work *w, size_t cell, sums *out)
{
    for (size_t p = 0; p < tf_cells_points(q); ++p) {
        double x[3], wt, ue[3], ge[9], uh[3] = {0, 0, 0}, gh[9] = {0};
        tf_cells_point(q, cell, p, x, &wt);
        if (tf_shape_at(sh, w, x, tf_shape_cell(sh, x), 1) != 0) {
            return -1;
        }
        for (size_t k = 0; k < w->n; ++k) {
            const double *ui = u + 3 * (size_t)w->idx[k];
            for (int i = 0; i < 3; ++i) {
                uh[i] += w->phi[k] * ui[i];
                for (int j = 0; j < 3; ++j) {
                    gh[3 * i + j] += w->dphi[(size_t)j * w->n + k] * ui[i];
                }
            }
        }
        tf_reference_eval(s, x, ue, ge);
        double diff[9];
        for (int k = 0; k < 9; ++k) {
            diff[k] = gh[k] - ge[k];
        }
        for (int i = 0; i < 3; ++i) {
            out->e2 += wt * (uh[i] - ue[i]) * (uh[i] - ue[i]);
            out->u2 += wt * ue[i] * ue[i];
        }
        out->ee += wt * energy_density(d, diff);
        out->ue += wt * energy_density(d, ge);
    }
    return 0;
}

int tf_error_norms(const tf_shape *sh, const tf_scene *s, const double *u, unsigned order,
                   double *l2, double *energy, char *err, size_t errlen)
{
    if (s->reference.kind == TF_REF_NONE) {
        snprintf(err, errlen, "%s has no reference solution", s->source);
        return -1;
    }
    tf_cells q;
    if (tf_cells_init(&q, s->box_min, s->box_max, sh->cells.n, order) != 0) {
        snprintf(err, errlen, "bad quadrature order %u", order);
        return -1;
    }
    double d[36];
    tf_dmatrix(s->young, s->poisson, d);
    size_t nc = tf_cells_count(&q);
    sums *per = calloc(nc, sizeof *per);
    if (per == NULL) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    int failed = 0;
    openblas_set_num_threads(1); /* LAPACK inside OpenMP threads: one thread each */
#pragma omp parallel reduction(| : failed)
    {
        tf_shape_work w;
        tf_shape_work_init(&w);
#pragma omp for schedule(dynamic, 8)
        for (size_t c = 0; c < nc; ++c) {
            failed |= cell_sums(sh, s, u, &q, d, &w, c, &per[c]) != 0;
        }
        tf_shape_work_free(&w);
    }
    /* Summed in cell order: the same bits whatever the thread count. */
    sums t = {0, 0, 0, 0};
    for (size_t c = 0; c < nc; ++c) {
        t.e2 += per[c].e2;
        t.u2 += per[c].u2;
        t.ee += per[c].ee;
        t.ue += per[c].ue;
    }
    free(per);
    if (failed) {
        snprintf(err, errlen, "a local RPIM system is singular");
        return -1;
    }
    *l2 = t.u2 > 0 ? sqrt(t.e2 / t.u2) : sqrt(t.e2);
    *energy = t.ue > 0 ? sqrt(t.ee / t.ue) : sqrt(t.ee);
    return 0;
}
