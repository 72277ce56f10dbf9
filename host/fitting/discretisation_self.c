/*
 * discretisation_self.c — see discretisation_self.h.
 */
#include "fitting/discretisation_self.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/clock.h"
#include "base/log.h"

static const double unit_forces[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

/* The points the clouds are compared at: the outputs, then the contact
 * point (3 (n_outputs + 1)). */
static double *points_of(const tf_solver *s, const tf_problem *p, int contact, size_t *np)
{
    const tf_outputs *o = &p->outputs;
    const double *xn = tf_solver_coords(s);
    double *x = malloc(3 * (o->n_nodes + 1) * sizeof *x);
    if (x == NULL) {
        return NULL;
    }
    for (size_t i = 0; i < o->n_nodes; ++i) {
        memcpy(x + 3 * i, o->points ? o->points + 3 * i : xn + 3 * (size_t)o->nodes[i],
               3 * sizeof *x);
    }
    const tf_contact *site = &p->contacts[contact];
    memcpy(x + 3 * o->n_nodes, site->by_node ? xn + 3 * (size_t)site->node : site->at,
           3 * sizeof *x);
    *np = o->n_nodes + 1;
    return x;
}

/* The cloud's nominal spacing, mm: an organ's interior spacing; a box's
 * geometric mean over the axes of more than two nodes. */
static double spacing_of(const tf_problem *p)
{
    const tf_mesh_geometry *m = tf_problem_mesh(p);
    if (m != NULL) {
        return m->mesh.spacing;
    }
    const tf_box_geometry *b = &p->geometry.as.box;
    double logsum = 0;
    int axes = 0;
    for (int a = 0; a < 3; ++a) {
        if (b->grid[a] > 2) {
            logsum += log((b->max[a] - b->min[a]) / (b->grid[a] - 1));
            ++axes;
        }
    }
    return exp(logsum / axes);
}

/* The load cases every cloud solves: a linear solve's three unit forces
 * (its error is linear in the force, so they bound the whole envelope); any
 * other solve's six forces of the envelope's radius along +-x, +-y, +-z
 * from its centre, where a nonlinear solve's error is largest (the figure
 * is then the largest over them). */
typedef struct self_cases {
    size_t n;
    double force[TF_SELF_MAX_CASES][3];
} self_cases;

static void cases_of(const tf_solver *s, const tf_problem *p, double reach, self_cases *c)
{
    if (tf_solver_caps_of(s) & TF_SOLVER_LINEAR) {
        c->n = 3;
        memcpy(c->force, unit_forces, sizeof unit_forces);
        return;
    }
    c->n = 6;
    for (size_t k = 0; k < 6; ++k) {
        memcpy(c->force[k], p->envelope.centre, sizeof c->force[k]);
        c->force[k][k / 2] += (k % 2 ? -1 : 1) * reach * p->envelope.radius;
    }
}

/* The cases' displacements at the points x, from solver s (u: n cases x
 * 3 np); a time-dependent solver's fully relaxed ones. */
static int fields(tf_ctx *ctx, tf_solver *s, int contact, const self_cases *c, const double *x,
                  size_t np, double *u)
{
    const size_t dofs = 3 * tf_solver_node_count(s);
    double *nodal = malloc(c->n * dofs * sizeof *nodal), *grad = malloc(9 * np * sizeof *grad);
    int rc = nodal && grad ? 0 : tf_fail(ctx, "out of memory");
    if (rc == 0 && tf_solver_solve(s, contact, (const double(*)[3])c->force, c->n, NULL, nodal) != 0) {
        rc = -1;
    }
    for (size_t k = 0; k < c->n && rc == 0; ++k) {
        rc = tf_solver_field(ctx, s, nodal + k * dofs, x, np, u + 3 * np * k, grad);
    }
    free(nodal);
    free(grad);
    return rc;
}

/* The same contact site on another cloud: its name, and its point. */
static int same_site(const tf_problem *p, const tf_solver *s, const tf_problem *q,
                     const tf_solver *t, int contact)
{
    if ((size_t)contact >= q->n_contacts) {
        return 0;
    }
    const tf_contact *a = &p->contacts[contact], *b = &q->contacts[contact];
    const double *xa = a->by_node ? tf_solver_coords(s) + 3 * (size_t)a->node : a->at;
    const double *xb = b->by_node ? tf_solver_coords(t) + 3 * (size_t)b->node : b->at;
    return strcmp(a->name, b->name) == 0 &&
           hypot(hypot(xa[0] - xb[0], xa[1] - xb[1]), xa[2] - xb[2]) < 1e-9;
}

/* Why the coarser level failed, in short, for the header (the log has the
 * whole message). */
static void coarser_why(tf_discretisation *out, int which, const char *why)
{
    if (which == 0) {
        snprintf(out->self_shifted_why, sizeof out->self_shifted_why, "%s", why);
    }
}

/* Level `which` (0 coarser, 2 finer) at spacing factor f: its fields at x. */
static int level(tf_ctx *ctx, const tf_rescale *re, double f, const tf_problem *p,
                 const tf_solver *s, int contact, const self_cases *c, const double *x, size_t np,
                 double *u, tf_discretisation *out, int which)
{
    const tf_problem *q = re->make(re->user, ctx, f);
    if (q == NULL) {
        coarser_why(out, which, "it could not be built");
        return tf_fail(ctx, "the cloud at %.4g times the spacing: %s", f, ctx->err);
    }
    tf_solver *t = tf_solver_create(q, NULL, ctx);
    int rc = t != NULL ? 0 : tf_fail(ctx, "the cloud at %.4g times the spacing: %s", f, ctx->err);
    if (rc != 0) {
        coarser_why(out, which, "its solver could not be set up");
    }
    if (rc == 0 && !same_site(p, s, q, t, contact)) {
        tf_fail(ctx, "the contact site moves with the cloud (no node of the cloud at %.4g times "
                     "the spacing lies at its point; a box two nodes thick scales its thickness "
                     "with the spacing)", f);
        coarser_why(out, which, "the contact site is not a node of it");
        rc = 1;
    }
    if (rc == 0) {
        out->self_h[which] = spacing_of(q);
        out->self_nodes[which] = tf_solver_node_count(t);
        tf_info(ctx, "fit: discretisation: the cloud of spacing %.4g mm (%zu nodes) solved",
                out->self_h[which], out->self_nodes[which]);
        rc = fields(ctx, t, contact, c, x, np, u);
        if (rc != 0) {
            out->self_solve_failed = 1;
            tf_fail(ctx, "the cloud of spacing %.4g mm: %s", out->self_h[which], ctx->err);
            char why[64];
            snprintf(why, sizeof why, "its solve at spacing %.4g mm failed", out->self_h[which]);
            coarser_why(out, which, why);
        }
    }
    tf_solver_destroy(t);
    re->release(re->user, q);
    return rc;
}

static double norm(const double *a, const double *b, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; ++i) {
        s += (a[i] - b[i]) * (a[i] - b[i]);
    }
    return sqrt(s);
}

/* The order p with (rc^p - 1) / (1 - rf^-p) = rho, by bisection (the left
 * side rises with p); NAN when rho lies outside what p in [0.1, 12] gives. */
static double observed_order(double rho, double rc, double rf)
{
    double lo = 0.1, hi = 12;
    const double at_lo = (pow(rc, lo) - 1) / (1 - pow(rf, -lo));
    const double at_hi = (pow(rc, hi) - 1) / (1 - pow(rf, -hi));
    if (!(rho >= at_lo && rho <= at_hi)) {
        return NAN;
    }
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        if ((pow(rc, mid) - 1) / (1 - pow(rf, -mid)) > rho) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    return 0.5 * (lo + hi);
}

/* The references u(h) - E for the two estimates, and the comparisons. */
static int estimate(tf_ctx *ctx, tf_solver *s, const tf_problem *p, int contact,
                    const self_cases *c, const double *x, size_t np, double *const u[3],
                    const double *own_u, tf_discretisation *out)
{
    const size_t n = 3 * np * c->n;
    const double rc = out->self_h[0] / out->self_h[1], rf = out->self_h[1] / out->self_h[2];
    const double dc = norm(u[0], u[1], n), df = norm(u[1], u[2], n);
    out->self_diff[0] = dc;
    out->self_diff[1] = df;
    out->self_order = df > 0 ? observed_order(dc / df, rc, rf) : NAN;
    if (!(df > 0)) {
        tf_fail(ctx, "the clouds of spacing %.4g and %.4g mm give the same outputs", out->self_h[1],
                out->self_h[2]);
        return 1;
    }
    /* No order observed (the differences do not shrink, as when cloud-to-
     * cloud scatter outweighs the trend): first order, the conservative
     * choice (a lower order makes E larger).  An order observed above the
     * cap, common before the asymptotic range, would make E smaller. */
    const double q = isnan(out->self_order) || out->self_order < TF_SELF_ORDER_MIN
                         ? TF_SELF_ORDER_MIN
                         : fmin(out->self_order, TF_SELF_ORDER_MAX);
    out->self_order_used = q;
    double *ref = malloc(2 * n * sizeof *ref);
    if (ref == NULL) {
        return tf_fail(ctx, "out of memory");
    }
    for (size_t i = 0; i < n; ++i) {
        ref[i] = u[1][i] - (u[1][i] - u[2][i]) / (1 - pow(rf, -q));  /* the finer pair */
        ref[n + i] = u[1][i] - (u[0][i] - u[1][i]) / (pow(rc, q) - 1); /* the coarser pair */
    }
    tf_discretisation other = {0};
    const double *fine[TF_SELF_MAX_CASES], *coarse[TF_SELF_MAX_CASES], *own[TF_SELF_MAX_CASES];
    for (size_t k = 0; k < c->n; ++k) {
        fine[k] = ref + 3 * np * k;
        coarse[k] = ref + n + 3 * np * k;
        own[k] = own_u + 3 * np * k;
    }
    const double(*f)[3] = (const double(*)[3])c->force;
    int rc2 = tf_discretisation_compare(ctx, s, p, contact, f, c->n, x, np, coarse, own, &other);
    if (rc2 == 0) {
        rc2 = tf_discretisation_compare(ctx, s, p, contact, f, c->n, x, np, fine, own, out);
    }
    out->self_other_mm = other.max_mm;
    free(ref);
    return rc2;
}

/* Whether the three clouds' spacings fall strictly. */
static int falling(const tf_discretisation *out)
{
    return out->self_h[0] > out->self_h[1] * (1 + 1e-9) &&
           out->self_h[2] < out->self_h[1] * (1 - 1e-9);
}

/* The clouds h/r and h/r^2 after the coarser one failed: the scene's own
 * cloud becomes the coarsest of the three (u[0]), solved by s. */
static int finer_levels(tf_ctx *ctx, const tf_rescale *re, tf_solver *s, const tf_problem *p,
                        int contact, const self_cases *c, const double *x, size_t np,
                        double *const u[3], tf_discretisation *out)
{
    out->self_h[0] = out->self_h[1];
    out->self_nodes[0] = out->self_nodes[1];
    tf_info(ctx, "fit: discretisation: the coarser cloud failed (%s); the scene's cloud, h/%.4g "
                 "and h/%.4g instead", out->self_shifted_why, TF_SELF_FACTOR,
            TF_SELF_FACTOR * TF_SELF_FACTOR);
    if (fields(ctx, s, contact, c, x, np, u[0]) != 0) {
        out->self_solve_failed = 1;
        return tf_fail(ctx, "the scene's own cloud: %s", ctx->err);
    }
    int rc = level(ctx, re, 1 / TF_SELF_FACTOR, p, s, contact, c, x, np, u[1], out, 1);
    if (rc == 0) {
        rc = level(ctx, re, 1 / (TF_SELF_FACTOR * TF_SELF_FACTOR), p, s, contact, c, x, np, u[2],
                   out, 2);
    }
    return rc;
}

/* One measurement with the cases at `reach` of the envelope's radius: the
 * coarser, the scene's and the finer cloud, or the scene's and two finer
 * ones when the coarser fails. */
static int measure(tf_ctx *ctx, const tf_rescale *re, tf_solver *s, const tf_problem *p,
                   int contact, const self_cases *c, const double *x, size_t np,
                   double *const u[3], tf_discretisation *out)
{
    int rc = level(ctx, re, TF_SELF_FACTOR, p, s, contact, c, x, np, u[0], out, 0);
    /* a box keeps an axis whose node sites would not stay nodes (and an
     * axis of two intervals rounds back to two at 4/3) */
    int same = rc == 0 && !(out->self_h[0] > out->self_h[1] * (1 + 1e-9));
    if (same) {
        rc = tf_fail(ctx, "the cloud of spacing %.4g mm is not coarser than the scene's %.4g mm",
                     out->self_h[0], out->self_h[1]);
    }
    /* A coarse cloud may fail where the scene's solves (Newton past a
     * limit point the coarser discretisation reaches first, a node site
     * no coarser grid keeps): the scene's cloud, h/r and h/r^2.  The
     * header gets the short reason, the log the whole message. */
    if (rc != 0) {
        out->self_shifted = 1; /* (a failed solve stays flagged: smaller forces may serve) */
        if (same) {
            coarser_why(out, 0, "no coarser grid keeps the contact node");
        }
        tf_info(ctx, "fit: discretisation: the coarser cloud: %s", ctx->err);
        rc = finer_levels(ctx, re, s, p, contact, c, x, np, u, out);
    } else {
        rc = level(ctx, re, 1 / TF_SELF_FACTOR, p, s, contact, c, x, np, u[2], out, 2);
    }
    if (rc == 0 && !falling(out)) {
        tf_fail(ctx, "the clouds of spacing %.4g, %.4g and %.4g mm are not coarser and finer (a "
                     "contact node that no other grid keeps)",
                out->self_h[0], out->self_h[1], out->self_h[2]);
        rc = 1;
    }
    if (rc == 0 && !out->self_shifted && fields(ctx, s, contact, c, x, np, u[1]) != 0) {
        out->self_solve_failed = 1;
        rc = tf_fail(ctx, "the scene's own cloud: %s", ctx->err);
    }
    if (rc == 0) {
        rc = estimate(ctx, s, p, contact, c, x, np, u, u[out->self_shifted ? 0 : 1], out);
    }
    if (rc != 0 && out->self_shifted) {
        tf_fail(ctx, "%s (after the coarser cloud failed: %s)", ctx->err, out->self_shifted_why);
    }
    return rc;
}

/* The fractions of the envelope's radius a nonlinear measurement tries, in
 * turn, while a cloud's solve fails (a finer cloud can lose stability
 * before the envelope where the scene's own does not). */
static const double reaches[] = {1.0, 0.75, 0.5};

/* out as a measurement starts: nothing of an earlier attempt left. */
static void start(tf_discretisation *out, const tf_solver *s, const tf_problem *p)
{
    memset(out, 0, sizeof *out);
    snprintf(out->source, sizeof out->source, "self-measured");
    out->self = 1;
    out->self_order = out->self_order_used = out->self_other_mm = NAN;
    out->self_relaxed = (tf_solver_caps_of(s) & TF_SOLVER_TIME_DEPENDENT) != 0;
    out->self_h[1] = spacing_of(p);
    out->self_nodes[1] = tf_solver_node_count(s);
    const tf_mesh_geometry *m = tf_problem_mesh(p);
    out->self_skin_kept = m != NULL && !m->mesh.refine_skin;
}

int tf_discretisation_self(tf_ctx *ctx, const tf_rescale *re, tf_solver *s, const tf_problem *p,
                           int contact, tf_discretisation *out)
{
    start(out, s, p);
    if (contact < 0 || (size_t)contact >= p->n_contacts) {
        return tf_fail(ctx, "a discretisation measurement needs a contact site");
    }
    /* the clouds are compared at the scene's points, between the other
     * clouds' nodes */
    if (!tf_solver_has_field(s)) {
        tf_fail(ctx, "the solver %s gives no displacement field between its nodes, which the "
                     "comparison of clouds needs", tf_solver_name(s));
        return 1;
    }
    const double t0 = tf_seconds();
    const int linear = (tf_solver_caps_of(s) & TF_SOLVER_LINEAR) != 0;
    const size_t n_cases = linear ? 3 : 6;
    size_t np = 0;
    double *x = points_of(s, p, contact, &np), *u[3] = {NULL, NULL, NULL};
    int rc = x != NULL ? 0 : tf_fail(ctx, "out of memory");
    for (int k = 0; k < 3 && rc == 0; ++k) {
        u[k] = malloc(3 * np * n_cases * sizeof *u[k]);
        rc = u[k] != NULL ? 0 : tf_fail(ctx, "out of memory");
    }
    char first[TF_CTX_ERR_MAX] = "";
    for (size_t k = 0; rc == 0 && k < sizeof reaches / sizeof reaches[0]; ++k) {
        self_cases c;
        cases_of(s, p, reaches[k], &c);
        start(out, s, p);
        out->cases = c.n;
        if (k > 0) {
            tf_info(ctx, "fit: discretisation: again with forces of %.3g of the envelope's radius",
                    reaches[k]);
        }
        rc = measure(ctx, re, s, p, contact, &c, x, np, u, out);
        if (rc == 0 || linear || !out->self_solve_failed) {
            break;
        }
        if (k == 0) {
            snprintf(first, sizeof first, "%s", ctx->err);
        }
        tf_info(ctx, "fit: discretisation: at %.3g of the envelope's radius: %s", reaches[k],
                ctx->err);
        rc = 0;
        if (k + 1 == sizeof reaches / sizeof reaches[0]) {
            rc = tf_fail(ctx, "%s (and at the envelope's radius: %.600s)", ctx->err, first);
        }
    }
    out->self_seconds = tf_seconds() - t0;
    free(x);
    for (int k = 0; k < 3; ++k) {
        free(u[k]);
    }
    return rc;
}
