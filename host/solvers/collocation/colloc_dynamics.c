/*
 * colloc_dynamics.c — explicit time integration (central differences) and
 * its stable step.
 *
 * The step, with masses m, nodal forces f(u_n) and mass-proportional
 * damping alpha (force -alpha m v), is the central-difference (leapfrog)
 * scheme with the damping term centred in time:
 *
 *   v_{n+1/2} = ((1 - alpha dt/2) v_{n-1/2} + dt f(u_n) / m) / (1 + alpha dt/2),
 *   u_{n+1}   = u_n + dt v_{n+1/2},
 *
 * second-order accurate and symplectic without damping, stable for
 * dt < 2 / omega_max whatever alpha (omega_max^2 the largest eigenvalue of
 * M^-1 K).  Seed 004 used fourth-order Runge-Kutta through SOFA; RK4 needs
 * four force evaluations per step for a stable step only 1.4 times longer.
 *
 * The stable step is computed, not guessed: omega_max^2 is the largest
 * eigenvalue of M^-1/2 K M^-1/2 over the free components, K the stiffness
 * at the reference configuration applied without being assembled
 * (K y = -(f(eps y) - f(-eps y)) / 2 eps) and Lanczos's method (40 steps,
 * LAPACK dstev on the tridiagonal matrix).  The wave-speed bound
 * min r / c_p is printed beside it (docs/collocation.md).
 */
#include "solvers/collocation/colloc_internal.h"

#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/rng.h"
#include "materials/elasticity.h"

#define LANCZOS 40

void tf_colloc_impose(tf_colloc *c, double *u, double *v)
{
    for (size_t i = 0; i < c->n; ++i) {
        for (int a = 0; c->fixed[i] && a < 3; ++a) {
            if (c->fixed[i] >> a & 1) {
                u[3 * i + a] = c->ubar[3 * i + a];
                if (v) {
                    v[3 * i + a] = 0;
                }
            }
        }
    }
}

void tf_colloc_kick_drift(tf_colloc *c, const double *m, double dt, double alpha)
{
    double damp = alpha * dt / 2, keep = (1 - damp) / (1 + damp), gain = dt / (1 + damp);
#pragma omp parallel for schedule(static) num_threads(tf_colloc_threads(c))
    for (size_t i = 0; i < c->n; ++i) {
        double inv = gain / m[i];
        for (int a = 0; a < 3; ++a) {
            size_t q = 3 * i + a;
            if (c->fixed[i] >> a & 1) {
                c->u[q] = c->ubar[q];
                c->v[q] = 0;
            } else {
                c->v[q] = keep * c->v[q] + inv * (c->f[q] + c->fext[q]);
                c->u[q] += dt * c->v[q];
            }
        }
    }
}

static int all_finite(const double *x, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; ++i) {
        s += x[i] * 0; /* NaN or Inf anywhere makes s NaN */
    }
    return s == 0;
}

int tf_colloc_run(tf_ctx *ctx, tf_colloc *c, double dt, size_t steps, double alpha)
{
    if (!(dt > 0) || !isfinite(dt) || !(alpha >= 0) || !isfinite(alpha)) {
        return tf_fail(ctx, "time step %g s must be > 0 and damping %g 1/s >= 0", dt, alpha);
    }
    if (c->ball.on && c->ball.s.drive == TF_COLLOC_FORCE && !(c->ball.s.mass > 0)) {
        return tf_fail(ctx, "sphere: a force-driven indenter needs a mass > 0 in dynamics");
    }
    tf_colloc_impose(c, c->u, c->v);
    for (size_t k = 0; k < steps; ++k) {
        if (tf_colloc_eval(ctx, c, c->u, dt, c->f, NULL) != 0) {
            return -1;
        }
        tf_colloc_kick_drift(c, c->mass, dt, alpha);
        tf_colloc_contact(c, c->mass, dt, alpha, c->ball.s.mass);
        double *t = c->hold; /* the step is taken: its history is the state now */
        c->hold = c->hnew;
        c->hnew = t;
        c->time += dt;
        if ((k % 16 == 15 || k + 1 == steps) && !all_finite(c->u, 3 * c->n)) {
            return tf_fail(ctx,
                           "the motion is no longer finite after %zu steps of %g s: the step is "
                           "above the stable one (tf_colloc_critical_dt)",
                           k + 1, dt);
        }
    }
    return 0;
}

/* y = K x over the free components (K at the reference configuration). */
static int stiffness_times(tf_ctx *ctx, tf_colloc *c, const double *x, double *y, double *up,
                           double *fp, double *fm)
{
    size_t n3 = 3 * c->n;
    double big = 0, hmean = 0;
    for (size_t q = 0; q < n3; ++q) {
        big = fmax(big, fabs(x[q]));
    }
    for (size_t i = 0; i < c->n; ++i) {
        hmean += c->h[i] / (double)c->n;
    }
    double eps = big > 0 ? 1e-7 * hmean / big : 1;
    for (size_t q = 0; q < n3; ++q) {
        up[q] = eps * x[q];
    }
    if (tf_colloc_eval(ctx, c, up, 0, fp, NULL) != 0) {
        return -1;
    }
    for (size_t q = 0; q < n3; ++q) {
        up[q] = -eps * x[q];
    }
    if (tf_colloc_eval(ctx, c, up, 0, fm, NULL) != 0) {
        return -1;
    }
    for (size_t q = 0; q < n3; ++q) {
        y[q] = c->fixed[q / 3] >> (q % 3) & 1 ? 0 : -(fp[q] - fm[q]) / (2 * eps);
    }
    return 0;
}

static double dot(const double *a, const double *b, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; ++i) {
        s += a[i] * b[i];
    }
    return s;
}

double tf_colloc_omega2_max(tf_ctx *ctx, tf_colloc *c, const double *m)
{
    size_t n3 = 3 * c->n;
    double *buf = malloc(6 * n3 * sizeof *buf);
    if (buf == NULL) {
        return tf_fail(ctx, "out of memory for the stable-step estimate");
    }
    double *q = buf, *qold = buf + n3, *x = buf + 2 * n3, *w = buf + 3 * n3, *up = buf + 4 * n3,
           *fp = buf + 5 * n3;
    double alpha[LANCZOS], beta[LANCZOS];
    tf_rng r = {20240607};
    for (size_t k = 0; k < n3; ++k) {
        q[k] = c->fixed[k / 3] >> (k % 3) & 1 ? 0 : tf_rng_range(&r, -1, 1);
        qold[k] = 0;
    }
    double nq = sqrt(dot(q, q, n3));
    int steps = 0, rc = 0;
    double *fm = malloc(n3 * sizeof *fm);
    if (fm == NULL || !(nq > 0)) {
        free(buf);
        free(fm);
        return tf_fail(ctx, fm ? "no free component: nothing moves" : "out of memory");
    }
    for (size_t k = 0; k < n3; ++k) {
        q[k] /= nq;
    }
    for (int j = 0; j < LANCZOS; ++j) {
        for (size_t k = 0; k < n3; ++k) {
            x[k] = q[k] / sqrt(m[k / 3]);
        }
        if (stiffness_times(ctx, c, x, w, up, fp, fm) != 0) {
            rc = -1;
            break;
        }
        for (size_t k = 0; k < n3; ++k) {
            w[k] = w[k] / sqrt(m[k / 3]) - (j ? beta[j - 1] : 0) * qold[k];
        }
        alpha[j] = dot(w, q, n3);
        for (size_t k = 0; k < n3; ++k) {
            w[k] -= alpha[j] * q[k];
        }
        beta[j] = sqrt(dot(w, w, n3));
        steps = j + 1;
        if (!(beta[j] > 1e-12 * fabs(alpha[j]))) {
            break; /* an invariant subspace: exact */
        }
        for (size_t k = 0; k < n3; ++k) {
            qold[k] = q[k];
            q[k] = w[k] / beta[j];
        }
    }
    free(buf);
    free(fm);
    if (rc != 0) {
        return -1;
    }
    if (LAPACKE_dstev(LAPACK_COL_MAJOR, 'N', steps, alpha, beta, NULL, 1) != 0) {
        return tf_fail(ctx, "dstev failed on the Lanczos matrix");
    }
    return alpha[steps - 1]; /* ascending */
}

double tf_colloc_critical_dt(tf_ctx *ctx, tf_colloc *c)
{
    double w2 = tf_colloc_omega2_max(ctx, c, c->mass);
    if (!(w2 > 0)) {
        if (w2 >= 0) {
            tf_fail(ctx, "the stiffness has no positive eigenvalue");
        }
        return -1;
    }
    return 2 / sqrt(w2);
}

double tf_colloc_wave_dt(const tf_colloc *c)
{
    tf_lame l = tf_material_lame(&c->mat); /* the initial (fastest) response's */
    double cp = sqrt((l.lambda + 2 * l.mu) / c->density), r = INFINITY;
    for (size_t i = 0; i < c->n; ++i) {
        r = fmin(r, c->rmin[i]);
    }
    return r / cp;
}
