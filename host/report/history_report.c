/*
 * history_report.c — see history_report.h.
 */
#include "report/history_report.h"

#include <math.h>
#include <stdlib.h>

#include "base/plot.h"
#include "model/forms/stateful.h"

/* The model stepped through held-out history i from rest: outputs of every
 * tick into out (n_ticks x 3 n_out floats). */
static void step_through(const tf_model *m, const tf_history_set *s, size_t i, float *out)
{
    float state[TF_STATEFUL_MAX_STATE];
    const size_t rows = 3 * (size_t)m->n_out;
    tf_stateful_reset(m, state);
    for (size_t n = 0; n < s->n_ticks; ++n) {
        const double *f = tf_history_force(s, i, n);
        const float in[3] = {(float)f[0], (float)f[1], (float)f[2]};
        (void)tf_stateful_step(m, state, in, out + n * rows, NULL);
    }
}

static int plot_history(tf_ctx *ctx, const char *path, const tf_model *m, const tf_histories *h,
                        size_t i, const float *out, size_t row)
{
    const tf_history_set *s = &h->heldout;
    const size_t rows = 3 * (size_t)m->n_out;
    tf_plot p;
    if (tf_plot_open(ctx, &p, path, 1000, 560) != 0) {
        return -1;
    }
    fprintf(p.gp, "$u << EOD\n");
    for (size_t n = 0; n < s->n_ticks; ++n) {
        const double *f = tf_history_force(s, i, n);
        fprintf(p.gp, "%g %.6g %.6g %.6g %.6g %.6g\n", 1e3 * (double)(n + 1) * h->tick,
                tf_history_u(s, i, n)[row], (double)out[n * rows + row], f[0], f[1], f[2]);
    }
    fprintf(p.gp, "EOD\n");
    fprintf(p.gp,
            "set multiplot layout 2,1\nset grid\nset key top right\n"
            "set title 'held-out history %zu: node %u, %c displacement'\n"
            "set ylabel 'displacement (mm)'\nset format x ''\n"
            "plot $u u 1:2 w l lw 2 t 'solve', $u u 1:3 w l dt 2 lw 2 t 'model (float32)'\n"
            "set title 'force'\nset format x '%%g'\nset xlabel 'time (ms)'\n"
            "set ylabel 'force (N)'\n"
            "plot $u u 1:4 w l t 'x', $u u 1:5 w l t 'y', $u u 1:6 w l t 'z'\n"
            "unset multiplot\n",
            i, m->node_ids[row / 3], "xyz"[row % 3]);
    return tf_plot_close(ctx, &p);
}

int tf_report_histories(tf_ctx *ctx, FILE *f, const char *png_path, const char *png_name,
                        const tf_model *m, const tf_histories *h, int dynamic)
{
    const tf_history_set *s = &h->heldout;
    const size_t rows = 3 * (size_t)m->n_out;
    float *out = malloc(s->n_ticks * rows * sizeof *out);
    if (out == NULL) {
        return tf_fail(ctx, "report: out of memory for a history");
    }
    fprintf(f, "\n## Held-out force histories\n\nThe float32 model stepped from rest through "
               "each held-out history (never fitted) at its %u ns tick, against the solve: the "
               "largest error over every output and tick, and the peak displacement.\n\n"
               "| history | kind | peak displacement (mm) | largest error (mm) | of the peak |\n"
               "|---|---|---|---|---|\n",
            h->tick_ns);
    size_t show = 0, show_row = 0;
    double show_peak = -1;
    for (size_t i = 0; i < s->n; ++i) {
        step_through(m, s, i, out);
        double peak = 0, worst = 0, row_peak = 0;
        size_t row = 0;
        for (size_t n = 0; n < s->n_ticks; ++n) {
            const double *u = tf_history_u(s, i, n);
            for (size_t o = 0; o < rows; ++o) {
                worst = fmax(worst, fabs((double)out[n * rows + o] - u[o]));
                if (fabs(u[o]) > row_peak) {
                    row_peak = fabs(u[o]);
                    row = o;
                }
            }
        }
        peak = row_peak;
        const char *kind = dynamic ? (i % 2 == 0 ? "strike" : "smooth random")
                                   : "press-hold-release";
        fprintf(f, "| %zu | %s | %.4g | %.3g | %.2f %% |\n", i, kind, peak, worst,
                100 * worst / peak);
        if (i == 0 || (dynamic && i % 2 == 0 && peak > show_peak)) {
            show = i;
            show_row = row;
            show_peak = peak;
        }
    }
    step_through(m, s, show, out);
    const int rc = plot_history(ctx, png_path, m, h, show, out, show_row);
    free(out);
    if (rc == 0) {
        fprintf(f, "\n![held-out history %zu](%s)\n", show, png_name);
    }
    return rc;
}
