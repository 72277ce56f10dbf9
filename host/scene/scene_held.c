/*
 * scene_held.c — the fixed regions against the rigid motions of the body
 * (scene_held.h).
 *
 * A rigid motion u(x) = t + w x r, r = (x - c) / L about the nodes' centre
 * c scaled by their extent L, is stopped by the prescribed components when
 * the rows they give (component a of node x: its coefficients in
 * (t, w)) have rank 6: the 6 x 6 sum of their outer products is then
 * positive definite, which LAPACK's Cholesky factorisation with complete
 * pivoting (dpstrf) tells with a relative tolerance.
 */
#include "scene/scene_held.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <lapacke.h>

/* The row of component a at the scaled position r (u_a = t_a + (w x r)_a). */
static void row(int a, const double r[3], double q[6])
{
    memset(q, 0, 6 * sizeof *q);
    q[a] = 1;
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    q[3 + b] = r[c];  /* (w x r)_a = w_b r_c - w_c r_b */
    q[3 + c] = -r[b];
}

/* Rank of the symmetric positive semi-definite m (6 x 6, destroyed):
 * LAPACK's Cholesky with complete pivoting (dpstrf), pivots under tol
 * times the largest diagonal taken as zero. */
static int rank6(double m[6][6], double tol)
{
    double top = 0;
    for (int i = 0; i < 6; ++i) {
        top = fmax(top, m[i][i]);
    }
    if (!(top > 0)) {
        return 0;
    }
    lapack_int piv[6], rank = 0;
    if (LAPACKE_dpstrf(LAPACK_ROW_MAJOR, 'U', 6, &m[0][0], 6, piv, &rank, tol * top) < 0) {
        return 0;
    }
    return (int)rank;
}

/* The centre and extent of the nodes. */
static void frame(const tf_cloud *c, double centre[3], double *extent)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < c->n; ++i) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = fmin(lo[a], c->xyz[3 * i + (size_t)a]);
            hi[a] = fmax(hi[a], c->xyz[3 * i + (size_t)a]);
        }
    }
    *extent = 0;
    for (int a = 0; a < 3; ++a) {
        centre[a] = 0.5 * (lo[a] + hi[a]);
        *extent = fmax(*extent, hi[a] - lo[a]);
    }
    *extent = *extent > 0 ? *extent : 1;
}

static const char *what_is_free(const tf_problem *s)
{
    unsigned held = 0;
    for (size_t k = 0; k < s->n_fixed; ++k) {
        held |= s->fixed[k].components;
    }
    return held == TF_COMP_ALL ? "free to turn (a rigid rotation nothing stops)"
                               : "free to slide (a component no fixed region holds)";
}

/* Every component of every node prescribed, by several regions together. */
static int all_fixed(const tf_problem *s, sd_issue *is)
{
    unsigned char *fixed = malloc(3 * s->cloud.n + 1);
    if (fixed == NULL) {
        return sd_fail(is, "fixed", "out of memory");
    }
    tf_problem_fixed_dofs(s, fixed);
    size_t n = 0;
    for (size_t d = 0; d < 3 * s->cloud.n; ++d) {
        n += fixed[d] != 0;
    }
    free(fixed);
    if (n == 3 * s->cloud.n) {
        return sd_fail(is, "fixed",
                       "the fixed regions together hold every component of every node (%zu "
                       "nodes): nothing is left to move",
                       s->cloud.n);
    }
    return 0;
}

int sd_check_held(const tf_problem *s, sd_issue *is)
{
    char p[64];
    double m[6][6] = {{0}}, c[3], L;
    frame(&s->cloud, c, &L);
    for (size_t k = 0; k < s->n_fixed; ++k) {
        const tf_fixed *f = &s->fixed[k];
        if (f->components == TF_COMP_ALL && f->n_nodes == s->cloud.n) {
            snprintf(p, sizeof p, "fixed.%zu", k);
            return sd_fail(is, p,
                           "this region holds every node of the body (%zu): nothing is left "
                           "to move",
                           f->n_nodes);
        }
        for (size_t i = 0; i < f->n_nodes; ++i) {
            const double *x = s->cloud.xyz + 3 * (size_t)f->nodes[i];
            const double r[3] = {(x[0] - c[0]) / L, (x[1] - c[1]) / L, (x[2] - c[2]) / L};
            for (int a = 0; a < 3; ++a) {
                if (!(f->components & (1u << a))) {
                    continue;
                }
                double q[6];
                row(a, r, q);
                for (int u = 0; u < 6; ++u) {
                    for (int v = 0; v < 6; ++v) {
                        m[u][v] += q[u] * q[v];
                    }
                }
            }
        }
    }
    if (all_fixed(s, is) != 0) {
        return -1;
    }
    if (s->n_fixed == 0 || rank6(m, 1e-12) == 6) {
        return 0;
    }
    const size_t k = s->n_fixed - 1;
    const tf_fixed *f = &s->fixed[k];
    const double *x = s->cloud.xyz + 3 * (size_t)f->nodes[0];
    snprintf(p, sizeof p, "fixed.%zu", k);
    return sd_fail(is, p,
                   "this region holds %zu node%s (the first at (%g, %g, %g) mm), and the fixed "
                   "regions together leave the body %s: its stiffness is singular; hold a face, "
                   "or three nodes not on one line",
                   f->n_nodes, f->n_nodes == 1 ? "" : "s", x[0], x[1], x[2], what_is_free(s));
}
