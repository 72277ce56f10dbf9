/*
 * palpate_models.c — the fitted region as device models (palpate.h): the
 * model layer's builders (model/region_model.h, header-format.md §5.10,
 * §5.11) on the numbers of the fit.
 */
#include <stdlib.h>
#include <string.h>

#include "coeffs/palpate/palpate.h"
#include "model/region_model.h"

static tf_region_grid grid_of(const palpate_grid *g)
{
    tf_region_grid c = {.nx = g->nx, .ny = g->ny, .ha = g->ha, .hb = g->hb};
    memcpy(c.origin, g->origin, sizeof c.origin);
    memcpy(c.rot, g->rot, sizeof c.rot);
    return c;
}

tf_model *palpate_law(tf_ctx *ctx, const palpate_grid *g, unsigned P, double s_u, double mu,
                      const double *ctrl)
{
    const tf_region_grid c = grid_of(g);
    return tf_region_law_new(ctx, "palpate_law", &c, P, s_u, mu, ctrl, 0);
}

tf_model *palpate_surface(tf_ctx *ctx, const palpate_grid *g, double s_u, double mu, double R_F,
                          unsigned r, const double *ctrl, const double *modes, size_t n_out,
                          const uint32_t *node_ids)
{
    const tf_region_grid c = grid_of(g);
    return tf_region_surface_new(ctx, "palpate_surface", &c, s_u, mu, R_F, r, 1, 1, ctrl,
                                 modes, (uint32_t)n_out, node_ids);
}

void palpate_rest_point(const tf_model *law, const double g[2], double x[3])
{
    tf_region_rest_point(law, g, x, NULL);
}

void palpate_to_scene(const palpate_grid *g, const double q[3], double p[3])
{
    for (int j = 0; j < 3; ++j) {
        p[j] = g->origin[j] + g->rot[j] * q[0] + g->rot[3 + j] * q[1] + g->rot[6 + j] * q[2];
    }
}

void palpate_to_chart(const palpate_grid *g, const double p[3], double q[3])
{
    for (int i = 0; i < 3; ++i) {
        q[i] = 0;
        for (int j = 0; j < 3; ++j) {
            q[i] += g->rot[3 * i + j] * (p[j] - g->origin[j]);
        }
    }
}
