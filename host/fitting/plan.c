/*
 * plan.c — the default fit plan (plan.h).
 */
#include "fitting/plan.h"

#include "fitting/families/family.h"

void tf_fit_plan_defaults(tf_fit_plan *p)
{
    *p = (tf_fit_plan){.family = tf_family_find("nodal"), .contact = 0, .n_train = 100,
                       .n_heldout = 50, .seed = 20170912, .folds = 5, .max_degree = 4,
                       .max_rank = 12, .tick_ns = 1000000, .hist_train = 12,
                       .hist_heldout = 6, .hist_ticks = 5000,
                       .cut_intervals = 0, .cut_heldout = 4};
}
