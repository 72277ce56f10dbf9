/*
 * solver_report.c — time split, memory and conditioning warnings
 * (solver_report.h).
 */
#include "solvers/solver_report.h"

#include <math.h>
#include <stdio.h>
#include <sys/resource.h>

#include "base/log.h"

double tf_peak_mib(void)
{
    struct rusage ru;
    if (getrusage(RUSAGE_SELF, &ru) != 0) {
        return 0;
    }
    return (double)ru.ru_maxrss / 1024.0; /* Linux: kilobytes */
}

void tf_solver_report(const tf_solver *s, const tf_scene *scene)
{
    const tf_solver_info *in = tf_solver_info_of(s);
    tf_info("solver: times (s): pattern %.3f, shape functions %.3f, assembly %.3f, loads %.3f, "
            "factorisation %.3f, solves %.3f (%zu right-hand sides); peak memory %.0f MiB",
            in->t_pattern, in->t_shape, in->t_assemble, in->t_loads, in->t_factor, in->t_solve,
            in->solves, tf_peak_mib());
    tf_info("solver: %zu local systems of %zu to %zu nodes, smallest reciprocal condition %.2g",
            in->st.systems, in->st.min_nodes, in->st.max_nodes, in->st.min_rcond);
    if (in->st.ill > 0) {
        fprintf(stderr,
                "tissuefit: warning: %s: %zu of %zu local RPIM systems are ill-conditioned "
                "(reciprocal condition below %.2g; worst %.2g near (%g, %g, %g) mm); the shape "
                "functions lose about %.0f digits: lower solver.rbf.d_c or solver.support\n",
                scene->source, in->st.ill, in->st.systems, scene->solver.rcond_warn,
                in->st.min_rcond, in->st.worst_at[0], in->st.worst_at[1], in->st.worst_at[2],
                in->st.min_rcond > 0 ? -log10(in->st.min_rcond) : 16.0);
    }
}
