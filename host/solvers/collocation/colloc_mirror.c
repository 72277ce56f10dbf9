/*
 * colloc_mirror.c — planes of symmetry through mirror images (colloc.h).
 *
 * Modelling a quarter of a symmetric body is only as good as the supports
 * at the cut: a particle on the plane with neighbours on one side only
 * fits its gradient one-sidedly (first-order error, right at the
 * indenter's axis in the Hertz test).  With the images of the particles
 * near the plane as extra neighbours, every support is what it would be in
 * the whole body, and the reduced problem is the whole one exactly: the
 * energy of the modelled part with u_image = S u_particle (S the
 * reflection) has the gradient f_j + sum_images S f_image.  Images carry no
 * stress of their own (they are not integration points).
 */
#include "solvers/collocation/colloc_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Distance from particle i to plane p (>= 0 on the body's side). */
static double depth(const tf_colloc *c, size_t i, size_t p)
{
    return fabs(c->X[3 * i + (size_t)c->mirror[p].axis] - c->mirror[p].at);
}

static int check_planes(tf_ctx *ctx, const tf_colloc *c, double tol)
{
    for (size_t p = 0; p < c->n_mirrors; ++p) {
        int a = c->mirror[p].axis, below = 0, above = 0;
        for (size_t q = 0; q < p; ++q) {
            if (c->mirror[q].axis == a) {
                return tf_fail(ctx, "mirror planes %zu and %zu are both normal to %c", q, p,
                               'x' + a);
            }
        }
        for (size_t i = 0; i < c->n; ++i) {
            double t = c->X[3 * i + (size_t)a] - c->mirror[p].at;
            below |= t < -tol;
            above |= t > tol;
        }
        if (below && above) {
            return tf_fail(ctx, "mirror plane %c = %g: particles lie on both sides of it", 'x' + a,
                           c->mirror[p].at);
        }
    }
    return 0;
}

int tf_colloc_make_ghosts(tf_ctx *ctx, tf_colloc *c, const double *reach)
{
    size_t n = c->n, np = c->n_mirrors, subsets = (size_t)1 << np;
    double lo = INFINITY, hi = -INFINITY, D[3] = {0, 0, 0};
    for (size_t q = 0; q < 3 * n; ++q) {
        lo = fmin(lo, c->X[q]);
        hi = fmax(hi, c->X[q]);
    }
    double tol = c->mtol = 1e-9 * (hi - lo);
    if (check_planes(ctx, c, tol) != 0) {
        return -1;
    }
    /* An image is someone's neighbour only if it is nearer than the reach. */
    for (size_t i = 0; i < n; ++i) {
        for (size_t p = 0; p < np; ++p) {
            D[p] = fmax(D[p], reach[i] - depth(c, i, p));
            if (depth(c, i, p) <= tol) {
                c->fixed[i] |= (unsigned char)(1u << c->mirror[p].axis);
            }
        }
    }
    size_t ng = 0;
    for (int pass = 0; pass < 2; ++pass) {
        ng = 0;
        for (size_t i = 0; i < n; ++i) {
            if (pass) {
                c->gstart[i] = (uint32_t)ng;
            }
            for (size_t m = 1; m < subsets; ++m) {
                int ok = 1;
                for (size_t p = 0; p < np && ok; ++p) {
                    double t = depth(c, i, p);
                    ok = !(m >> p & 1) || (t > tol && t <= D[p] * (1 + 1e-9));
                }
                if (!ok) {
                    continue;
                }
                if (pass) {
                    double *x = c->X + 3 * (n + ng), *s = c->gsign + 3 * ng;
                    for (int a = 0; a < 3; ++a) {
                        x[a] = c->X[3 * i + a];
                        s[a] = 1;
                    }
                    for (size_t p = 0; p < np; ++p) {
                        if (m >> p & 1) {
                            int a = c->mirror[p].axis;
                            x[a] = 2 * c->mirror[p].at - x[a];
                            s[a] = -1;
                        }
                    }
                    c->gsrc[ng] = (uint32_t)i;
                }
                ng++;
            }
        }
        if (pass) {
            c->gstart[n] = (uint32_t)ng;
            break;
        }
        double *X = realloc(c->X, 3 * (n + ng + 1) * sizeof *X);
        if (X) {
            c->X = X;
        }
        c->gsrc = malloc((ng + 1) * sizeof *c->gsrc);
        c->gsign = malloc(3 * (ng + 1) * sizeof *c->gsign);
        c->gstart = malloc((n + 1) * sizeof *c->gstart);
        if (!X || !c->gsrc || !c->gsign || !c->gstart) {
            return tf_fail(ctx, "out of memory for %zu mirror images", ng);
        }
    }
    c->na = n + ng;
    return 0;
}

void tf_colloc_ghost_fill(const tf_colloc *c, const double *u, double *ue)
{
    for (size_t q = 0; q < 3 * c->n; ++q) {
        ue[q] = u[q];
    }
    for (size_t g = 0; g < c->na - c->n; ++g) {
        const double *s = c->gsign + 3 * g, *src = u + 3 * (size_t)c->gsrc[g];
        double *dst = ue + 3 * (c->n + g);
        dst[0] = s[0] * src[0];
        dst[1] = s[1] * src[1];
        dst[2] = s[2] * src[2];
    }
}

void tf_colloc_ghost_fold(const tf_colloc *c, const double *fe, double *f)
{
#pragma omp parallel for schedule(static) num_threads(tf_colloc_threads(c))
    for (size_t i = 0; i < c->n; ++i) {
        double f0 = fe[3 * i], f1 = fe[3 * i + 1], f2 = fe[3 * i + 2];
        for (uint32_t g = c->gstart[i]; g < c->gstart[i + 1]; ++g) {
            const double *s = c->gsign + 3 * (size_t)g, *fg = fe + 3 * (c->n + g);
            f0 += s[0] * fg[0];
            f1 += s[1] * fg[1];
            f2 += s[2] * fg[2];
        }
        f[3 * i] = f0;
        f[3 * i + 1] = f1;
        f[3 * i + 2] = f2;
    }
}

double tf_colloc_mirror_share(const tf_colloc *c, size_t i)
{
    double share = 1;
    for (size_t p = 0; p < c->n_mirrors; ++p) {
        if (depth(c, i, p) <= c->mtol) {
            share /= 2;
        }
    }
    return share;
}

int tf_colloc_drop_ghosts(tf_colloc *c, uint32_t *lists, const size_t *cnt, size_t cap)
{
    size_t n = c->n, ng = c->na - n;
    uint32_t *map = calloc(ng + 1, sizeof *map);
    if (map == NULL) {
        return -1;
    }
    for (size_t i = 0; i < n; ++i) {
        for (size_t q = 0; q < cnt[i]; ++q) {
            if (lists[i * cap + q] >= n) {
                map[lists[i * cap + q] - n] = 1;
            }
        }
    }
    size_t kept = 0, g = 0;
    for (size_t i = 0; i < n; ++i) { /* keeps the order: images of i stay together */
        uint32_t first = (uint32_t)kept;
        for (; g < c->gstart[i + 1]; ++g) {
            if (map[g]) {
                map[g] = (uint32_t)kept;
                for (int a = 0; a < 3; ++a) {
                    c->X[3 * (n + kept) + a] = c->X[3 * (n + g) + a];
                    c->gsign[3 * kept + a] = c->gsign[3 * g + a];
                }
                c->gsrc[kept++] = c->gsrc[g];
            }
        }
        c->gstart[i] = first;
    }
    c->gstart[n] = (uint32_t)kept;
    for (size_t i = 0; i < n; ++i) {
        for (size_t q = 0; q < cnt[i]; ++q) {
            uint32_t *k = &lists[i * cap + q];
            *k = *k >= n ? (uint32_t)(n + map[*k - n]) : *k;
        }
    }
    free(map);
    c->na = n + kept;
    return 0;
}
