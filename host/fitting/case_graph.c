/*
 * case_graph.c — the anchored continuation graph (case_graph.h).
 */
#include "fitting/case_graph.h"

static double dist2(const double a[3], const double b[3])
{
    double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
    return d0 * d0 + d1 * d1 + d2 * d2;
}

size_t tf_case_graph_anchors(size_t n)
{
    size_t a = 0;
    while (a * a < n) {
        ++a;
    }
    return a;
}

void tf_case_graph_anchored(const double (*forces)[3], size_t n, size_t n_anchor, long *from)
{
    static const double rest[3] = {0, 0, 0};
    for (size_t i = 0; i < n; ++i) {
        from[i] = -1;
        if (i < n_anchor) {
            continue;
        }
        double best = dist2(forces[i], rest);
        for (size_t a = 0; a < n_anchor; ++a) {
            double d = dist2(forces[i], forces[a]);
            if (d < best) {
                best = d;
                from[i] = (long)a;
            }
        }
    }
}
