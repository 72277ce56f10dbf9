/*
 * colloc_loads.c — nodal forces of surface loads for the collocation solver
 * (colloc_solver.h): with nodal integration a traction acts on the
 * particles of the loaded face through their tributary areas, the face
 * divided between its particles as the grid divides it (a particle's
 * rectangle reaches half a spacing each way, clipped to the face).  Each
 * rectangle is sampled at SUB x SUB midpoints; a sample inside the patch
 * carries the traction there times its area.  A uniform load is scaled so
 * that the samples' forces add up to the total force exactly (a disc's
 * sampled area is not exactly pi r^2).  A point force goes to its node.
 */
#include "solvers/collocation/colloc_solver.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "problem/analytic.h"

#define SUB 8

/* 1 when the in-face point (u, v) is inside the patch. */
static int in_patch(const tf_patch *p, double u, double v)
{
    switch (p->shape) {
    case TF_PATCH_FACE:
        return 1;
    case TF_PATCH_RECT:
        return fabs(u - p->centre[0]) <= p->size[0] / 2 && fabs(v - p->centre[1]) <= p->size[1] / 2;
    case TF_PATCH_CIRCLE:
        return (u - p->centre[0]) * (u - p->centre[0]) + (v - p->centre[1]) * (v - p->centre[1]) <=
               p->radius * p->radius;
    case TF_PATCH_POINT:
    case TF_PATCH_AT:
    case TF_PATCH_SURFACE: /* an organ's patch: create() admits boxes only */
    case TF_PATCH_POINTS:
        return 0;
    }
    return 0;
}

/* Calls add(node, x, weight) for every sample of the patch's face inside
 * the patch; returns the total weight (mm^2). */
typedef void (*sample_fn)(void *user, size_t node, const double x[3], double w);

static double sample_patch(const tf_problem *pr, const tf_patch *p, sample_fn add, void *user)
{
    const tf_cloud *c = &pr->cloud;
    int a = tf_face_axis(p->face), u, v;
    tf_face_axes(p->face, &u, &v);
    double plane = tf_cloud_face_coord(c, p->face), tol = tf_cloud_tol(c), total = 0;
    for (size_t i = 0; i < c->n; ++i) {
        const double *xi = c->xyz + 3 * i;
        if (fabs(xi[a] - plane) > tol) {
            continue;
        }
        double lo[2], hi[2];
        int ax[2] = {u, v};
        for (int q = 0; q < 2; ++q) {
            double h = c->spacing[ax[q]] / 2;
            lo[q] = fmax(xi[ax[q]] - h, c->lo[ax[q]]);
            hi[q] = fmin(xi[ax[q]] + h, c->hi[ax[q]]);
        }
        double du = (hi[0] - lo[0]) / SUB, dv = (hi[1] - lo[1]) / SUB;
        for (int s = 0; s < SUB; ++s) {
            for (int t = 0; t < SUB; ++t) {
                double x[3];
                x[a] = plane;
                x[u] = lo[0] + (s + 0.5) * du;
                x[v] = lo[1] + (t + 0.5) * dv;
                if (in_patch(p, x[u], x[v])) {
                    add(user, i, x, du * dv);
                    total += du * dv;
                }
            }
        }
    }
    return total;
}

typedef struct uniform {
    double *f;
} uniform;

/* Area weights into column 0 (one per node, summed; spread later). */
static void add_area(void *user, size_t node, const double x[3], double w)
{
    (void)x;
    uniform *s = user;
    s->f[node] += w;
}

typedef struct exact {
    const tf_problem *pr;
    tf_face face;
    double *f;
} exact;

static void add_traction(void *user, size_t node, const double x[3], double w)
{
    exact *s = user;
    double t[3];
    tf_analytic_traction(s->pr, s->face, x, t);
    for (int a = 0; a < 3; ++a) {
        s->f[3 * node + (size_t)a] += w * t[a];
    }
}

int tf_colloc_patch_forces(tf_ctx *ctx, const tf_problem *pr, const tf_patch *p,
                           const double *force, double *f)
{
    size_t n = pr->cloud.n, n3 = 3 * n;
    if (p->shape == TF_PATCH_AT) {
        /* A point force between particles would need the MLS shape
         * functions at that point; not provided (no field either). */
        return tf_fail(ctx, "mls-collocation: a force at a point between particles is not "
                            "supported; give a node or a face patch");
    }
    if (p->shape == TF_PATCH_POINTS) {
        return tf_fail(ctx, "mls-collocation: a contact region's probe (a patch given by "
                            "quadrature points) is not supported; give a face patch");
    }
    if (p->shape == TF_PATCH_POINT) {
        for (int a = 0; a < 3; ++a) {
            if (force) {
                f[3 * (size_t)p->node + (size_t)a] += force[a];
            } else {
                f[(size_t)a * n3 + 3 * (size_t)p->node + (size_t)a] += 1;
            }
        }
        return 0;
    }
    double *area = calloc(n + 1, sizeof *area);
    if (area == NULL) {
        return tf_fail(ctx, "out of memory for a patch load");
    }
    uniform s = {.f = area};
    double total = sample_patch(pr, p, add_area, &s);
    if (!(total > 0)) {
        free(area);
        return tf_fail(ctx, "a load patch covers no particle's share of its face");
    }
    for (size_t i = 0; i < n; ++i) {
        for (int a = 0; area[i] > 0 && a < 3; ++a) {
            if (force) {
                f[3 * i + (size_t)a] += force[a] * area[i] / total;
            } else {
                f[(size_t)a * n3 + 3 * i + (size_t)a] += area[i] / total;
            }
        }
    }
    free(area);
    return 0;
}

int tf_colloc_exact_forces(tf_ctx *ctx, const tf_problem *pr, const tf_patch *p, double *f)
{
    if (p->shape == TF_PATCH_POINT || p->shape == TF_PATCH_AT) {
        return tf_fail(ctx, "an analytic traction needs a patch, not a point");
    }
    exact s = {.pr = pr, .face = p->face, .f = f};
    if (!(sample_patch(pr, p, add_traction, &s) > 0)) {
        return tf_fail(ctx, "a load patch covers no particle's share of its face");
    }
    return 0;
}
