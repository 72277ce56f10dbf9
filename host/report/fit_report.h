/*
 * fit_report.h — a fit's report: DIR/NAME.md with PNG plots (gnuplot),
 * docs-style Markdown that can be committed beside the header.
 */
#ifndef TF_FIT_REPORT_H
#define TF_FIT_REPORT_H

#include <stddef.h>

#include "base/context.h"
#include "fitting/pipeline.h"

/* header: the header path (its stem names the files).  Returns 0, or -1
 * with a message. */
int tf_report_fit(tf_ctx *ctx, const char *dir, const char *header, const tf_problem *p,
                  const tf_solver *solver, const tf_fit_plan *plan, const tf_fit_outcome *out);

#endif /* TF_FIT_REPORT_H */
