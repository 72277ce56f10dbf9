/*
 * fit_physics.h — what `tissuefit fit` states as the solve's error against
 * the physics: measured against a finer reference (--reference), assumed
 * from another measurement (--discretisation-rel), or measured by the tool
 * on a coarser and a finer cloud of the scene itself (the default,
 * fitting/discretisation_self.h); written into the models' fields that the
 * header and the report print.
 */
#ifndef TF_FIT_PHYSICS_H
#define TF_FIT_PHYSICS_H

#include "base/context.h"
#include "cli/cmd_args.h"
#include "fitting/discretisation.h"
#include "model/model.h"
#include "solvers/solver.h"

/* The self-measurement of the scene file at path (overrides sets) solved by
 * s.  Returns 0; 1 when it could not be measured, the reason in ctx->err. */
int tf_fit_physics_self(tf_ctx *ctx, const char *path, const tf_sets *sets, tf_solver *s,
                        const tf_problem *p, int contact, tf_discretisation *out);

/* A measurement d (a reference's or the tool's own) into the forward model's
 * displacement bound and the contact inverse's force bound (the contact
 * site's relative error times the envelope's largest force). */
void tf_fit_physics_state(const tf_discretisation *d, const tf_envelope *env, tf_model *fwd,
                          tf_model *con);

/* --discretisation-rel: the relative figures rel (forward, contact site)
 * of another measurement.  Returns 0, or -1 with a message when the forward
 * model states no peak displacement. */
int tf_fit_physics_assume(tf_ctx *ctx, const double rel[2], const tf_envelope *env, tf_model *fwd,
                          tf_model *con);

/* A contact region's models measured at the probe's patch at the region's
 * centre (the site its contact entry carries): their notes say so. */
void tf_fit_physics_at_centre(tf_model *surface, tf_model *law);

/* Not measured, and why (the header and report say so); hint: add that
 * --reference gives a finer solution (a contact region takes none yet). */
void tf_fit_physics_unmeasured(const char *why, int hint, tf_model *fwd, tf_model *con);

#endif /* TF_FIT_PHYSICS_H */
