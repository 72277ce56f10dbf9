/*
 * cell_gradients.c — shape-function gradients over a cell's node set, with
 * the VCI correction (cell_gradients.h).
 */
#include "solvers/cell_gradients.h"

#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Sub-rectangles per cell face and axis: the load patches' rule. */
#define FACE_SPLIT 2

static size_t face_point_count(const tf_cells *c)
{
    return 6 * FACE_SPLIT * FACE_SPLIT * (size_t)c->gauss * c->gauss;
}

int tf_grad_work_init(tf_grad_work *w, const tf_shape *sh, size_t n_nodes)
{
    size_t np = tf_cells_points(&sh->cells), nf = face_point_count(&sh->cells);
    memset(w, 0, sizeof *w);
    tf_shape_work_init(&w->sw);
    tf_shape_work_init(&w->fw);
    w->map = malloc((n_nodes + 1) * sizeof *w->map);
    w->x = malloc(3 * np * sizeof *w->x);
    w->w = malloc(np * sizeof *w->w);
    w->fx = malloc(3 * nf * sizeof *w->fx);
    w->fwt = malloc(nf * sizeof *w->fwt);
    w->fn = malloc(3 * nf * sizeof *w->fn);
    w->fnb = malloc(nf * sizeof *w->fnb);
    if (!w->map || !w->x || !w->w || !w->fx || !w->fwt || !w->fn || !w->fnb) {
        tf_grad_work_free(w);
        return -1;
    }
    for (size_t i = 0; i < n_nodes; ++i) {
        w->map[i] = -1;
    }
    return 0;
}

void tf_grad_work_free(tf_grad_work *w)
{
    tf_shape_work_free(&w->sw);
    tf_shape_work_free(&w->fw);
    free(w->map);
    free(w->x);
    free(w->w);
    free(w->fx);
    free(w->fwt);
    free(w->fn);
    free(w->fnb);
    memset(w, 0, sizeof *w);
}

/* The face points of a cell, face by face (x-, x+, y-, y+, z-, z+), each
 * face's points contiguous: w->nf of them.  A point on a cut (a cut along
 * the cells' faces) is moved into the cell by ON_CUT_NUDGE of the cell's
 * half-width, so that its shape functions are this cell's side's (on the
 * panel itself the + side's), and has no neighbour: the cut is a boundary
 * of both cells, each integrating its own side's trace. */
#define ON_CUT_TOL 1e-12   /* of the cell's half-width: a point on the panel */
#define ON_CUT_NUDGE 1e-10 /* of the cell's half-width: clear of ON_CUT_TOL and of rounding */

static void face_points(const tf_shape *sh, size_t cell, tf_grad_work *w)
{
    const tf_cells *c = &sh->cells;
    double centre[3], half[3];
    size_t ijk[3] = {cell % c->n[0], cell / c->n[0] % c->n[1], cell / c->n[0] / c->n[1]};
    size_t stride[3] = {1, c->n[0], (size_t)c->n[0] * c->n[1]};
    tf_cells_box(c, cell, centre, half);
    size_t k = 0;
    unsigned g = c->gauss;
    for (int f = 0; f < 6; ++f) {
        int axis = f / 2, u, v, hi = f % 2;
        tf_face_axes((tf_face)f, &u, &v);
        size_t nb = hi ? (ijk[axis] + 1 < c->n[axis] ? cell + stride[axis] : SIZE_MAX)
                       : (ijk[axis] > 0 ? cell - stride[axis] : SIZE_MAX);
        double du = 2 * half[u] / FACE_SPLIT, dv = 2 * half[v] / FACE_SPLIT;
        double u0 = centre[u] - half[u], v0 = centre[v] - half[v];
        for (unsigned jv = 0; jv < FACE_SPLIT; ++jv) {
            for (unsigned ju = 0; ju < FACE_SPLIT; ++ju) {
                for (unsigned b = 0; b < g; ++b) {
                    for (unsigned a = 0; a < g; ++a) {
                        double *x = w->fx + 3 * k, *n = w->fn + 3 * k;
                        x[axis] = centre[axis] + (hi ? half[axis] : -half[axis]);
                        x[u] = u0 + (ju + 0.5) * du + 0.5 * du * c->gx[a];
                        x[v] = v0 + (jv + 0.5) * dv + 0.5 * dv * c->gx[b];
                        n[0] = n[1] = n[2] = 0;
                        n[axis] = hi ? 1 : -1;
                        w->fwt[k] = 0.25 * du * dv * c->gw[a] * c->gw[b];
                        w->fnb[k] = nb;
                        if (sh->cuts.n > 0 &&
                            tf_cut_on_panel(&sh->cuts, x, ON_CUT_TOL * half[axis])) {
                            x[axis] -= n[axis] * ON_CUT_NUDGE * half[axis];
                            w->fnb[k] = SIZE_MAX;
                        }
                        k++;
                    }
                }
            }
        }
    }
    w->nf = k;
}

/* The neighbour across face f (SIZE_MAX on the box, or where a cut covers
 * the whole face). */
static size_t face_neighbour(const tf_grad_work *w, size_t f)
{
    size_t per_face = w->nf / 6;
    for (size_t p = f * per_face; p < (f + 1) * per_face; ++p) {
        if (w->fnb[p] != SIZE_MAX) {
            return w->fnb[p];
        }
    }
    return SIZE_MAX;
}

/* RPIM with cell-centred supports: phi jumps between cells, and a shared
 * face takes the mean of both cells' functions. */
static int averages_faces(const tf_shape *sh)
{
    return sh->centre == TF_SUPPORT_CELL && sh->mls_radius == NULL;
}

static void add_support(const tf_shape_work *s, uint32_t *mark, uint32_t stamp, uint32_t *list,
                        size_t *len)
{
    for (size_t k = 0; k < s->n; ++k) {
        uint32_t a = s->idx[k];
        if (mark[a] != stamp) {
            mark[a] = stamp;
            list[(*len)++] = a;
        }
    }
}

int tf_vci_cell_nodes(const tf_shape *sh, tf_grad_work *w, size_t cell, uint32_t *mark,
                      uint32_t stamp, uint32_t *list, size_t *len)
{
    face_points(sh, cell, w);
    size_t per_face = w->nf / 6;
    for (size_t k = 0; k < w->nf; ++k) {
        const double *x = w->fx + 3 * k;
        size_t nb = k % per_face == 0 ? face_neighbour(w, k / per_face) : SIZE_MAX;
        if (sh->centre == TF_SUPPORT_POINT) {
            if (tf_shape_support(sh, &w->fw, x, cell) != 0) {
                snprintf(w->sw.err, sizeof w->sw.err, "%s", w->fw.err);
                return -1;
            }
            add_support(&w->fw, mark, stamp, list, len);
        } else if (averages_faces(sh) && nb != SIZE_MAX) {
            if (tf_shape_support(sh, &w->fw, x, nb) != 0) {
                snprintf(w->sw.err, sizeof w->sw.err, "%s", w->fw.err);
                return -1;
            }
            add_support(&w->fw, mark, stamp, list, len);
        }
    }
    return 0;
}

/* Adds scale * phi_i * n * wt of points first .. first + np of the face
 * list to b (3 m, b[a m + i]), scale = alone at a point with no neighbour
 * (the box, a cut), shared at the others; their shape functions are rows
 * row0 .. row0 + np of the evaluation s. */
static void add_face_values(const tf_grad_work *w, const tf_shape_work *s, size_t first,
                            size_t row0, size_t np, double alone, double shared, size_t m,
                            double *b)
{
    for (size_t p = 0; p < np; ++p) {
        const double *n = w->fn + 3 * (first + p);
        double wt = (w->fnb[first + p] == SIZE_MAX ? alone : shared) * w->fwt[first + p];
        if (wt == 0) {
            continue;
        }
        for (size_t k = 0; k < s->n; ++k) {
            size_t i = (size_t)w->map[s->idx[k]];
            double v = wt * s->phi[(row0 + p) * s->n + k];
            b[i] += v * n[0];
            b[m + i] += v * n[1];
            b[2 * m + i] += v * n[2];
        }
    }
}

/* b_i = int over the cell's faces of phi^_i n (3 m, b[a m + i]). */
static int face_integrals(const tf_shape *sh, tf_grad_work *w, size_t cell, size_t m, double *b)
{
    memset(b, 0, 3 * m * sizeof *b);
    face_points(sh, cell, w);
    size_t per_face = w->nf / 6;
    if (sh->centre == TF_SUPPORT_POINT) {
        for (size_t k = 0; k < w->nf; ++k) {
            if (tf_shape_at(sh, &w->fw, w->fx + 3 * k, cell, 0) != 0) {
                return -1;
            }
            add_face_values(w, &w->fw, k, 0, 1, 1.0, 1.0, m, b);
        }
        return 0;
    }
    if (tf_shape_cell_points(sh, &w->fw, cell, w->fx, w->nf, 0) != 0) {
        return -1;
    }
    if (!averages_faces(sh)) {
        add_face_values(w, &w->fw, 0, 0, w->nf, 1.0, 1.0, m, b);
        return 0;
    }
    for (size_t f = 0; f < 6; ++f) {
        size_t first = f * per_face;
        add_face_values(w, &w->fw, first, first, per_face, 1.0, 0.5, m, b);
    }
    for (size_t f = 0; f < 6; ++f) {
        size_t first = f * per_face, nb = face_neighbour(w, f);
        if (nb == SIZE_MAX) {
            continue;
        }
        if (tf_shape_cell_points(sh, &w->fw, nb, w->fx + 3 * first, per_face, 0) != 0) {
            return -1;
        }
        add_face_values(w, &w->fw, first, 0, per_face, 0.0, 0.5, m, b);
    }
    return 0;
}

/* Uncorrected gradients at the Gauss points, scattered into set order. */
static int gauss_gradients(const tf_shape *sh, tf_grad_work *w, size_t cell, size_t m, double *g)
{
    size_t np = tf_cells_points(&sh->cells);
    for (size_t p = 0; p < np; ++p) {
        tf_cells_point(&sh->cells, cell, p, w->x + 3 * p, w->w + p);
    }
    memset(g, 0, 3 * np * m * sizeof *g);
    if (sh->centre == TF_SUPPORT_CELL) {
        if (tf_shape_cell_points(sh, &w->sw, cell, w->x, np, 1) != 0) {
            return -1;
        }
        size_t n = w->sw.n;
        for (size_t q = 0; q < 3 * np; ++q) {
            for (size_t k = 0; k < n; ++k) {
                g[q * m + (size_t)w->map[w->sw.idx[k]]] = w->sw.dphi[q * n + k];
            }
        }
        return 0;
    }
    for (size_t p = 0; p < np; ++p) {
        if (tf_shape_at(sh, &w->sw, w->x + 3 * p, cell, 1) != 0) {
            return -1;
        }
        size_t n = w->sw.n;
        for (size_t a = 0; a < 3; ++a) {
            for (size_t k = 0; k < n; ++k) {
                g[(3 * p + a) * m + (size_t)w->map[w->sw.idx[k]]] = w->sw.dphi[a * n + k];
            }
        }
    }
    return 0;
}

int tf_cell_gradients(const tf_shape *sh, int vci, tf_grad_work *w, size_t cell,
                      const uint32_t *set, size_t m, double *g)
{
    size_t np = tf_cells_points(&sh->cells);
    double t0 = omp_get_wtime(), *b = NULL;
    for (size_t r = 0; r < m; ++r) {
        w->map[set[r]] = (int)r;
    }
    int rc = gauss_gradients(sh, w, cell, m, g);
    if (rc == 0 && vci) {
        b = malloc(3 * m * sizeof *b);
        rc = b == NULL ? -1 : face_integrals(sh, w, cell, m, b);
        if (rc != 0 && b == NULL) {
            snprintf(w->sw.err, sizeof w->sw.err, "out of memory");
        } else if (rc != 0) {
            snprintf(w->sw.err, sizeof w->sw.err, "%s", w->fw.err);
        }
    }
    if (rc == 0 && vci) {
        double vol = 0;
        for (size_t p = 0; p < np; ++p) {
            vol += w->w[p];
        }
        for (size_t a = 0; a < 3; ++a) {
            for (size_t i = 0; i < m; ++i) {
                double sum = 0;
                for (size_t p = 0; p < np; ++p) {
                    sum += w->w[p] * g[(3 * p + a) * m + i];
                }
                double xi = (b[a * m + i] - sum) / vol;
                for (size_t p = 0; p < np; ++p) {
                    g[(3 * p + a) * m + i] += xi;
                }
            }
        }
    }
    free(b);
    for (size_t r = 0; r < m; ++r) {
        w->map[set[r]] = -1;
    }
    w->t_shape += omp_get_wtime() - t0;
    return rc;
}
