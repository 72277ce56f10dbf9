/*
 * colloc_relax.c — static answers by dynamic relaxation (Underwood 1983,
 * "Dynamic relaxation", in Computational Methods for Transient Analysis,
 * ch. 5; derived again here).
 *
 * The equilibrium f(u) + fext = 0 is the end state of a damped motion, so
 * the masses and the damping may be anything that gets there fastest:
 *
 * - fictitious masses m_i = c v_i / h_i^2 (the local stiffness ~ E v / h^2)
 *   make every particle's own frequency about the same, so a graded cloud
 *   relaxes in as many steps as a uniform one of as many particles across;
 *   c is set by the Lanczos estimate of omega_max so that the unit step is
 *   0.9 of the stable one;
 * - damping adapted to the lowest mode: alpha = 2 sqrt(rho), rho the
 *   Rayleigh quotient du.(-df) / du.M du of the displacement so far (it
 *   tends to the lowest mode as the motion dies out), the critical damping
 *   of that mode;
 * - a force-driven sphere gets a fictitious mass too: four times the mass
 *   of the particles it touches (at least the largest particle's), so that
 *   its step is stable against the contact's stiffness.
 *
 * Converged when the residual (the net force at free components, less the
 * sphere's reactions, and for a force-driven sphere its own net force) is
 * below tol times the applied and reaction forces (2-norms), and the motion
 * has died out: the last step moved no component by more than tol times
 * the largest displacement so far (the kinetic criterion; with unit steps
 * the largest speed).  Both are checked every step.
 *
 * The residual cannot fall below the rounding of F = I + grad u: the
 * strain of a particle carries an absolute error of about the machine
 * epsilon whatever the load, so a small load or a stiff material meets a
 * floor (measured on block48: 4.5e-13 N at E = 0.32 MPa).  The tolerance is
 * therefore at least the estimate 16 eps (lambda + 2 mu) |v_i / h_i|_2,
 * about 6 times the measured floor, over the force scale (for both
 * criteria).
 */
#include "solvers/collocation/colloc_internal.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "materials/elasticity.h"

/* Fraction of the stable unit step the fictitious masses allow. */
#define SAFETY 0.9

void tf_colloc_relax_defaults(tf_colloc_relax_opts *o)
{
    o->tol = 1e-6;
    o->max_steps = 200000;
}

/* The residual's rounding floor (see above), N. */
static double floor_of(const tf_colloc *c)
{
    double s = 0;
    tf_lame l = tf_material_lame(&c->mat); /* the initial response's */
    for (size_t i = 0; i < c->n; ++i) {
        s += (c->vol[i] / c->h[i]) * (c->vol[i] / c->h[i]);
    }
    return 16 * DBL_EPSILON * (l.lambda + 2 * l.mu + c->opts.kv) * sqrt(s);
}

static int fictitious_masses(tf_ctx *ctx, tf_colloc *c)
{
    size_t n = c->n;
    c->mdr = calloc(n, sizeof *c->mdr);
    c->u0 = malloc(3 * n * sizeof *c->u0);
    c->f0 = malloc(3 * n * sizeof *c->f0);
    c->res = malloc(3 * n * sizeof *c->res);
    if (!c->mdr || !c->u0 || !c->f0 || !c->res) {
        return tf_fail(ctx, "out of memory for the relaxation");
    }
    for (size_t i = 0; i < n; ++i) {
        c->mdr[i] = c->vol[i] / (c->h[i] * c->h[i]);
    }
    double w2 = tf_colloc_omega2_max(ctx, c, c->mdr);
    if (!(w2 > 0)) {
        if (w2 >= 0) {
            tf_fail(ctx, "the stiffness has no positive eigenvalue");
        }
        free(c->mdr);
        c->mdr = NULL;
        return -1;
    }
    double scale = w2 / (4 * SAFETY * SAFETY); /* omega_max = 2 SAFETY at dt = 1 */
    for (size_t i = 0; i < n; ++i) {
        c->mdr[i] *= scale;
    }
    return 0;
}

/* Residual and force scale (2-norms) at the current state; c->f holds the
 * elastic forces. */
static void residual(tf_colloc *c, double *rnorm, double *scale)
{
    double fc = tf_colloc_contact_static(c, c->res), r2 = 0, s2 = 0;
    for (size_t q = 0; q < 3 * c->n; ++q) {
        r2 += c->res[q] * c->res[q];
        double applied = c->fixed[q / 3] >> (q % 3) & 1 ? c->f[q] + c->fext[q] : c->fext[q];
        s2 += applied * applied;
    }
    if (c->ball.on && c->ball.s.drive == TF_COLLOC_FORCE) { /* the sphere's balance */
        double rs = c->ball.s.force - fc;
        r2 += rs * rs;
        s2 += c->ball.s.force * c->ball.s.force;
    }
    *rnorm = sqrt(r2);
    *scale = sqrt(s2) + fabs(fc);
}

/* The largest speed against the largest displacement since u0. */
static int at_rest(const tf_colloc *c, double tol)
{
    double vmax = 0, umax = 0;
    for (size_t q = 0; q < 3 * c->n; ++q) {
        vmax = fmax(vmax, fabs(c->v[q]));
        umax = fmax(umax, fabs(c->u[q] - c->u0[q]));
    }
    return vmax <= tol * umax;
}

/* 2 sqrt of the Rayleigh quotient of the displacement so far, or the
 * previous value when there is none yet. */
static double adapt(const tf_colloc *c, double alpha)
{
    double num = 0, den = 0;
    for (size_t q = 0; q < 3 * c->n; ++q) {
        if (!(c->fixed[q / 3] >> (q % 3) & 1)) {
            double du = c->u[q] - c->u0[q];
            num += -du * (c->f[q] - c->f0[q]);
            den += du * du * c->mdr[q / 3];
        }
    }
    if (num > 0 && den > 0) {
        alpha = fmin(2 * sqrt(num / den), 1.0);
    }
    return alpha;
}

int tf_colloc_relax(tf_ctx *ctx, tf_colloc *c, const tf_colloc_relax_opts *o,
                    tf_colloc_relax_stats *st)
{
    tf_colloc_relax_opts def;
    tf_colloc_relax_stats dummy;
    if (o == NULL) {
        tf_colloc_relax_defaults(&def);
        o = &def;
    }
    st = st ? st : &dummy;
    *st = (tf_colloc_relax_stats){0};
    if (!(o->tol > 0)) {
        return tf_fail(ctx, "relaxation tolerance %g must be > 0", o->tol);
    }
    if (c->mdr == NULL && fictitious_masses(ctx, c) != 0) {
        return -1;
    }
    size_t n3 = 3 * c->n;
    memset(c->v, 0, n3 * sizeof *c->v);
    c->ball.speed = 0;
    tf_colloc_impose(c, c->u, NULL);
    tf_colloc_contact(c, c->mdr, 1, 0, 0); /* particles inside the sphere onto it */
    memcpy(c->u0, c->u, n3 * sizeof *c->u0);
    if (tf_colloc_eval(ctx, c, c->u, 0, c->f0, NULL) != 0) {
        return -1;
    }
    double alpha = 0, mmax = 0, floor = floor_of(c);
    for (size_t i = 0; i < c->n; ++i) {
        mmax = fmax(mmax, c->mdr[i]);
    }
    for (size_t k = 0;; ++k) {
        if (tf_colloc_eval(ctx, c, c->u, 0, c->f, NULL) != 0) {
            return -1;
        }
        double rnorm, scale;
        residual(c, &rnorm, &scale);
        st->steps = k;
        st->residual = scale > 0 ? rnorm / scale : rnorm;
        if (!isfinite(st->residual)) {
            return tf_fail(ctx, "the relaxation diverged after %zu steps", k);
        }
        double tol = scale > 0 ? fmax(o->tol, floor / scale) : o->tol; /* the floor's */
        if (rnorm <= tol * scale && at_rest(c, tol)) {
            st->converged = 1;
            break;
        }
        if (k == o->max_steps) {
            break;
        }
        alpha = adapt(c, alpha);
        tf_colloc_kick_drift(c, c->mdr, 1, alpha);
        double ms = 4 * fmax(tf_colloc_contact_mass(c, c->mdr), mmax);
        tf_colloc_contact(c, c->mdr, 1, alpha, ms);
    }
    memset(c->v, 0, n3 * sizeof *c->v);
    c->ball.speed = 0;
    return st->converged ? 0 : 1;
}
