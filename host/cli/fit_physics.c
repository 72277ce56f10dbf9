/*
 * fit_physics.c — see fit_physics.h.
 */
#include "cli/fit_physics.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/log.h"
#include "fitting/discretisation_self.h"
#include "scene/scene_levels.h"

/* The scene at a spacing factor, for the self-measurement. */
typedef struct rescale_scene {
    const char *path;
    const tf_sets *sets;
    tf_scene *scene; /* the one made last, until released */
} rescale_scene;

static const tf_problem *make(void *user, tf_ctx *ctx, double f)
{
    rescale_scene *r = user;
    r->scene = tf_scene_scaled(ctx, r->path, r->sets->item, r->sets->n, f);
    return r->scene != NULL ? &r->scene->problem : NULL;
}

static void release(void *user, const tf_problem *p)
{
    rescale_scene *r = user;
    (void)p;
    tf_scene_free(r->scene);
    r->scene = NULL;
}

int tf_fit_physics_self(tf_ctx *ctx, const char *path, const tf_sets *sets, tf_solver *s,
                        const tf_problem *p, int contact, tf_discretisation *out)
{
    rescale_scene r = {.path = path, .sets = sets};
    const tf_rescale re = {.make = make, .release = release, .user = &r};
    tf_info(ctx, "fit: the solve against the physics: self-measured on a coarser and a finer "
                 "cloud (tissuefit fit --no-discretisation skips it)");
    int rc = tf_discretisation_self(ctx, &re, s, p, contact, out);
    if (rc == 0) {
        tf_info(ctx, "fit: discretisation (self-measured, observed order %.3g, taken as %.3g): "
                     "max %.3g mm over the envelope (the coarser pair: %.3g mm), contact site "
                     "%.3g %%; %.1f s%s",
                out->self_order, out->self_order_used, out->max_mm, out->self_other_mm, 100 * out->site_rel,
                out->self_seconds, out->self_shifted ? " (the scene's cloud, h/r and h/r^2: the "
                                                       "coarser cloud failed)" : "");
        if (!out->enveloped && out->reach < 1 - 1e-9) { /* shown under -q too */
            tf_warn(ctx, "fit: the discretisation is measured up to %.3g %% of the envelope's "
                         "radius only (a cloud's solve failed at the radius; the header says so)",
                    100 * out->reach);
        }
    }
    return rc == 0 ? 0 : 1;
}

/* How the self-measurement was made, for the forward model's note (not its
 * time: a header is a function of the models). */
static void self_note(const tf_discretisation *d, char *buf, size_t n)
{
    char order[192];
    if (isnan(d->self_order)) {
        snprintf(order, sizeof order, "no order observed (the outputs change by %.3g then %.3g mm "
                 "L2), first order taken", d->self_diff[0], d->self_diff[1]);
    } else if (d->self_order != d->self_order_used) {
        snprintf(order, sizeof order, "observed order %.3g, taken as %.3g", d->self_order,
                 d->self_order_used);
    } else {
        snprintf(order, sizeof order, "observed order %.3g", d->self_order);
    }
    char over[320];
    if (d->enveloped) {
        snprintf(over, sizeof over, "bound over the envelope (linear)");
    } else {
        char of[64] = "the envelope's radius"; /* less when a cloud failed at the radius */
        if (d->reach < 1 - 1e-9) {
            snprintf(of, sizeof of, "%.3g %% of the envelope's radius", 100 * d->reach);
        }
        snprintf(over, sizeof over, "largest over the 6 forces of %s along +-x, +-y, +-z%s%s", of,
                 d->self_relaxed ? " (the fully relaxed response)" : "",
                 d->reach < 1 - 1e-9 ? " (a cloud's solve failed at the radius; not measured "
                                       "beyond)" : "");
    }
    if (d->self_skin_kept) { /* the clouds refine the interior only */
        const size_t len = strlen(over);
        snprintf(over + len, sizeof over - len, "; the file's skin on every cloud: the surface's "
                 "part of the error is not in this figure");
    }
    if (d->self_shifted) { /* the scene's cloud is the coarsest of the three */
        snprintf(buf, n,
                 "self-measured: Richardson extrapolation over clouds of spacing %.4g (this "
                 "one), %.4g, %.4g mm (%zu, %zu, %zu nodes; the coarser cloud: %s), "
                 "%s, at %zu points, %s; this cloud's pair gives %.3g mm",
                 d->self_h[0], d->self_h[1], d->self_h[2], d->self_nodes[0], d->self_nodes[1],
                 d->self_nodes[2], d->self_shifted_why, order, d->points, over, d->self_other_mm);
        return;
    }
    snprintf(buf, n,
             "self-measured: Richardson extrapolation over clouds of spacing %.4g, %.4g (this "
             "one), %.4g mm (%zu, %zu, %zu nodes), %s, at %zu points, %s; the coarser pair "
             "gives %.3g mm",
             d->self_h[0], d->self_h[1], d->self_h[2], d->self_nodes[0], d->self_nodes[1],
             d->self_nodes[2], order, d->points, over, d->self_other_mm);
}

void tf_fit_physics_state(const tf_discretisation *d, const tf_envelope *env, tf_model *fwd,
                          tf_model *con)
{
    const double *c = env->centre, biggest = env->radius + hypot(hypot(c[0], c[1]), c[2]);
    fwd->discretisation_max = d->max_mm;
    con->discretisation_max = d->site_rel * biggest;
    char reach[128] = "";
    if (!d->enveloped) { /* a nonlinear solve: only where the reference's cases reach */
        snprintf(reach, sizeof reach, " (forces up to %.3g %% of the envelope's radius %.3g N; "
                 "not measured beyond)", 100 * d->reach, env->radius);
    }
    if (d->self) {
        self_note(d, fwd->discretisation_note, sizeof fwd->discretisation_note);
    } else {
        snprintf(fwd->discretisation_note, sizeof fwd->discretisation_note,
                 "%s, %zu load case%s at %zu points, %s%s", d->source, d->cases,
                 d->cases == 1 ? "" : "s", d->points,
                 d->enveloped ? "bound over the envelope (linear)" : "largest over the cases",
                 reach);
    }
    if (d->self) {
        snprintf(con->discretisation_note, sizeof con->discretisation_note,
                 "self-measured: contact-site displacement off by %.3g %% (the extrapolation "
                 "of the forward model's), times the largest force %.3g N",
                 100 * d->site_rel, biggest);
    } else {
        snprintf(con->discretisation_note, sizeof con->discretisation_note,
                 "%s: contact-site displacement off by %.3g %% (reference point %.3g mm from "
                 "the site), times the largest force %.3g N",
                 d->source, 100 * d->site_rel, d->site_gap, biggest);
    }
}

int tf_fit_physics_assume(tf_ctx *ctx, const double rel[2], const tf_envelope *env, tf_model *fwd,
                          tf_model *con)
{
    const double *c = env->centre, biggest = env->radius + hypot(hypot(c[0], c[1]), c[2]);
    if (!(fwd->heldout_rel_max > 0) || !(fwd->heldout_max > 0)) {
        tf_error(ctx, "fit: --discretisation-rel: the forward model states no peak displacement "
                 "(only the prony family's held-out histories do)");
        return -1;
    }
    const double peak = fwd->heldout_max / fwd->heldout_rel_max;
    fwd->discretisation_max = rel[0] * peak;
    con->discretisation_max = rel[1] * biggest;
    snprintf(fwd->discretisation_note, sizeof fwd->discretisation_note,
             "assumed, not measured for this law: %.3g %% (another measurement's, "
             "--discretisation-rel) of the held-out peak displacement %.4g mm",
             100 * rel[0], peak);
    snprintf(con->discretisation_note, sizeof con->discretisation_note,
             "assumed, not measured for this law: contact-site displacement off by %.3g %% "
             "(--discretisation-rel), times the largest force %.3g N",
             100 * rel[1], biggest);
    return 0;
}

void tf_fit_physics_at_centre(tf_model *surface, tf_model *law)
{
    tf_model *m[2] = {surface, law};
    for (int k = 0; k < 2; ++k) {
        const size_t n = strlen(m[k]->discretisation_note);
        snprintf(m[k]->discretisation_note + n, sizeof m[k]->discretisation_note - n,
                 "; at one site of the region, its centre, under the probe's patch");
    }
}

void tf_fit_physics_unmeasured(const char *why, int hint, tf_model *fwd, tf_model *con)
{
    tf_model *m[2] = {fwd, con};
    for (int k = 0; k < 2; ++k) {
        snprintf(m[k]->discretisation_note, sizeof m[k]->discretisation_note, "not measured (%s%s)",
                 why, hint ? "; tissuefit fit --reference gives a finer solution" : "");
    }
}
