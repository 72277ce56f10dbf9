/*
 * colloc_mls.c — the MLS gradient of seed 004 eqs 6-9 in the reference
 * configuration (total Lagrangian, as TLED does: computed once).
 *
 * Minimising e = sum_k w_ik (u_i + grad u . X_ik - u_k)^2 (eqs 7-8) gives
 * A_i grad u_a = sum_k w_ik (u_ka - u_ia) X_ik (eq 9), A_i = sum_k w_ik
 * X_ik X_ik^T the moment matrix, X_ik = X_k - X_i.  So
 *
 *   grad u|_i = (sum_k (u_k - u_i) y_ik^T) A_i^-1,   y_ik = w_ik X_ik,
 *
 * and y_ik and A_i^-1 are all a step needs.  The fit reproduces every
 * linear field exactly (first-order consistency).  Set-up refuses a moment
 * matrix whose reciprocal condition is below rcond_min, naming the
 * particle.
 */
#include "solvers/collocation/colloc_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "materials/elasticity.h"
#include "materials/kinematics.h"

static double norm1(const double a[9])
{
    double m = 0;
    for (int col = 0; col < 3; ++col) {
        m = fmax(m, fabs(a[col]) + fabs(a[3 + col]) + fabs(a[6 + col]));
    }
    return m;
}

/* The shear modulus the residual energy is scaled with: the law's
 * (instantaneous) one. */
static double shear_modulus(const tf_material *m)
{
    return tf_material_lame(m).mu;
}

/* Particle i: A_i (in coordinates divided by h_i, which makes the
 * condition comparable between particles), its inverse, s_i, beta_i.
 * Returns the reciprocal condition (1-norm) of A_i, 0 when singular. */
static double particle(tf_colloc *c, size_t i, double mu)
{
    const double *xi = c->X + 3 * i;
    double A[9] = {0}, inv[9], hi = c->h[i], w2 = 0, *s = c->s + 3 * i;
    s[0] = s[1] = s[2] = 0;
    for (uint32_t p = c->start[i]; p < c->start[i + 1]; ++p) {
        const double *xk = c->X + 3 * (size_t)c->nbr[p];
        double x[3] = {xk[0] - xi[0], xk[1] - xi[1], xk[2] - xi[2]}, w = c->w[p];
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) {
                A[3 * a + b] += w * (x[a] / hi) * (x[b] / hi);
            }
            s[a] += c->y[3 * (size_t)p + a];
        }
        w2 += w * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    }
    double det = tf_det3(A);
    if (det > 0) {
        tf_inverse_sym3(A, det, inv);
    }
    if (!(det > 0) || !isfinite(det) || !(w2 > 0)) {
        return 0;
    }
    for (int k = 0; k < 9; ++k) {
        c->ainv[9 * i + (size_t)k] = inv[k] / (hi * hi);
    }
    /* Residual energy (colloc_force.c): stab mu v_i sum w |r|^2 / sum w |X|^2,
     * i.e. 1/2 beta_i sum w |r|^2. */
    c->beta[i] = 2 * c->opts.stab * mu * c->vol[i] / w2;
    return 1 / (norm1(A) * norm1(inv));
}

/* The pairs grouped by the neighbour (particle or image) that receives
 * their force, in ascending order of the particle whose stress makes it;
 * and the forward pairs' y and w side by side (colloc_internal.h). */
static int reverse(tf_colloc *c)
{
    size_t n = c->n, na = c->na, nnz = c->start[n];
    c->rstart = calloc(na + 1, sizeof *c->rstart);
    c->rsrc = malloc((nnz + 1) * sizeof *c->rsrc);
    c->ryc = malloc((4 * nnz + 1) * sizeof *c->ryc);
    c->yw = malloc((4 * nnz + 1) * sizeof *c->yw);
    c->bsum = calloc(na + 1, sizeof *c->bsum);
    uint32_t *fill = malloc((na + 1) * sizeof *fill);
    if (!c->rstart || !c->rsrc || !c->ryc || !c->yw || !c->bsum || !fill) {
        free(fill);
        return -1;
    }
    for (size_t p = 0; p < nnz; ++p) {
        c->rstart[c->nbr[p] + 1]++;
    }
    for (size_t k = 0; k < na; ++k) {
        c->rstart[k + 1] += c->rstart[k];
    }
    for (size_t k = 0; k <= na; ++k) {
        fill[k] = c->rstart[k];
    }
    for (size_t i = 0; i < n; ++i) {
        for (uint32_t p = c->start[i]; p < c->start[i + 1]; ++p) {
            uint32_t k = c->nbr[p], e = fill[k]++;
            double *r = c->ryc + 4 * (size_t)e, *f = c->yw + 4 * (size_t)p;
            c->rsrc[e] = (uint32_t)i;
            r[3] = c->beta[i] * c->w[p];
            c->bsum[k] += r[3]; /* ascending i: a fixed order */
            for (int a = 0; a < 3; ++a) {
                r[a] = f[a] = c->y[3 * (size_t)p + a];
            }
            f[3] = c->w[p];
        }
    }
    free(fill);
    return 0;
}

int tf_colloc_setup_mls(tf_ctx *ctx, tf_colloc *c)
{
    double mu = shear_modulus(&c->mat);
    double *rc = malloc(c->n * sizeof *rc);
    if (rc == NULL) {
        return tf_fail(ctx, "out of memory for the moment matrices");
    }
#pragma omp parallel for schedule(static) num_threads(tf_colloc_threads(c))
    for (size_t i = 0; i < c->n; ++i) {
        rc[i] = particle(c, i, mu);
    }
    c->rcond = 2;
    for (size_t i = 0; i < c->n; ++i) { /* the first worst particle, in index order */
        if (rc[i] < c->rcond) {
            c->rcond = rc[i];
            c->rcond_at = i;
        }
    }
    free(rc);
    if (c->rcond < c->opts.rcond_min) {
        size_t i = c->rcond_at;
        return tf_fail(ctx,
                       "particle %zu at (%g, %g, %g) mm: its moment matrix (eq 9) is near singular "
                       "(reciprocal condition %.3g < %g) with %u neighbours: they lie close to a "
                       "plane or a line; use more neighbours or a cloud without flat clusters",
                       i, c->X[3 * i], c->X[3 * i + 1], c->X[3 * i + 2], c->rcond,
                       c->opts.rcond_min, (unsigned)(c->start[i + 1] - c->start[i]));
    }
    if (reverse(c) != 0) {
        return tf_fail(ctx, "out of memory for the reverse supports");
    }
    return 0;
}
