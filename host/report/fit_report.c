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
#include "base/plot.h"
#include "cost/cycles.h"
#include "fitting/pipeline.h"
#include "model/forms/stateful.h"
#include "problem/datasheet.h"
#include "report/history_report.h"

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

static const char *unit_of(const tf_family *f)
{
    return f->kind == TF_FAMILY_INVERSE ? "N" : "mm";
}

static void cost_row(FILE *f, const tf_family_result *r, int emitted)
{
    char ord[128];
    const tf_model *m = r->model;
    const tf_family *fam = r->family;
    if (!r->applicable) {
        fprintf(f, "| %s | not applicable: %s |||||||||\n", fam->name, r->why);
        return;
    }
    fam->orders_text(m, TF_ORDERS_SHORT, ord, sizeof ord);
    tf_family_cost cost;
    fam->cost(m, &cost);
    const char *unit = unit_of(fam);
    fprintf(f, "| %s%s | %s | %u | %llu | %u | %.1f–%.1f | %.2f | %.3g %s | %.3g %s | %.2f |\n",
            fam->name, emitted ? " (emitted)" : "", ord, m->n_coef,
            (unsigned long long)(cost.ops.add + cost.ops.mul + cost.ops.div), cost.table_bytes,
            cost.m4f.cycles_low / tf_core_mhz(TF_CORE_M4F),
            cost.m4f.cycles / tf_core_mhz(TF_CORE_M4F), cost.m7.cycles / tf_core_mhz(TF_CORE_M7),
            r->heldout_max, unit, r->heldout_rms, unit, r->seconds);
}

/* Whether a curve has a value: the family searched it. */
static int searched(const double *v, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        if (isfinite(v[i])) {
            return 1;
        }
    }
    return 0;
}

static void table3(FILE *f, const tf_family_result *ff, const char *title)
{
    fprintf(f, "\n**%s**\n\n| force along | RMS x | RMS y | RMS z |\n|---|---|---|---|\n", title);
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

/* Left: the CV error by degree of every family that searched a degree;
 * right: the CV and held-out errors by rank of every family with a rank. */
static int cv_plot(tf_ctx *ctx, const char *path, const tf_fit_outcome *o)
{
    static const int point[] = {7, 5, 9, 11, 13};
    tf_plot p;
    if (tf_plot_open(ctx, &p, path, 1000, 420) != 0) {
        return -1;
    }
    double deg[TFIT_MAX_DEGREE + 1], rank[TF_FAMILY_MAX_RANK + 1];
    for (int i = 0; i <= TFIT_MAX_DEGREE; ++i) {
        deg[i] = i;
    }
    for (int i = 0; i <= TF_FAMILY_MAX_RANK; ++i) {
        rank[i] = i;
    }
    char name[64];
    for (size_t i = 0; i < o->n_families; ++i) {
        const tf_family_result *r = &o->fam[i];
        snprintf(name, sizeof name, "cv%zu", i);
        data_block(p.gp, name, deg, r->cv, TFIT_MAX_DEGREE + 1);
        snprintf(name, sizeof name, "rank%zu", i);
        data_block(p.gp, name, rank, r->cv_rank, TF_FAMILY_MAX_RANK + 1);
        snprintf(name, sizeof name, "heldout%zu", i);
        data_block(p.gp, name, rank, r->heldout_rank, TF_FAMILY_MAX_RANK + 1);
    }
    fprintf(p.gp, "set multiplot layout 1,2\n"
                  "set logscale y\nset format y '%%.0e'\nset xtics 1\nset grid\nset key top right\n"
                  "set title 'cross-validated RMS error by polynomial degree'\n"
                  "set xlabel 'total degree p'\nset ylabel 'CV RMS error (mm; contact: N)'\n"
                  "plot ");
    const char *sep = "";
    for (size_t i = 0; i < o->n_families; ++i) {
        const tf_family_result *r = &o->fam[i];
        if (searched(r->cv, TFIT_MAX_DEGREE + 1)) {
            fprintf(p.gp, "%s$cv%zu w lp pt %d t '%s (%s)'", sep, i, point[i % 5], r->family->name,
                    unit_of(r->family));
            sep = ", ";
        }
    }
    fprintf(p.gp,
            "%s\nset title 'error by rank'\nset xlabel 'rank r'\nset ylabel 'error (mm)'\n"
            "set xtics 2\nplot ",
            *sep ? "" : "NaN t ''");
    sep = "";
    for (size_t i = 0; i < o->n_families; ++i) {
        const tf_family_result *r = &o->fam[i];
        if (searched(r->cv_rank, TF_FAMILY_MAX_RANK + 1)) {
            fprintf(p.gp,
                    "%s$rank%zu w lp pt 7 t '%s CV RMS', $heldout%zu w lp pt 5 t '%s "
                    "held-out max'",
                    sep, i, r->family->name, i, r->family->name);
            sep = ", ";
        }
    }
    fprintf(p.gp, "%s0.010 w l dt 2 t '10 um'\nunset multiplot\n", sep);
    return tf_plot_close(ctx, &p);
}

/* 3 x 3 panels: mean deviation (model - solve) of each component under a
 * force along each axis, over the output points seen from above. */
static int error_map(tf_ctx *ctx, const char *path, const tf_fitdata *d, const tf_family_result *ff,
                     const char *family)
{
    tf_plot p;
    if (tf_plot_open(ctx, &p, path, 1200, 1100) != 0) {
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
    return tf_plot_close(ctx, &p);
}

/* The rank table of a family with a rank (modal). */
static void rank_table(FILE *f, const tf_family_result *r, const tf_fit_plan *plan)
{
    uint32_t within = 0;
    fprintf(f,
            "\n## Error against rank: %s\n\n| rank r | CV RMS (mm) | held-out max "
            "(mm) |\n|---|---|---|\n",
            r->family->name);
    for (uint32_t k = 1; k <= plan->max_rank && k <= TF_FAMILY_MAX_RANK; ++k) {
        fprintf(f, "| %u | %.3g | %.3g |\n", k, r->cv_rank[k], r->heldout_rank[k]);
    }
    for (uint32_t k = 1; k <= TF_FAMILY_MAX_RANK && within == 0; ++k) {
        within = r->heldout_rank[k] <= 0.010 ? k : 0;
    }
    if (within > 0) {
        fprintf(f, "\nSmallest rank within 10 µm (held-out max): **r = %u**.\n", within);
    } else {
        fprintf(f, "\nNo rank up to %u is within 10 µm.\n", plan->max_rank);
    }
}

/* The cut family (docs/cutting.md, "Cut progress"): its error by the
 * number of intervals K at the validation s values, then the emitted
 * model's at every solved s (training knots, validation, held-out) under
 * the held-out forces. */
static void cut_table(FILE *f, const tf_fit_outcome *o, const tf_family_result *r)
{
    static const char *const role[] = {"knot (trained)", "between knots (chose K)",
                                       "held out"};
    const tf_cut_cases *cc = &o->cut;
    fprintf(f, "\n## Error against cut progress: %s\n\nIntervals K in s (knots s = k/K), "
               "by the error at the s values between the finest knots, which no fit sees "
               "(training forces):\n\n| K | RMS (mm) | max (mm) |\n|---|---|---|\n",
            r->family->name);
    for (uint32_t k = 1; k <= cc->knots && k <= TF_FAMILY_MAX_RANK; k *= 2) {
        fprintf(f, "| %u | %.3g | %.3g |\n", k, r->cv_rank[k], r->heldout_rank[k]);
    }
    fprintf(f, "\nThe emitted model (K = %u) at every solved s, held-out forces (%zu):\n\n"
               "| s | role | max (mm) | RMS (mm) |\n|---|---|---|---|\n",
            r->model->dims[1], o->cases.heldout.n_cases);
    for (size_t i = 0; i < cc->n; ++i) {
        double max, sum2;
        if (tf_cut_cases_errors(r->model, cc, i, &o->cases.heldout, &max, &sum2) != 0) {
            return;
        }
        fprintf(f, "| %.4f | %s | %.3g | %.3g |\n", (double)cc->s[i], role[cc->role[i]], max,
                sqrt(sum2 / ((double)o->cases.heldout.n_cases * (double)cc->rows)));
    }
}

/* The CV table: one column per family that searched a degree. */
static void cv_table(FILE *f, const tf_fit_outcome *o, const tf_fit_plan *plan)
{
    fprintf(f, "| degree p |");
    for (size_t i = 0; i < o->n_families; ++i) {
        if (searched(o->fam[i].cv, TFIT_MAX_DEGREE + 1)) {
            fprintf(f, " %s CV RMS (%s) |", o->fam[i].family->name, unit_of(o->fam[i].family));
        }
    }
    fprintf(f, "\n|---|");
    for (size_t i = 0; i < o->n_families; ++i) {
        fprintf(f, "%s", searched(o->fam[i].cv, TFIT_MAX_DEGREE + 1) ? "---|" : "");
    }
    fprintf(f, "\n");
    for (int p = 0; p <= (int)plan->max_degree; ++p) {
        fprintf(f, "| %d |", p);
        for (size_t i = 0; i < o->n_families; ++i) {
            if (searched(o->fam[i].cv, TFIT_MAX_DEGREE + 1)) {
                fprintf(f, " %.3g |", o->fam[i].cv[p]);
            }
        }
        fprintf(f, "\n");
    }
}

/* The emitted models' error against the physics (tissuefit fit --reference),
 * as the header states it: fit + discretisation = total. */
static void physics_table(FILE *f, const tf_fit_outcome *o)
{
    int first = 1;
    for (size_t i = 0; i < o->n_families; ++i) {
        const tf_family_result *r = &o->fam[i];
        if (!r->applicable || r->model == NULL || isnan(r->model->discretisation_max)) {
            continue;
        }
        if (first) {
            fprintf(f, "\n## Error against the physics\n\nThe solve's own error against a finer "
                       "solution of the same physics, added to the fit's (docs/fitting.md).\n\n"
                       "| model | fit (held-out max) | discretisation | total | measured against |\n"
                       "|---|---|---|---|---|\n");
            first = 0;
        }
        const char *unit = unit_of(r->family);
        const tf_model *m = r->model;
        fprintf(f, "| %s | %.3g %s | %.3g %s | %.3g %s | %s |\n", r->family->name, m->heldout_max,
                unit, m->discretisation_max, unit, m->heldout_max + m->discretisation_max, unit,
                m->discretisation_note);
    }
}

/* The physics the models encode (the header's banner says the same), and
 * whether the displacements leave the range its law describes. */
static void physics_section(FILE *f, const tf_problem *s, const tf_fit_plan *plan,
                            const tf_fit_outcome *o)
{
    char sheet[2048], why[320];
    tf_problem_datasheet(s, (int)plan->contact, sheet, sizeof sheet);
    fprintf(f, "## Physics\n\n```\n%s\n```\n\n", sheet);
    double peak;
    if (o->cases.train.n_cases > 0 &&
        tf_fit_law_range(s, &o->cases.train, &peak, why, sizeof why) > 0) {
        fprintf(f, "**Warning (the law's range):** %s.\n\n", why);
    }
}

static void write_md(FILE *f, const char *name, const char *header, const tf_problem *s,
                     const tf_solver *solver, const tf_fit_plan *plan, const tf_fit_outcome *o)
{
    const tf_solver_info *si = tf_solver_info_of(solver);
    const tf_contact *ct = &s->contacts[plan->contact];
    /* a site given by position is named by it: its nearest node's number
     * means nothing to the reader (and differs from cloud to cloud) */
    char site[96];
    if (ct->by_node) {
        snprintf(site, sizeof site, "node %u", (unsigned)ct->node + 1);
    } else {
        snprintf(site, sizeof site, "at (%g, %g, %g) mm", ct->at[0], ct->at[1], ct->at[2]);
    }
    fprintf(f, "# Fit report: %s\n\nGenerated by `tissuefit fit` for `%s` (scene `%s`).\n\n",
            name, header, s->source);
    fprintf(f,
            "Solver: %zu nodes, %zu DOFs; assembly and factorisation %.2f s; %zu right-hand "
            "sides solved.  Load cases at contact site `%s` (%s): %zu training (%s), %zu "
            "held-out (solved directly, never fitted), forces uniform in the envelope |F - c| "
            "<= %g N.  Orders by %u-fold cross-validation.\n\n",
            si->nodes, si->dofs, si->t_setup,
            o->cases.solves, ct->name, site, plan->n_train,
            o->cases.superposed ? "superposed from unit solves" : "solved directly",
            plan->n_heldout, s->envelope.radius, plan->folds);
    physics_section(f, s, plan, o);
    fprintf(f, "## Models\n\nHeld-out errors are those of the float32 firmware (the host's "
               "reference evaluator reproduces its bits) against the double-precision solve. "
               "Times are the Cortex-M4F estimate (lower–upper bound) at 168 MHz and the "
               "Cortex-M7 estimate at 480 MHz (docs/firmware.md).\n\n"
               "| family | orders | coefficients | ops | table bytes | M4F µs | M7 µs | held-out "
               "max | held-out RMS | fit s |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (size_t i = 0; i < o->n_families; ++i) {
        cost_row(f, &o->fam[i], o->fam[i].family == plan->family);
    }
    for (size_t i = 0; i < o->n_families; ++i) {
        const tf_family_result *r = &o->fam[i];
        if (r->applicable && r->family->kind == TF_FAMILY_INVERSE) {
            fprintf(f, "\nInverse family %s: held-out relative force error max %.3g.\n",
                    r->family->name, r->heldout_rel_max);
        }
    }
    physics_table(f, o);
    fprintf(f, "\n## Cross-validation\n\n![cross-validation](%s_cv.png)\n\n", name);
    cv_table(f, o, plan);
    for (size_t i = 0; i < o->n_families; ++i) {
        if (o->fam[i].family->id == TFIT_FAMILY_CUT && o->fam[i].applicable && o->has_cut) {
            cut_table(f, o, &o->fam[i]);
        } else if (searched(o->fam[i].cv_rank, TF_FAMILY_MAX_RANK + 1)) {
            rank_table(f, &o->fam[i], plan);
        }
    }
    fprintf(f, "\n## The seed's Table 3 view\n\nRMS error of the output displacements under "
               "forces of 0.2, 0.4, ... 1.0 × the envelope radius along each axis, divided by "
               "the force (mm/N), as [Zhou2017] Table 3 reports it.\n");
    for (size_t i = 0; i < o->n_families; ++i) {
        const tf_family_result *r = &o->fam[i];
        if (r->applicable && r->family->kind == TF_FAMILY_FORWARD) {
            char ord[512];
            r->family->orders_text(r->model, TF_ORDERS_FULL, ord, sizeof ord);
            table3(f, r, r->family->name);
            fprintf(f, "\nOrders: `%s`.\n", ord);
        }
    }
    fprintf(f, "\n**[Zhou2017], Table 3** (its own RPIM solution, point load, raw-mm basis):\n\n"
               "| force along | RMS x | RMS y | RMS z |\n|---|---|---|---|\n");
    for (int a = 0; a < 3; ++a) {
        fprintf(f, "| %c | %.3g | %.3g | %.3g |\n", "XYZ"[a], seed_table3[a][0], seed_table3[a][1],
                seed_table3[a][2]);
    }
    fprintf(f, "\n## Error maps\n\nMean deviation of each family from the solve over the output "
               "points (the seed's Figs 5–13), per force axis and displacement component.\n\n");
    for (size_t i = 0; i < o->n_families; ++i) {
        const tf_family_result *r = &o->fam[i];
        if (r->applicable && r->family->kind == TF_FAMILY_FORWARD) {
            fprintf(f, "![%s](%s_errors_%s.png)\n\n", r->family->name, name, r->family->name);
        }
    }
}

int tf_report_fit(tf_ctx *ctx, const char *dir, const char *header, const tf_problem *s,
                  const tf_solver *solver, const tf_fit_plan *plan, const tf_fit_outcome *o)
{
    char name[256], path[4096];
    stem(header, name, sizeof name);
    snprintf(path, sizeof path, "%s/%s_cv.png", dir, name);
    if (cv_plot(ctx, path, o) != 0) {
        return -1;
    }
    for (size_t i = 0; i < o->n_families; ++i) {
        const tf_family_result *r = &o->fam[i];
        if (!r->applicable || r->family->kind != TF_FAMILY_FORWARD) {
            continue;
        }
        snprintf(path, sizeof path, "%s/%s_errors_%s.png", dir, name, r->family->name);
        if (error_map(ctx, path, &o->cases.train, r, r->family->name) != 0) {
            return -1;
        }
    }
    tf_afile md;
    snprintf(path, sizeof path, "%s/%s.md", dir, name);
    if (tf_afile_open(ctx, &md, path) != 0) {
        return -1;
    }
    write_md(md.fp, name, header, s, solver, plan, o);
    const tf_family_result *em = tf_fit_result_of(o, plan->family);
    if (o->has_hist && em != NULL && em->model != NULL && tf_stateful(em->model)) {
        char png[512];
        snprintf(png, sizeof png, "%s_history.png", name);
        snprintf(path, sizeof path, "%s/%s", dir, png);
        if (tf_report_histories(ctx, md.fp, path, png, em->model, &o->hist,
                                em->model->family == TFIT_FAMILY_RESONANT) != 0) {
            tf_afile_abort(&md);
            return -1;
        }
    }
    return tf_afile_commit(ctx, &md);
}
