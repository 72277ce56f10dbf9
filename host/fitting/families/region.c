/*
 * region.c — the region family (TFIT_FAMILY_REGION): the contact law over a
 * contact region (docs/header-format.md §5.10), fitted with the region's
 * surface from the site solves (fitting/region_models.h), and what the two
 * region families share (region_family.h).
 */
#include <stdio.h>

#include "fitting/families/common.h"
#include "fitting/families/region_family.h"
#include "fitting/region_models.h"

static int from_region(tf_ctx *ctx)
{
    return tf_fail(ctx, "fitted from a contact region (contact.K.region) with its site solves, "
                        "not from one contact site's load cases");
}

int tf_family_region_applicable(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan)
{
    (void)c;
    (void)plan;
    return from_region(ctx);
}

int tf_family_region_select(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan,
                            tf_family_result *r)
{
    (void)c;
    (void)plan;
    (void)r;
    return from_region(ctx);
}

tf_model *tf_family_region_fit_cases(tf_ctx *ctx, const tf_cases *c, const size_t *idx, size_t m,
                                     const uint32_t *orders)
{
    (void)c;
    (void)idx;
    (void)m;
    (void)orders;
    from_region(ctx);
    return NULL;
}

int tf_family_region_candidates(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan,
                                tf_family_take take, void *arg)
{
    (void)c;
    (void)plan;
    (void)take;
    (void)arg;
    return from_region(ctx);
}

int tf_family_region_models(tf_ctx *ctx, tf_solver *s, const tf_problem *p,
                            const tf_fit_plan *plan, tf_model **models, size_t *n)
{
    *n = 0;
    const int rc = tf_region_models(ctx, s, p, plan->contact, "region_law", "region_surface",
                                    &models[1], &models[0]);
    if (rc != 0) {
        return rc;
    }
    *n = 2;
    return 0;
}

/* "P=2 sites=17x17": the potential's degree and the grid. */
static void orders_text(const tf_model *m, int style, char *buf, size_t n)
{
    (void)style;
    snprintf(buf, n, "P=%u sites=%ux%u", m->dims[2], m->dims[0], m->dims[1]);
}

const tf_family tf_family_region = {
    .id = TFIT_FAMILY_REGION,
    .name = "region",
    .kind = TF_FAMILY_INVERSE,
    .applicable = tf_family_region_applicable,
    .select = tf_family_region_select,
    .fit = tf_family_region_fit_cases,
    .candidates = tf_family_region_candidates,
    .orders_text = orders_text,
    .q31 = NULL,
    .f64_errors = NULL,
    .cost = tf_family_layout_cost,
    .suffix = "law",
    .region = tf_family_region_models,
};
