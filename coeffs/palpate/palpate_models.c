/*
 * palpate_models.c — the device models' geometry (palpate.h): the law's
 * rest surface and the chart's frame.
 */
#include <stdlib.h>
#include <string.h>

#include "coeffs/palpate/palpate.h"
#include "model/region_model.h"

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
