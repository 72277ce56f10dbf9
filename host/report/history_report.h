/*
 * history_report.h — the held-out force histories of a stateful forward
 * model (prony, resonant) in a fit's report: per history its peak
 * displacement and the float32 model's largest error there, and a plot of
 * one history (the solve and the model at the output point and component
 * with the largest displacement, the force beneath).
 */
#ifndef TF_HISTORY_REPORT_H
#define TF_HISTORY_REPORT_H

#include <stdio.h>

#include "base/context.h"
#include "fitting/histories.h"
#include "model/model.h"

/* The Markdown section (a table, and the plot's link under name) into f,
 * and the plot at png_path; kinds: the dynamic design's held-out kinds are
 * named (strike, smooth random) when dynamic != 0.  Returns 0, or -1 with
 * a message (no memory, gnuplot failed). */
int tf_report_histories(tf_ctx *ctx, FILE *f, const char *png_path, const char *png_name,
                        const tf_model *m, const tf_histories *h, int dynamic);

#endif /* TF_HISTORY_REPORT_H */
