/*
 * region_models.c — a contact region's law and surface as device models
 * (region_models.h).
 */
#include "fitting/region_models.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "model/region_model.h"

/* The model's grid: the chart's frame (o: the domain's corner (0, 0)) and
 * the spacing's sites. */
static tf_region_grid grid_of(const tf_region_chart *c, const tf_region_level *lv)
{
    tf_region_grid g = {.nx = lv->nx, .ny = lv->ny, .ha = lv->h[0], .hb = lv->h[1]};
    for (int i = 0; i < 3; ++i) {
        g.origin[i] = c->o[i];
    }
    for (int i = 0; i < 9; ++i) {
        g.rot[i] = c->R[i];
    }
    return g;
}

/* The surface model: the fit's modes are 3 n_out x r column-major, the
 * table's Phi[3 n_out][r] row-major; the control blocks {A[r][3],
 * Phi_site[3][r]} are the same in both. */
static tf_model *surface_model(tf_ctx *ctx, const tf_problem *p, const tf_region_grid *g,
                               const tf_region_level *lv, const char *name)
{
    const tf_region_surface *sf = &lv->surface_model;
    const size_t rows = 3 * sf->n_out;
    double *modes = malloc((rows * sf->r + 1) * sizeof *modes);
    uint32_t *ids = malloc((sf->n_out + 1) * sizeof *ids);
    if (modes == NULL || ids == NULL) {
        free(modes);
        free(ids);
        tf_fail(ctx, "out of memory");
        return NULL;
    }
    for (size_t o = 0; o < rows; ++o) {
        for (unsigned k = 0; k < sf->r; ++k) {
            modes[o * sf->r + k] = sf->modes[o + (size_t)k * rows];
        }
    }
    for (size_t j = 0; j < sf->n_out; ++j) { /* as the load cases number them (cases.c) */
        ids[j] = p->outputs.points ? (uint32_t)j + 1
                                   : tf_problem_node_number(p, p->outputs.nodes[j]);
    }
    /* the near field per unit normalised force f = F / R_F */
    const size_t ne = (size_t)(sf->nx + 2) * (sf->ny + 2) * sf->n_near;
    double *D = malloc((9 * ne + 1) * sizeof *D);
    if (D == NULL) {
        free(modes);
        free(ids);
        tf_fail(ctx, "out of memory");
        return NULL;
    }
    for (size_t i = 0; i < 9 * ne; ++i) {
        D[i] = sf->near_D[i] * sf->R_F;
    }
    const tf_region_near_table near = {sf->n_near, sf->near_idx, D};
    tf_model *m = tf_region_surface_new(ctx, name, g, lv->law.s_u, lv->law.mu, sf->R_F, sf->r, 1,
                                        1, sf->ctrl, &near, modes, (uint32_t)sf->n_out, ids);
    free(D);
    free(modes);
    free(ids);
    return m;
}

int tf_region_level_models(tf_ctx *ctx, const tf_problem *p, int contact,
                           const tf_region_level *lv, const char *law_name,
                           const char *surf_name, tf_model **law, tf_model **surf)
{
    const tf_region_grid g = grid_of(&p->contacts[contact].region.chart, lv);
    *law = tf_region_law_new(ctx, law_name, &g, lv->law.P, lv->law.s_u, lv->law.mu, lv->law.ctrl,
                             (uint32_t)contact);
    *surf = *law != NULL ? surface_model(ctx, p, &g, lv, surf_name) : NULL;
    if (*surf == NULL) {
        tf_model_free(*law);
        *law = NULL;
        return -1;
    }
    return 0;
}

/* The datasheet lines of the law and of the surface (region_models.h):
 * the sites and why, then each model's own figures.  Nothing that varies
 * from run to run (times): the header regenerates byte for byte. */
static void notes(const tf_region_result *res, const tf_region_level *lv,
                  const tf_region_targets *tg, const char *contact, double R_F, tf_model *law,
                  tf_model *surf)
{
    const unsigned centres = (lv->nx - 1) * (lv->ny - 1);
    snprintf(law->fit_note, sizeof law->fit_note,
             "region '%s': %s\n"
             "held out at the %u cell centres (sites never fitted): the worst force on the "
             "envelope's\nsphere (%.3g N) off by %.3g %% of it; rest height within %.2g mm; "
             "stiffness >= %.4g N/mm\n(%s: passive)",
             contact, res->why, centres, R_F, 100 * lv->force, lv->height, lv->min_stiffness,
             lv->cp_spd ? "every control point SPD" : "the blend sampled 8 per site interval");
    snprintf(surf->fit_note, sizeof surf->fit_note,
             "region '%s': %s\n"
             "held out at the %u cell centres (sites never fitted): %.3g %% of the peak "
             "displacement %.4g mm;\nrank %u, %s (at most %u); near field: %u outputs "
             "per control point\n(those within %.3g mm, %.3g probe widths); two instruments\n"
             "(tfit_region_pair): %.3g %% of the envelope radius over %zu pairs of sites",
             contact, res->why, centres, 100 * lv->surface, lv->peak, lv->rank,
             lv->surface <= tg->surface ? "the smallest meeting the surface target"
                                        : "the smallest surface error tried",
             tg->max_rank, lv->surface_model.n_near, lv->surface_model.near_radius, tg->near,
             100 * lv->coupling, lv->pairs);
}

int tf_region_models(tf_ctx *ctx, tf_solver *s, const tf_problem *p, int contact,
                     const char *law_name, const char *surf_name, tf_model **law,
                     tf_model **surf)
{
    const tf_contact *c = &p->contacts[contact];
    const double *x0 = p->envelope.centre;
    *law = *surf = NULL;
    if (!(tf_solver_caps_of(s) & TF_SOLVER_AFFINE)) {
        tf_fail(ctx, "contact region '%s': not yet: a region's models are fitted for an "
                            "affine solve (linear elasticity); this scene's solver is not affine "
                            "(a nonlinear law: make region-nonlinear studies its (site, force) "
                            "cases)",
                c->name);
        return -2;
    }
    if (x0[0] != 0 || x0[1] != 0 || x0[2] != 0) {
        tf_fail(ctx, "contact region '%s': not yet: a region's surface takes forces in the "
                     "ball |F| <= radius about zero; envelope.centre is (%g, %g, %g) N",
                c->name, x0[0], x0[1], x0[2]);
        return -2;
    }
    tf_region_targets tg = tf_region_targets_default();
    /* The device's rule: at most the modes a device surface holds (tfit.h),
     * and the rank chosen for one instrument, the surface target; the
     * two-instrument coupling is measured and stated, not a target (at 9 x 9
     * sites on block48 it needs rank 144 for 2 %: 3 times the cap). */
    tg.max_rank = TFIT_REGION_MAX_RANK;
    tg.coupling = INFINITY;
    tf_region_result res;
    if (tf_region_fit(ctx, s, p, contact, &tg, &res) != 0) {
        return -1;
    }
    const tf_region_level *lv = &res.level[res.n_levels - 1];
    if (tf_region_level_models(ctx, p, contact, lv, law_name, surf_name, law, surf) != 0) {
        tf_region_result_free(&res);
        return -1;
    }
    const uint32_t centres = (lv->nx - 1) * (lv->ny - 1);
    const double R_F = p->envelope.radius;
    (*law)->heldout_max = lv->force * R_F;
    (*law)->heldout_rms = lv->force_rms * R_F;
    (*law)->heldout_rel_max = lv->force;
    (*law)->heldout_cases = centres;
    (*surf)->heldout_max = lv->surface * lv->peak;
    (*surf)->heldout_rms = lv->surface_rms * lv->peak;
    (*surf)->heldout_rel_max = lv->surface;
    (*surf)->heldout_cases = centres;
    notes(&res, lv, &tg, c->name, R_F, *law, *surf);
    tf_region_result_free(&res);
    return 0;
}
