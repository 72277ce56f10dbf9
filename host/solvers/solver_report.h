/*
 * solver_report.h — what a solver run says on stderr: the time split and
 * memory (progress, silenced by -q) and conditioning warnings (always).
 */
#ifndef TF_SOLVER_REPORT_H
#define TF_SOLVER_REPORT_H

#include "solvers/solver.h"

/* Time split (tf_info) and, when local systems were ill-conditioned, a
 * warning naming how many, the worst place and what to change. */
void tf_solver_report(const tf_solver *s, const tf_scene *scene);

/* Peak resident memory of this process, MiB. */
double tf_peak_mib(void);

#endif /* TF_SOLVER_REPORT_H */
