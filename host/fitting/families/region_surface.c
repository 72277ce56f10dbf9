/*
 * region_surface.c — the region_surface family (TFIT_FAMILY_REGION_SURFACE):
 * the outputs' displacements for the current contact on a contact region
 * (docs/header-format.md §5.11), p = 1 with site modes (the two-instrument
 * form, §5.12), fitted with the region's law (region.c, region_family.h).
 * The forward family `tissuefit fit` emits for a region.
 */
#include <stdio.h>

#include "fitting/families/common.h"
#include "fitting/families/region_family.h"

/* "p=1 r=12 sites=17x17 site-modes near=9". */
static void orders_text(const tf_model *m, int style, char *buf, size_t n)
{
    (void)style;
    char near[24] = "";
    if (m->n_dims > 5 && m->dims[5] != 0) {
        snprintf(near, sizeof near, " near=%u", m->dims[5]);
    }
    snprintf(buf, n, "p=%u r=%u sites=%ux%u%s%s", m->dims[3], m->dims[2], m->dims[0], m->dims[1],
             m->dims[4] ? " site-modes" : "", near);
}

const tf_family tf_family_region_surface = {
    .id = TFIT_FAMILY_REGION_SURFACE,
    .name = "region_surface",
    .kind = TF_FAMILY_FORWARD,
    .applicable = tf_family_region_applicable,
    .select = tf_family_region_select,
    .fit = tf_family_region_fit_cases,
    .candidates = tf_family_region_candidates,
    .orders_text = orders_text,
    .q31 = NULL,
    .f64_errors = NULL,
    .cost = tf_family_layout_cost,
    .suffix = "surface",
    .region = tf_family_region_models,
};
