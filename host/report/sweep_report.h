/*
 * sweep_report.h — a sweep (tradeoff/sweep.h) written out: CSV, a Markdown
 * table and a log-log PNG of held-out error against native time, with the
 * seed's own point.
 */
#ifndef TF_SWEEP_REPORT_H
#define TF_SWEEP_REPORT_H

#include <stddef.h>
#include <stdio.h>

#include "base/context.h"
#include "problem/problem.h"
#include "tradeoff/sweep.h"

/* Each returns 0, or -1 with a message. */
int tf_report_sweep_csv(tf_ctx *ctx, const tf_sweep *sw, const char *path);
/* The same table written to an open stream (standard output, which is not
 * replaced by a renamed file); 0, or -1 when a write failed. */
int tf_report_sweep_csv_write(const tf_sweep *sw, FILE *fp);
int tf_report_sweep_markdown(tf_ctx *ctx, const tf_sweep *sw, const tf_problem *p,
                             const char *path);
int tf_report_sweep_plot(tf_ctx *ctx, const tf_sweep *sw, const char *path);

#endif /* TF_SWEEP_REPORT_H */
