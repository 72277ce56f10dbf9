/*
 * boundary.c — Gamma_u's quadrature and the weak essential conditions of a
 * linear Galerkin system (boundary.h).
 */
#include "solvers/boundary.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "problem/analytic.h"
#include "solvers/sparsity.h"

/* The face a fixed region names, or -1 when it is not a face of the box. */
static int region_face(const tf_region *r, const tf_cloud *c)
{
    if (r->kind == TF_REGION_FACE) {
        return (int)r->face;
    }
    if (r->kind == TF_REGION_PLANE) {
        double tol = tf_cloud_tol(c);
        if (fabs(r->at - c->lo[r->axis]) <= tol) {
            return 2 * r->axis;
        }
        if (fabs(r->at - c->hi[r->axis]) <= tol) {
            return 2 * r->axis + 1;
        }
    }
    return -1;
}

/* Appends the points of fixed region k's face to b->pt (room for them is
 * made here). */
static int add_region(tf_ctx *ctx, tf_boundary *b, const tf_problem *p, const tf_shape *sh,
                      size_t k, int face)
{
    const tf_fixed *fx = &p->fixed[k];
    tf_patch patch = {.shape = TF_PATCH_FACE, .face = (tf_face)face};
    size_t nq = 0;
    tf_qpoint *q = tf_patch_points(&patch, &p->cloud, &sh->cells, &nq);
    tf_bpoint *grown = q ? realloc(b->pt, (b->n + nq + 1) * sizeof *b->pt) : NULL;
    if (grown == NULL) {
        free(q);
        return tf_fail(ctx, "out of memory for the boundary points");
    }
    b->pt = grown;
    int axis = tf_face_axis((tf_face)face);
    for (size_t i = 0; i < nq; ++i) {
        tf_bpoint *bp = &b->pt[b->n++];
        memset(bp, 0, sizeof *bp);
        memcpy(bp->x, q[i].x, sizeof bp->x);
        bp->w = q[i].w;
        bp->n[axis] = tf_face_is_max((tf_face)face) ? 1 : -1;
        bp->mask = fx->components;
        bp->region = (uint32_t)k;
        bp->cell = tf_shape_cell(sh, bp->x);
        if (fx->exact) {
            double g[9];
            tf_analytic_eval(p, bp->x, bp->ubar, g);
        } else {
            memcpy(bp->ubar, fx->value, sizeof bp->ubar);
        }
    }
    free(q);
    return 0;
}

/* Counting sort of the points by cell (stable), and the cell index. */
static int sort_by_cell(tf_boundary *b, size_t n_cells)
{
    tf_bpoint *sorted = malloc((b->n + 1) * sizeof *sorted);
    b->cell_ptr = calloc(n_cells + 2, sizeof *b->cell_ptr);
    if (sorted == NULL || b->cell_ptr == NULL) {
        free(sorted);
        return -1;
    }
    b->n_cells = n_cells;
    for (size_t i = 0; i < b->n; ++i) {
        b->cell_ptr[b->pt[i].cell + 1]++;
    }
    for (size_t c = 0; c < n_cells; ++c) {
        b->cell_ptr[c + 1] += b->cell_ptr[c];
    }
    size_t *fill = malloc((n_cells + 1) * sizeof *fill);
    if (fill == NULL) {
        free(sorted);
        return -1;
    }
    memcpy(fill, b->cell_ptr, n_cells * sizeof *fill);
    for (size_t i = 0; i < b->n; ++i) {
        sorted[fill[b->pt[i].cell]++] = b->pt[i];
    }
    free(fill);
    free(b->pt);
    b->pt = sorted;
    return 0;
}

int tf_boundary_build(tf_ctx *ctx, tf_boundary *b, const tf_problem *p, const tf_shape *sh)
{
    memset(b, 0, sizeof *b);
    for (size_t k = 0; k < p->n_fixed; ++k) {
        int face = region_face(&p->fixed[k].where, &p->cloud);
        if (face < 0) {
            tf_fail(ctx,
                    "fixed region %zu is not a face of the box: weak essential conditions "
                    "(solver.bc: penalty or nitsche with efg-galerkin, nitsche with "
                    "rpim-galerkin) integrate over faces; use rpim-galerkin with "
                    "bc: elimination for a box or an interior plane",
                    k);
            tf_boundary_free(b);
            return -1;
        }
        if (add_region(ctx, b, p, sh, k, face) != 0) {
            tf_boundary_free(b);
            return -1;
        }
    }
    if (sort_by_cell(b, tf_cells_count(&sh->cells)) != 0) {
        tf_fail(ctx, "out of memory for the boundary points");
        tf_boundary_free(b);
        return -1;
    }
    return 0;
}

void tf_boundary_free(tf_boundary *b)
{
    free(b->pt);
    free(b->cell_ptr);
    memset(b, 0, sizeof *b);
}

double tf_boundary_scale(const tf_lame *l, const tf_cloud *c)
{
    double h = fmin(c->spacing[0], fmin(c->spacing[1], c->spacing[2]));
    return (l->lambda + 2 * l->mu) / h;
}

/* (sigma(phi e_b) n)_a for a node with gradient g: the traction of a unit
 * displacement along b, t[3 b + a]. */
static void unit_tractions(const tf_lame *l, const double g[3], const double n[3], double t[9])
{
    double gn = g[0] * n[0] + g[1] * n[1] + g[2] * n[2];
    for (int b = 0; b < 3; ++b) {
        for (int a = 0; a < 3; ++a) {
            t[3 * b + a] = l->lambda * g[b] * n[a] + l->mu * (g[a] * n[b] + (a == b ? gn : 0));
        }
    }
}

/* The weak terms of one point into the dense local matrix kl (3n x 3n,
 * column major) and rhs (3N). */
static void point_terms(const tf_bpoint *q, const tf_shape_work *w, tf_bc_method method,
                        double factor, const tf_lame *l, double *kl, double *t, double *rhs)
{
    size_t n = w->n, dim = 3 * n;
    const double *phi = w->phi, *d = w->dphi;
    for (size_t i = 0; method == TF_BC_NITSCHE && i < n; ++i) {
        const double g[3] = {d[i], d[n + i], d[2 * n + i]};
        unit_tractions(l, g, q->n, t + 9 * i);
    }
    double s[3];
    for (int a = 0; a < 3; ++a) {
        s[a] = (q->mask >> a) & 1u ? 1.0 : 0.0;
    }
    for (size_t j = 0; j < n; ++j) {
        for (int b = 0; b < 3; ++b) {
            double *col = kl + dim * (3 * j + (size_t)b);
            for (size_t i = 0; i < n; ++i) {
                for (int a = 0; a < 3; ++a) {
                    double v = a == b ? factor * phi[i] * phi[j] * s[a] : 0;
                    if (method == TF_BC_NITSCHE) {
                        v -= phi[i] * s[a] * t[9 * j + 3 * b + a] +
                             t[9 * i + 3 * a + b] * s[b] * phi[j];
                    }
                    col[3 * i + (size_t)a] += q->w * v;
                }
            }
        }
    }
    for (size_t i = 0; i < n; ++i) {
        double *r = rhs + 3 * (size_t)w->idx[i];
        for (int a = 0; a < 3; ++a) {
            double v = factor * phi[i] * s[a] * q->ubar[a];
            for (int b = 0; method == TF_BC_NITSCHE && b < 3; ++b) {
                v -= t[9 * i + 3 * a + b] * s[b] * q->ubar[b];
            }
            r[a] += q->w * v;
        }
    }
}

int tf_boundary_add_linear(tf_ctx *ctx, const tf_boundary *b, const tf_shape *sh,
                           tf_bc_method method, double factor, const tf_lame *l, tf_csc *k,
                           double *rhs)
{
    tf_shape_work w;
    tf_shape_work_init(&w);
    double *kl = NULL, *t = NULL;
    size_t cap = 0;
    int rc = 0;
    for (size_t p = 0; p < b->n && rc == 0; ++p) {
        const tf_bpoint *q = &b->pt[p];
        if (tf_shape_at(sh, &w, q->x, q->cell, method == TF_BC_NITSCHE) != 0) {
            tf_fail(ctx, "boundary point (%g, %g, %g) mm: %s", q->x[0], q->x[1], q->x[2], w.err);
            rc = -1;
            break;
        }
        if (w.n > cap) {
            cap = w.n;
            free(kl);
            free(t);
            kl = malloc(9 * cap * cap * sizeof *kl);
            t = malloc(9 * cap * sizeof *t);
            if (kl == NULL || t == NULL) {
                tf_fail(ctx, "out of memory");
                rc = -1;
                break;
            }
        }
        memset(kl, 0, 9 * w.n * w.n * sizeof *kl);
        point_terms(q, &w, method, factor, l, kl, t, rhs);
        if (tf_sparsity_add_dense(k, w.idx, w.n, kl) != 0) {
            tf_fail(ctx,
                    "boundary point (%g, %g, %g) mm: a node pair of its support is not in "
                    "the stiffness pattern",
                    q->x[0], q->x[1], q->x[2]);
            rc = -1;
        }
    }
    free(kl);
    free(t);
    tf_shape_work_free(&w);
    return rc;
}
