/*
 * colloc_contact.c — a frictionless rigid sphere pressed into the body
 * (the Hertz test of seed 004 §3).
 *
 * Contact is a constraint, not a penalty: after each drift, a particle
 * inside the sphere is put back on its surface along the radius through
 * it, and the part of its velocity (relative to the sphere) that points
 * into the sphere is removed.  No stiffness is added, so the stable step is
 * the body's, and in equilibrium no particle penetrates (a penalty would
 * leave a penetration of force / penalty stiffness).  What the constraint
 * cannot see: the body's surface between particles may cut into the
 * sphere; the contact area is resolved by particles, so F(d) has the
 * discretisation error of a contact radius measured in particle spacings
 * (docs/collocation.md, Hertz).
 *
 * The force on the sphere is, in a dynamic step, the constraint force that
 * removed the particles' inward velocity (the momentum taken over dt, with
 * the damped step's gain); in equilibrium (tf_colloc_relax), the
 * sum of the particles' inward forces on it, which is the same number once
 * the motion has died out and has no lag.
 */
#include "solvers/collocation/colloc_internal.h"

#include <math.h>
#include <stdio.h>

/* Particles with a distance to the centre up to R (1 + this) touch. */
#define TOUCH 1e-9

int tf_colloc_set_sphere(tf_ctx *ctx, tf_colloc *c, const tf_colloc_sphere *s)
{
    double len = sqrt(s->dir[0] * s->dir[0] + s->dir[1] * s->dir[1] + s->dir[2] * s->dir[2]);
    if (!(s->radius > 0) || !isfinite(s->radius) || !(len > 0) || !isfinite(len)) {
        return tf_fail(ctx, "sphere: radius %g mm and |dir| %g must be finite and > 0", s->radius,
                       len);
    }
    if (s->drive == TF_COLLOC_FORCE && (!(s->mass >= 0) || !isfinite(s->force))) {
        return tf_fail(ctx, "sphere: force %g N must be finite and mass %g t >= 0", s->force,
                       s->mass);
    }
    c->ball = (tf_colloc_ball){0};
    c->ball.on = 1;
    c->ball.s = *s;
    for (int a = 0; a < 3; ++a) {
        c->ball.s.dir[a] = s->dir[a] / len;
    }
    return 0;
}

void tf_colloc_remove_sphere(tf_colloc *c) { c->ball.on = 0; }
void tf_colloc_set_travel(tf_colloc *c, double travel) { c->ball.travel = travel; }
double tf_colloc_travel(const tf_colloc *c) { return c->ball.travel; }
void tf_colloc_set_push(tf_colloc *c, double force) { c->ball.s.force = force; }
double tf_colloc_contact_force(const tf_colloc *c) { return c->ball.force; }
size_t tf_colloc_contacts(const tf_colloc *c) { return c->ball.contacts; }

static void centre(const tf_colloc *c, double x[3])
{
    for (int a = 0; a < 3; ++a) {
        x[a] = c->ball.s.centre[a] + c->ball.travel * c->ball.s.dir[a];
    }
}

/* Particle i inside the sphere: back onto the surface; returns the
 * momentum taken along dir (>= 0 when the particle pushes back), or a
 * negative value when i is outside.  n receives the outward normal. */
static double project(tf_colloc *c, size_t i, const double ctr[3], double vs, double mi)
{
    if (c->fixed[i] == TF_COLLOC_FIX_ALL) {
        return -1;
    }
    double *ui = c->u + 3 * i, *vi = c->v + 3 * i, r[3], d2 = 0, R = c->ball.s.radius;
    const double *dir = c->ball.s.dir;
    for (int a = 0; a < 3; ++a) {
        r[a] = c->X[3 * i + a] + ui[a] - ctr[a];
        d2 += r[a] * r[a];
    }
    if (!(d2 < R * R)) {
        return -1;
    }
    double d = sqrt(d2), n[3], vn = 0;
    if (!(d > 0)) { /* at the centre: out along -dir */
        n[0] = -dir[0];
        n[1] = -dir[1];
        n[2] = -dir[2];
    } else {
        for (int a = 0; a < 3; ++a) {
            n[a] = r[a] / d;
        }
    }
    for (int a = 0; a < 3; ++a) {
        if (!(c->fixed[i] >> a & 1)) {
            ui[a] = ctr[a] + R * n[a] - c->X[3 * i + a];
        }
        vn += (vi[a] - vs * dir[a]) * n[a];
    }
    if (!(vn < 0)) {
        return 0;
    }
    double taken = 0;
    for (int a = 0; a < 3; ++a) {
        if (!(c->fixed[i] >> a & 1)) {
            vi[a] -= vn * n[a];
            taken += -vn * n[a] * dir[a];
        }
    }
    return mi * taken;
}

/* The sphere moves (force drive), then the particles are put back. */
void tf_colloc_contact(tf_colloc *c, const double *m, double dt, double alpha, double ms)
{
    if (!c->ball.on) {
        return;
    }
    tf_colloc_ball *b = &c->ball;
    if (b->s.drive == TF_COLLOC_FORCE && ms > 0) {
        double damp = alpha * dt / 2;
        b->speed = ((1 - damp) * b->speed + dt * (b->s.force - b->force) / ms) / (1 + damp);
        b->travel += dt * b->speed;
    }
    double ctr[3], vs = b->s.drive == TF_COLLOC_FORCE ? b->speed : 0;
    centre(c, ctr);
    double p = 0;
    size_t touching = 0;
    for (size_t i = 0; i < c->n; ++i) { /* serial: the sum's order is fixed */
        double taken = project(c, i, ctr, vs, m[i]);
        if (taken >= 0) {
            p += taken;
            touching++;
        }
    }
    /* The constraint force lambda is what the step's update (dt/(1 + alpha
     * dt/2) per unit force, colloc_dynamics.c) needs to remove the inward
     * velocity: lambda = m dv (1 + alpha dt/2) / dt. */
    b->force = p * (1 + alpha * dt / 2) / dt;
    b->contacts = touching;
}

double tf_colloc_contact_static(tf_colloc *c, double *res)
{
    double ctr[3], force = 0, R = 0;
    size_t touching = 0;
    if (c->ball.on) {
        centre(c, ctr);
        R = c->ball.s.radius * (1 + TOUCH);
    }
    for (size_t i = 0; i < c->n; ++i) {
        double *ri = res + 3 * i, r[3], d2 = 0;
        for (int a = 0; a < 3; ++a) {
            ri[a] = c->fixed[i] >> a & 1 ? 0 : c->f[3 * i + a] + c->fext[3 * i + a];
        }
        if (!c->ball.on || c->fixed[i] == TF_COLLOC_FIX_ALL) {
            continue;
        }
        for (int a = 0; a < 3; ++a) {
            r[a] = c->X[3 * i + a] + c->u[3 * i + a] - ctr[a];
            d2 += r[a] * r[a];
        }
        if (!(d2 <= R * R) || !(d2 > 0)) {
            continue;
        }
        double d = sqrt(d2), fn = 0;
        for (int a = 0; a < 3; ++a) {
            fn += ri[a] * r[a] / d;
        }
        touching++;
        if (fn < 0) { /* pushes into the sphere: the sphere's reaction takes it */
            double along = 0;
            for (int a = 0; a < 3; ++a) {
                ri[a] -= fn * r[a] / d;
                along += r[a] / d * c->ball.s.dir[a];
            }
            force += -fn * along;
        }
    }
    if (c->ball.on) {
        c->ball.force = force;
        c->ball.contacts = touching;
    }
    return force;
}

double tf_colloc_contact_mass(const tf_colloc *c, const double *m)
{
    double sum = 0, ctr[3], R = c->ball.s.radius * (1 + TOUCH);
    if (!c->ball.on) {
        return 0;
    }
    centre(c, ctr);
    for (size_t i = 0; i < c->n; ++i) {
        double d2 = 0;
        for (int a = 0; a < 3; ++a) {
            double r = c->X[3 * i + a] + c->u[3 * i + a] - ctr[a];
            d2 += r * r;
        }
        if (d2 <= R * R) {
            sum += m[i];
        }
    }
    return sum;
}
