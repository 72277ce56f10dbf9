/*
 * fit_report.c — the Markdown report of a fit with its PNG plots: every
 * family's cost and held-out error side by side, the cross-validation
 * curves, the modal error-versus-rank table, the seed's Table 3 view and
 * error maps over the output points (the seed's Figs 5-13).
 */
#include "report/fit_report.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/atomic_file.h"
#include "cost/cycles.h"
#include "base/plot.h"

static const char *const axis_name = "xyz";

/* Seed 000, Table 3: RMS error of node displacements, mm/N (force X, Y, Z
 * rows; displacement x, y, z columns). */
static const double seed_table3[3][3] = {{0.081713, 0.084872, 0.262261},
                                         {0.077761, 0.099467, 0.291453},
                                         {0.094042, 0.065811, 0.155073}};

static void stem(const char *header, char *out, size_t n)
{
    const char *slash = strrchr(header, '/');
    snprintf(out, n, "%s", slash ? slash + 1 : header);
    out[strcspn(out, ".")] = '\0';
}

static void orders(const tf_model *m, char *buf, size_t n)
{
    if (m->family == TFIT_FAMILY_MODAL) {
        snprintf(buf, n, "p=%u r=%u", m->dims[0], m->dims[1]);
    } else if (m->family == TFIT_FAMILY_ZHOU2017) {
        snprintf(buf, n, "λ=%u,%u,%u (surfaces below)", m->dims[0], m->dims[1], m->dims[2]);
    } else {
        snprintf(buf, n, "p=%u", m->dims[0]);
    }
}

static void cost_row(FILE *f, const tf_family_fit *ff, tfit_family fam, int emitted)
{
    char ord[128];
    const tf_model *m = ff->model;
    if (!ff->applicable) {
        fprintf(f, "| %s | not applicable: %s |||||||||\n", tf_family_name(fam), ff->why);
        return;
    }
    orders(m, ord, sizeof ord);
    tf_opcount ops = tf_model_ops(m);
    tf_cycles m4 = tf_cycles_estimate(m, TF_CORE_M4F), m7 = tf_cycles_estimate(m, TF_CORE_M7);
    const char *unit = fam == TFIT_FAMILY_CONTACT ? "N" : "mm";
    fprintf(f, "| %s%s | %s | %u | %llu | %u | %.1f–%.1f | %.2f | %.3g %s | %.3g %s | %.2f |\n",
            tf_family_name(fam), emitted ? " (emitted)" : "", ord, m->n_coef,
            (unsigned long long)(ops.add + ops.mul + ops.div), tf_model_table_bytes(m),
            m4.cycles_low / tf_core_mhz(TF_CORE_M4F), m4.cycles / tf_core_mhz(TF_CORE_M4F),
            m7.cycles / tf_core_mhz(TF_CORE_M7), ff->heldout_max, unit, ff->heldout_rms, unit,
            ff->seconds);
}

static void table3(FILE *f, const tf_family_fit *ff, const char *title)
{
    fprintf(f, "\n%s\n\n| force along | RMS x | RMS y | RMS z |\n|---|---|---|---|\n", title);
    for (int a = 0; a < 3; ++a) {
        fprintf(f, "| %c | %.3g | %.3g | %.3g |\n", "XYZ"[a], ff->table3[a][0], ff->table3[a][1],
                ff->table3[a][2]);
    }
}

static void data_block(FILE *gp, const char *name, const double *x, const double *y, int n)
{
    fprintf(gp, "$%s << EOD\n", name);
    for (int i = 0; i < n; ++i) {
        if (isfinite(y[i])) {
            fprintf(gp, "%g %.6g\n", x[i], y[i]);
        }
    }
    fprintf(gp, "EOD\n");
}

static int cv_plot(const char *path, const tf_fit_outcome *o, char *err, size_t errlen)
{
    tf_plot p;
    if (tf_plot_open(&p, path, 1000, 420, err, errlen) != 0) {
        return -1;
    }
    double deg[TFIT_MAX_DEGREE + 1], rank[TF_FIT_MAX_RANK + 1];
    for (int i = 0; i <= TFIT_MAX_DEGREE; ++i) {
        deg[i] = i;
    }
    for (int i = 0; i <= TF_FIT_MAX_RANK; ++i) {
        rank[i] = i;
    }
    data_block(p.gp, "nodal", deg, o->fam[TFIT_FAMILY_NODAL].cv, TFIT_MAX_DEGREE + 1);
    data_block(p.gp, "modal", deg, o->fam[TFIT_FAMILY_MODAL].cv, TFIT_MAX_DEGREE + 1);
    data_block(p.gp, "contact", deg, o->fam[TFIT_FAMILY_CONTACT].cv, TFIT_MAX_DEGREE + 1);
    data_block(p.gp, "rank", rank, o->fam[TFIT_FAMILY_MODAL].cv_rank, TF_FIT_MAX_RANK + 1);
    data_block(p.gp, "heldout", rank, o->rank_max, TF_FIT_MAX_RANK + 1);
    fprintf(p.gp,
            "set multiplot layout 1,2\n"
            "set logscale y\nset format y '%%.0e'\nset xtics 1\nset grid\nset key top right\n"
            "set title 'cross-validated RMS error by polynomial degree'\n"
            "set xlabel 'total degree p'\nset ylabel 'CV RMS error (mm; contact: N)'\n"
            "plot $nodal w lp pt 7 t 'nodal', $modal w lp pt 5 t 'modal (largest rank)', "
            "$contact w lp pt 9 t 'contact inverse (N)'\n"
            "set title 'modal family by rank'\nset xlabel 'rank r'\nset ylabel 'error (mm)'\n"
            "set xtics 2\n"
            "plot $rank w lp pt 7 t 'CV RMS', $heldout w lp pt 5 t 'held-out max', "
            "0.010 w l dt 2 t '10 um'\n"
            "unset multiplot\n");
    return tf_plot_close(&p, err, errlen);
}

/* 3 x 3 panels: mean deviation (model - solve) of each component under a
 * force along each axis, over the output points seen from above. */
static int error_map(const char *path, const tf_fitdata *d, const tf_family_fit *ff,
                     const char *family, char *err, size_t errlen)
{
    tf_plot p;
    if (tf_plot_open(&p, path, 1200, 1100, err, errlen) != 0) {
        return -1;
    }
    fprintf(p.gp, "set multiplot layout 3,3 title '%s: mean deviation from the solve (mm), "
                  "forces 0.2..1.0 of the envelope along each axis'\n"
                  "set size ratio -1\nset palette defined (-1 'blue', 0 'white', 1 'red')\n"
                  "unset key\nset xlabel 'x (mm)'\nset ylabel 'y (mm)'\n",
            family);
    for (int a = 0; a < 3; ++a) {
        for (int c = 0; c < 3; ++c) {
            const double *dev = ff->deviation + ((size_t)a * 3 + (size_t)c) * d->n_out;
            double big = 1e-30;
            for (uint32_t j = 0; j < d->n_out; ++j) {
                big = fmax(big, fabs(dev[j]));
            }
            fprintf(p.gp, "set title 'force %c, u%c'\nset cbrange [%g:%g]\n", "XYZ"[a],
                    axis_name[c], -big, big);
            fprintf(p.gp, "plot '-' using 1:2:3 with points pt 5 ps 2.2 lc palette\n");
            for (uint32_t j = 0; j < d->n_out; ++j) {
                fprintf(p.gp, "%g %g %.6g\n", d->rest[j][0], d->rest[j][1], dev[j]);
            }
            fprintf(p.gp, "e\n");
        }
    }
    fprintf(p.gp, "unset multiplot\n");
    return tf_plot_close(&p, err, errlen);
}

static void zhou_orders(FILE *f, const tf_family_fit *z)
{
    fprintf(f, "\nzhou2017 orders chosen by cross-validation: contact laws λ = %u, %u, %u; "
               "surfaces (x order A, y order B, β order k) per force axis and component:\n\n"
               "| force | ux | uy | uz |\n|---|---|---|---|\n",
            z->zhou.lambda[0], z->zhou.lambda[1], z->zhou.lambda[2]);
    for (int a = 0; a < 3; ++a) {
        fprintf(f, "| %c |", "XYZ"[a]);
        for (int c = 0; c < 3; ++c) {
            int pair = 3 * a + c;
            fprintf(f, " A=%u B=%u k=%u |", z->zhou.a[pair], z->zhou.b[pair], z->zhou.k[pair]);
        }
        fprintf(f, "\n");
    }
}

static void write_md(FILE *f, const char *name, const char *header, const tf_problem *s,
                     const tf_solver *solver, const tf_fit_plan *plan, const tf_fit_outcome *o)
{
    const tf_solver_info *si = tf_solver_info_of(solver);
    fprintf(f, "# Fit report: %s\n\nGenerated by `tissuefit fit` for `%s` (scene `%s`).\n\n",
            name, header, s->source);
    fprintf(f,
            "Solver: %zu nodes, %zu DOFs; assembly and factorisation %.2f s; %zu right-hand "
            "sides solved.  Load cases at contact site `%s` (node %u): %zu training (%s), %zu "
            "held-out (solved directly, never fitted), forces uniform in the envelope |F - c| "
            "<= %g N.  Orders by %u-fold cross-validation.\n\n",
            si->nodes, si->dofs, si->t_setup,
            o->cases.solves, s->contacts[plan->contact].name,
            s->contacts[plan->contact].node + 1, plan->n_train,
            o->cases.superposed ? "superposed from unit solves" : "solved directly",
            plan->n_heldout, s->envelope.radius, plan->folds);
    fprintf(f, "## Models\n\nHeld-out errors are those of the float32 firmware (the host's "
               "reference evaluator reproduces its bits) against the double-precision solve. "
               "Times are the Cortex-M4F estimate (lower–upper bound) at 168 MHz and the "
               "Cortex-M7 estimate at 480 MHz (docs/firmware.md).\n\n"
               "| family | orders | coefficients | ops | table bytes | M4F µs | M7 µs | held-out "
               "max | held-out RMS | fit s |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (int fam = 1; fam <= 4; ++fam) {
        cost_row(f, &o->fam[fam], (tfit_family)fam, fam == (int)plan->family);
    }
    if (o->fam[TFIT_FAMILY_CONTACT].applicable) {
        fprintf(f, "\nContact inverse: held-out relative force error max %.3g.\n",
                o->fam[TFIT_FAMILY_CONTACT].heldout_rel_max);
    }
    fprintf(f, "\n## Cross-validation\n\n![cross-validation](%s_cv.png)\n\n"
               "| degree p | nodal CV RMS (mm) | modal CV RMS (mm) | contact CV RMS (N) |\n"
               "|---|---|---|---|\n",
            name);
    for (int p = 0; p <= (int)plan->max_degree; ++p) {
        fprintf(f, "| %d | %.3g | %.3g | %.3g |\n", p, o->fam[TFIT_FAMILY_NODAL].cv[p],
                o->fam[TFIT_FAMILY_MODAL].cv[p], o->fam[TFIT_FAMILY_CONTACT].cv[p]);
    }
    fprintf(f, "\n## Modal family: error against rank\n\n| rank r | CV RMS (mm) | held-out max "
               "(mm) |\n|---|---|---|\n");
    for (uint32_t r = 1; r <= plan->max_rank && r <= TF_FIT_MAX_RANK; ++r) {
        fprintf(f, "| %u | %.3g | %.3g |\n", r, o->fam[TFIT_FAMILY_MODAL].cv_rank[r],
                o->rank_max[r]);
    }
    if (o->rank_10um > 0) {
        fprintf(f, "\nSmallest rank within 10 µm (held-out max): **r = %u**.\n", o->rank_10um);
    } else {
        fprintf(f, "\nNo rank up to %u is within 10 µm.\n", plan->max_rank);
    }
    fprintf(f, "\n## The seed's Table 3 view\n\nRMS error of the output displacements under "
               "forces of 0.2, 0.4, ... 1.0 × the envelope radius along each axis, divided by "
               "the force (mm/N), as seed 000 Table 3 reports it.\n");
    table3(f, &o->fam[TFIT_FAMILY_NODAL], "**nodal**");
    table3(f, &o->fam[TFIT_FAMILY_MODAL], "**modal**");
    if (o->fam[TFIT_FAMILY_ZHOU2017].applicable) {
        table3(f, &o->fam[TFIT_FAMILY_ZHOU2017], "**zhou2017** (this tool, the seed's method)");
        zhou_orders(f, &o->fam[TFIT_FAMILY_ZHOU2017]);
    }
    fprintf(f, "\n**Seed 000, Table 3** (its own RPIM solution, point load, raw-mm basis):\n\n"
               "| force along | RMS x | RMS y | RMS z |\n|---|---|---|---|\n");
    for (int a = 0; a < 3; ++a) {
        fprintf(f, "| %c | %.3g | %.3g | %.3g |\n", "XYZ"[a], seed_table3[a][0], seed_table3[a][1],
                seed_table3[a][2]);
    }
    fprintf(f, "\n## Error maps\n\nMean deviation of each family from the solve over the output "
               "points (the seed's Figs 5–13), per force axis and displacement component.\n\n");
    for (int fam = 1; fam <= 3; ++fam) {
        if (o->fam[fam].applicable) {
            fprintf(f, "![%s](%s_errors_%s.png)\n\n", tf_family_name((tfit_family)fam), name,
                    tf_family_name((tfit_family)fam));
        }
    }
}

int tf_fit_report(const char *dir, const char *header, const tf_problem *s,
                  const tf_solver *solver, const tf_fit_plan *plan, const tf_fit_outcome *o,
                  char *err, size_t errlen)
{
    char name[256], path[4096];
    stem(header, name, sizeof name);
    snprintf(path, sizeof path, "%s/%s_cv.png", dir, name);
    if (cv_plot(path, o, err, errlen) != 0) {
        return -1;
    }
    for (int fam = 1; fam <= 3; ++fam) {
        if (!o->fam[fam].applicable) {
            continue;
        }
        snprintf(path, sizeof path, "%s/%s_errors_%s.png", dir, name,
                 tf_family_name((tfit_family)fam));
        if (error_map(path, &o->cases.train, &o->fam[fam], tf_family_name((tfit_family)fam), err,
                      errlen) != 0) {
            return -1;
        }
    }
    tf_afile md;
    snprintf(path, sizeof path, "%s/%s.md", dir, name);
    if (tf_afile_open(&md, path, err, errlen) != 0) {
        return -1;
    }
    write_md(md.fp, name, header, s, solver, plan, o);
    return tf_afile_commit(&md, err, errlen);
}
