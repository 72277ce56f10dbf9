/*
 * history_run.c — see history_run.h.
 */
#include "solvers/history_run.h"

#include "base/clock.h"
#include "base/log.h"
#include "solvers/nonlinear/nonlinear.h"

int tf_history_run(tf_ctx *ctx, tf_solver *sv, int contact, const tf_samples *smp, double *u)
{
    const size_t n3 = 3 * tf_solver_node_count(sv);
    tf_nonlinear_info info;
    const int nonlinear = tf_nonlinear_info_of(sv, &info) == 0;
    double t0 = tf_seconds(), shown = t0, prev = 0;
    int rc = nonlinear ? tf_nonlinear_reset(sv) : 0;
    for (size_t k = 0; k < smp->n && rc == 0; ++k) {
        double *uk = u + n3 * k;
        if (nonlinear) {
            rc = tf_nonlinear_advance(sv, smp->scale[k], contact, smp->force[k], smp->t[k] - prev);
            rc = rc == 0 ? tf_nonlinear_displacements(sv, uk) : rc;
        } else {
            rc = tf_solver_solve(sv, contact, (const double(*)[3])smp->force[k], 1, NULL, uk);
        }
        prev = smp->t[k];
        const double now = tf_seconds();
        if (rc == 0 && now - shown > 1) {
            tf_info(ctx, "solve: step %zu of %zu, t = %g s (%.0f s so far)", k + 1, smp->n,
                    smp->t[k], now - t0);
            shown = now;
        }
    }
    return rc == 0 ? 0 : -1;
}
