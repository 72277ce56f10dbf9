/*
 * region_family.h — what the two families of a contact region share
 * (region.c: the law, region_surface.c: the surface for the current
 * contact).  Both are fitted together from the region's site solves
 * (fitting/region_models.h), never from one contact site's load cases:
 * their case operations refuse, and their `region` operation fits both.
 */
#ifndef TF_REGION_FAMILY_H
#define TF_REGION_FAMILY_H

#include "fitting/families/family.h"

/* applicable and select: -1, "fitted from a contact region". */
int tf_family_region_applicable(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan);
int tf_family_region_select(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan,
                            tf_family_result *r);
/* fit: NULL, the same message; candidates: -1, the same. */
tf_model *tf_family_region_fit_cases(tf_ctx *ctx, const tf_cases *c, const size_t *idx, size_t m,
                                     const uint32_t *orders);
int tf_family_region_candidates(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan,
                                tf_family_take take, void *arg);
/* The region's models: the surface, then the law (tf_region_models). */
int tf_family_region_models(tf_ctx *ctx, tf_solver *s, const tf_problem *p,
                            const tf_fit_plan *plan, tf_model **models, size_t *n);

#endif /* TF_REGION_FAMILY_H */
