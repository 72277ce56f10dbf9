/*
 * quadrature.c — Gauss-Legendre rules, background cells, patch points
 * (quadrature.h).
 */
#include "meshfree/quadrature.h"

#include "meshfree/tet_cells.h"

#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Golub-Welsch: the nodes are the eigenvalues of the Jacobi matrix of the
 * Legendre recurrence (off-diagonal k / sqrt(4k^2 - 1)), the weights twice
 * the squared first components of its unit eigenvectors.  LAPACK's dstev
 * does the work; the rule is then symmetrised so that mirrored problems
 * see mirrored points. */
int tf_gauss_legendre(unsigned n, double *x, double *w)
{
    if (n < 1 || n > TF_GAUSS_MAX) {
        return -1;
    }
    double e[TF_GAUSS_MAX], z[TF_GAUSS_MAX * TF_GAUSS_MAX];
    for (unsigned k = 0; k < n; ++k) {
        x[k] = 0;
        e[k] = (k + 1.0) / sqrt(4.0 * (k + 1.0) * (k + 1.0) - 1.0);
    }
    if (LAPACKE_dstev(LAPACK_COL_MAJOR, 'V', (lapack_int)n, x, e, z, (lapack_int)n) != 0) {
        return -1;
    }
    for (unsigned k = 0; k < n; ++k) {
        w[k] = 2 * z[k * n] * z[k * n];
    }
    for (unsigned k = 0; k < n / 2; ++k) {
        unsigned m = n - 1 - k;
        double xs = 0.5 * (x[m] - x[k]), ws = 0.5 * (w[k] + w[m]);
        x[k] = -xs;
        x[m] = xs;
        w[k] = w[m] = ws;
    }
    if (n % 2) {
        x[n / 2] = 0;
    }
    return 0;
}

int tf_cells_init(tf_cells *c, const double lo[3], const double hi[3], const unsigned n[3],
                  unsigned gauss)
{
    for (int a = 0; a < 3; ++a) {
        c->lo[a] = lo[a];
        c->n[a] = n[a];
        c->size[a] = (hi[a] - lo[a]) / n[a];
        c->edge[a] = NULL;
    }
    c->gauss = gauss;
    c->tet_xyz = NULL;
    c->tet = NULL;
    c->ntet = 0;
    c->loc.start = c->loc.items = NULL;
    return tf_gauss_legendre(gauss, c->gx, c->gw);
}

int tf_cells_init_cloud(tf_cells *c, const tf_cloud *cloud, const unsigned n[3], unsigned gauss)
{
    int rc = tf_cells_init(c, cloud->lo, cloud->hi, n, gauss);
    if (rc != 0 || !cloud->graded) {
        return rc;
    }
    for (int a = 0; a < 3; ++a) {
        c->edge[a] = malloc((n[a] + 1) * sizeof *c->edge[a]);
        if (c->edge[a] == NULL) {
            tf_cells_free(c);
            return -1;
        }
        double per = (double)(cloud->grid[a] - 1) / n[a]; /* grid intervals per cell */
        for (unsigned k = 0; k <= n[a]; ++k) {
            c->edge[a][k] = k == n[a] ? cloud->hi[a] : tf_cloud_from_index(cloud, a, k * per);
        }
    }
    return 0;
}

void tf_cells_free(tf_cells *c)
{
    for (int a = 0; a < 3; ++a) {
        free(c->edge[a]);
        c->edge[a] = NULL;
    }
    tf_cells_tet_free(c);
}

unsigned tf_cells_slab(const tf_cells *c, int a, double x)
{
    if (c->edge[a] == NULL) {
        double t = floor((x - c->lo[a]) / c->size[a]);
        return t < 0 ? 0 : t >= c->n[a] ? c->n[a] - 1 : (unsigned)t;
    }
    return tf_cloud_lines_interval(c->edge[a], c->n[a] + 1, x);
}

double tf_cells_min_size(const tf_cells *c, int a)
{
    if (c->edge[a] == NULL) {
        return c->size[a];
    }
    double m = INFINITY;
    for (unsigned k = 0; k < c->n[a]; ++k) {
        m = fmin(m, c->edge[a][k + 1] - c->edge[a][k]);
    }
    return m;
}

/* Centre and size of cell slab i along axis a. */
static void slab(const tf_cells *c, int a, size_t i, double *centre, double *size)
{
    if (c->edge[a] == NULL) {
        *centre = c->lo[a] + ((double)i + 0.5) * c->size[a];
        *size = c->size[a];
    } else {
        *centre = 0.5 * (c->edge[a][i] + c->edge[a][i + 1]);
        *size = c->edge[a][i + 1] - c->edge[a][i];
    }
}

static void cell_ijk(const tf_cells *c, size_t cell, size_t ijk[3])
{
    ijk[0] = cell % c->n[0];
    ijk[1] = cell / c->n[0] % c->n[1];
    ijk[2] = cell / ((size_t)c->n[0] * c->n[1]);
}

void tf_cells_box(const tf_cells *c, size_t cell, double centre[3], double half[3])
{
    if (c->tet) {
        tf_cells_tet_box(c, cell, centre, half);
        return;
    }
    size_t ijk[3];
    cell_ijk(c, cell, ijk);
    for (int a = 0; a < 3; ++a) {
        double size;
        slab(c, a, ijk[a], &centre[a], &size);
        half[a] = 0.5 * size;
    }
}

void tf_cells_point(const tf_cells *c, size_t cell, size_t p, double x[3], double *w)
{
    if (c->tet) {
        tf_cells_tet_point(c, cell, p, x, w);
        return;
    }
    size_t ijk[3];
    cell_ijk(c, cell, ijk);
    size_t g = c->gauss, gi[3] = {p % g, p / g % g, p / (g * g)};
    double weight = 1;
    for (int a = 0; a < 3; ++a) {
        double centre, size;
        slab(c, a, ijk[a], &centre, &size);
        x[a] = centre + 0.5 * size * c->gx[gi[a]];
        weight *= 0.5 * size * c->gw[gi[a]];
    }
    *w = weight;
}

void tf_cells_describe(const tf_cells *c, char *buf, size_t len)
{
    if (c->tet) {
        snprintf(buf, len, "%zu tetrahedra x %u Gauss points (degree %u)", c->ntet, c->rule.n,
                 c->rule.degree);
    } else {
        snprintf(buf, len, "%zu cells x %u^3 Gauss points", tf_cells_count(c), c->gauss);
    }
}

double tf_patch_area(const tf_patch *p, const tf_cloud *cloud)
{
    int u, v;
    switch (p->shape) {
    case TF_PATCH_FACE:
        tf_face_axes(p->face, &u, &v);
        return (cloud->hi[u] - cloud->lo[u]) * (cloud->hi[v] - cloud->lo[v]);
    case TF_PATCH_RECT:
        return p->size[0] * p->size[1];
    case TF_PATCH_CIRCLE:
        return M_PI * p->radius * p->radius;
    case TF_PATCH_SURFACE:
    case TF_PATCH_POINTS:
        return p->area;
    default:
        return 0;
    }
}

/* Sub-cells along a length: about two per background cell, at least one. */
static unsigned subdivisions(double length, double cell)
{
    double m = ceil(2 * length / cell - 1e-9);
    return m < 1 ? 1 : (unsigned)m;
}

/* gauss^2 points on each of mu x mv sub-rectangles of [u0,u1] x [v0,v1]. */
static size_t rect_points(tf_qpoint *q, const tf_cells *cells, int u, int v, double plane_coord,
                          int axis, const double u01[2], const double v01[2], unsigned mu,
                          unsigned mv)
{
    size_t k = 0;
    unsigned g = cells->gauss;
    double du = (u01[1] - u01[0]) / mu, dv = (v01[1] - v01[0]) / mv;
    for (unsigned jv = 0; jv < mv; ++jv) {
        for (unsigned ju = 0; ju < mu; ++ju) {
            for (unsigned b = 0; b < g; ++b) {
                for (unsigned a = 0; a < g; ++a) {
                    q[k].x[axis] = plane_coord;
                    q[k].x[u] = u01[0] + (ju + 0.5) * du + 0.5 * du * cells->gx[a];
                    q[k].x[v] = v01[0] + (jv + 0.5) * dv + 0.5 * dv * cells->gx[b];
                    q[k].w = 0.25 * du * dv * cells->gw[a] * cells->gw[b];
                    k++;
                }
            }
        }
    }
    return k;
}

/* Polar rule on a disc: Gauss in r (weight r dr) on rings, Gauss in theta
 * on sectors. */
static size_t disc_points(tf_qpoint *q, const tf_cells *cells, int u, int v, double plane_coord,
                          int axis, const double c[2], double radius, unsigned mr, unsigned mt)
{
    size_t k = 0;
    unsigned g = cells->gauss;
    double dr = radius / mr, dt = 2 * M_PI / mt;
    for (unsigned it = 0; it < mt; ++it) {
        for (unsigned ir = 0; ir < mr; ++ir) {
            for (unsigned b = 0; b < g; ++b) {
                for (unsigned a = 0; a < g; ++a) {
                    double r = (ir + 0.5) * dr + 0.5 * dr * cells->gx[a];
                    double t = (it + 0.5) * dt + 0.5 * dt * cells->gx[b];
                    q[k].x[axis] = plane_coord;
                    q[k].x[u] = c[0] + r * cos(t);
                    q[k].x[v] = c[1] + r * sin(t);
                    q[k].w = 0.25 * dr * dt * cells->gw[a] * cells->gw[b] * r;
                    k++;
                }
            }
        }
    }
    return k;
}

tf_qpoint *tf_patch_points(const tf_patch *p, const tf_cloud *cloud, const tf_cells *cells,
                           size_t *n)
{
    int u, v, axis = tf_face_axis(p->face);
    tf_face_axes(p->face, &u, &v);
    double plane = tf_cloud_face_coord(cloud, p->face);
    double cu = tf_cells_min_size(cells, u), cv = tf_cells_min_size(cells, v);
    unsigned g2 = cells->gauss * cells->gauss, mu, mv;
    double u01[2], v01[2];
    if (p->shape == TF_PATCH_CIRCLE) {
        mu = subdivisions(p->radius, fmin(cu, cv));
        mv = 4 * mu < 8 ? 8 : 4 * mu;
    } else if (p->shape == TF_PATCH_FACE) {
        u01[0] = cloud->lo[u];
        u01[1] = cloud->hi[u];
        v01[0] = cloud->lo[v];
        v01[1] = cloud->hi[v];
    } else {
        u01[0] = p->centre[0] - 0.5 * p->size[0];
        u01[1] = p->centre[0] + 0.5 * p->size[0];
        v01[0] = p->centre[1] - 0.5 * p->size[1];
        v01[1] = p->centre[1] + 0.5 * p->size[1];
    }
    if (p->shape != TF_PATCH_CIRCLE) {
        mu = subdivisions(u01[1] - u01[0], cu);
        mv = subdivisions(v01[1] - v01[0], cv);
    }
    tf_qpoint *q = malloc((size_t)mu * mv * g2 * sizeof *q);
    if (q == NULL) {
        return NULL;
    }
    *n = p->shape == TF_PATCH_CIRCLE
             ? disc_points(q, cells, u, v, plane, axis, p->centre, p->radius, mu, mv)
             : rect_points(q, cells, u, v, plane, axis, u01, v01, mu, mv);
    return q;
}
