/*
 * region_sweep.c — see region_sweep.h.
 */
#include "tradeoff/region_sweep.h"

#include <math.h>
#include <stdlib.h>

#include "base/plot.h"
#include "cost/cycles.h"
#include "fitting/region_fit.h"
#include "fitting/region_models.h"
#include "model/model.h"
#include "tfit.h"

void tf_region_sweep_free(tf_region_sweep *sw)
{
    free(sw->row);
    sw->row = NULL;
    sw->n = 0;
}

/* One row: the surface of rank r at level lv, its errors, its device
 * models' bytes and cycles. */
static int row_at(tf_ctx *ctx, const tf_problem *p, int contact, const tf_region_result *res,
                  const tf_region_level *lv, unsigned r, tf_region_sweep_row *row)
{
    tf_region_level tmp = *lv;
    if (tf_region_surface_fit(ctx, &lv->modes, lv->nx, lv->ny, lv->h, p->envelope.radius, r,
                              &tmp.surface_model) != 0) {
        return -1;
    }
    tf_model *law = NULL, *surf = NULL;
    int rc = tf_region_level_models(ctx, p, contact, &tmp, "law", "surface", &law, &surf);
    if (rc == 0) {
        *row = (tf_region_sweep_row){.nx = lv->nx, .ny = lv->ny, .h = fmax(lv->h[0], lv->h[1]),
                                     .rank = r, .near = tmp.surface_model.n_near,
                                     .force = lv->force};
        tf_region_surface_heldout(&tmp.surface_model, res, lv, &row->surface, &row->surface_rms);
        row->coupling = tf_region_surface_coupling(&tmp.surface_model, res, lv);
        row->law_bytes = tf_model_table_bytes(law);
        row->surface_bytes = tf_model_table_bytes(surf);
        row->law_cycles = tf_model_cycles(law, TF_CORE_M4F).cycles;
        row->surface_cycles = tf_model_cycles(surf, TF_CORE_M4F).cycles;
    }
    tf_model_free(law);
    tf_model_free(surf);
    tf_region_surface_free(&tmp.surface_model);
    return rc;
}

int tf_region_sweep_run(tf_ctx *ctx, const tf_problem *p, tf_solver *s, int contact,
                        tf_region_sweep *out)
{
    *out = (tf_region_sweep){0};
    tf_region_targets tg = tf_region_targets_default();
    tg.max_rank = TFIT_REGION_MAX_RANK; /* as tissuefit fit (region_models.c) */
    tg.coupling = INFINITY;
    tf_region_result res;
    if (tf_region_fit(ctx, s, p, contact, &tg, &res) != 0) {
        return -1;
    }
    size_t cap = (size_t)res.n_levels * 12;
    out->row = calloc(cap, sizeof *out->row);
    int rc = out->row ? 0 : tf_fail(ctx, "out of memory");
    for (unsigned k = 0; rc == 0 && k < res.n_levels; ++k) {
        const tf_region_level *lv = &res.level[k];
        unsigned ranks[12], n = 0;
        for (unsigned r = 1; n + 2 < 12; r *= 2) { /* 1, 2, 4, ... and the modes there are */
            unsigned rr = r < lv->modes.r_max ? r : lv->modes.r_max;
            if (lv->rank < rr && (n == 0 || ranks[n - 1] < lv->rank)) {
                ranks[n++] = lv->rank; /* the chosen rank in its place */
            }
            if (n == 0 || ranks[n - 1] != rr) {
                ranks[n++] = rr;
            }
            if (rr == lv->modes.r_max) {
                break;
            }
        }
        if (ranks[n - 1] < lv->rank) {
            ranks[n++] = lv->rank;
        }
        for (unsigned i = 0; rc == 0 && i < n && out->n < cap; ++i) {
            tf_region_sweep_row *row = &out->row[out->n];
            rc = row_at(ctx, p, contact, &res, lv, ranks[i], row);
            if (rc == 0) {
                row->chosen = k + 1 == res.n_levels && ranks[i] == lv->rank;
                out->n++;
            }
        }
    }
    if (rc == 0) {
        out->peak = res.level[res.n_levels - 1].peak;
        out->seconds = res.level[res.n_levels - 1].seconds;
    }
    tf_region_result_free(&res);
    if (rc != 0) {
        tf_region_sweep_free(out);
    }
    return rc;
}

int tf_region_sweep_csv(const tf_region_sweep *sw, FILE *f)
{
    fprintf(f, "sites_x,sites_y,spacing_mm,rank,near,law_force_rel,surface_rel_max,"
               "surface_rel_rms,coupling_rel,law_bytes,surface_bytes,law_m4f_cycles,"
               "surface_m4f_cycles,chosen\n");
    for (size_t i = 0; i < sw->n; ++i) {
        const tf_region_sweep_row *r = &sw->row[i];
        fprintf(f, "%u,%u,%.6g,%u,%u,%.6g,%.6g,%.6g,%.6g,%u,%u,%.0f,%.0f,%d\n", r->nx, r->ny, r->h,
                r->rank, r->near, r->force, r->surface, r->surface_rms, r->coupling, r->law_bytes,
                r->surface_bytes, r->law_cycles, r->surface_cycles, r->chosen);
    }
    return ferror(f) ? -1 : 0;
}

int tf_region_sweep_markdown(const tf_region_sweep *sw, FILE *f)
{
    fprintf(f, "| sites | spacing | rank | near | law force | surface (max / rms) | coupling | "
               "law bytes | surface bytes | law M4F cycles | surface M4F cycles |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (size_t i = 0; i < sw->n; ++i) {
        const tf_region_sweep_row *r = &sw->row[i];
        char cpl[32];
        snprintf(cpl, sizeof cpl, "%.3g %%", 100 * r->coupling);
        fprintf(f, "| %u × %u | %.3g mm | %u%s | %u | %.3g %% | %.3g / %.3g %% | %s | %u | %u | "
                   "%.0f | %.0f |\n",
                r->nx, r->ny, r->h, r->rank, r->chosen ? " (chosen)" : "", r->near,
                100 * r->force, 100 * r->surface, 100 * r->surface_rms, cpl, r->law_bytes,
                r->surface_bytes, r->law_cycles, r->surface_cycles);
    }
    return ferror(f) ? -1 : 0;
}

int tf_region_sweep_plot(tf_ctx *ctx, const tf_region_sweep *sw, const char *path)
{
    tf_plot p;
    if (tf_plot_open(ctx, &p, path, 1000, 700) != 0) {
        return -1;
    }
    fprintf(p.gp, "set logscale xy\nset grid\nset key outside right\n"
                  "set xlabel 'surface table (bytes)'\n"
                  "set ylabel 'surface error at the cell centres (%% of the peak)'\n"
                  "set title 'contact region: surface error against table size, ranks 1 .. 48 "
                  "(circled: tissuefit fit''s choice)'\n");
    fprintf(p.gp, "plot");
    unsigned last_nx = 0;
    for (size_t i = 0; i < sw->n; ++i) { /* one series a spacing (rows come in spacing order) */
        if (sw->row[i].nx != last_nx) {
            fprintf(p.gp, "%s '-' w lp pt 7 t '%u x %u sites, %.3g mm'", last_nx ? "," : "",
                    sw->row[i].nx, sw->row[i].ny, sw->row[i].h);
            last_nx = sw->row[i].nx;
        }
    }
    fprintf(p.gp, ", '-' w p pt 6 ps 3 lc 'black' t 'chosen'\n");
    for (size_t i = 0; i < sw->n; ++i) {
        fprintf(p.gp, "%u %g\n", sw->row[i].surface_bytes, 100 * sw->row[i].surface);
        if (i + 1 == sw->n || sw->row[i + 1].nx != sw->row[i].nx) {
            fprintf(p.gp, "e\n");
        }
    }
    for (size_t i = 0; i < sw->n; ++i) {
        if (sw->row[i].chosen) {
            fprintf(p.gp, "%u %g\n", sw->row[i].surface_bytes, 100 * sw->row[i].surface);
        }
    }
    fprintf(p.gp, "e\n");
    return tf_plot_close(ctx, &p);
}
