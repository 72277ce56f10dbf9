/*
 * analytic.c — analytic solutions (analytic.h).
 */
#include "problem/analytic.h"

#include "materials/elasticity.h"

static void cantilever(const tf_problem *p, const double at[3], double u[3], double g[9])
{
    double young, poisson, lo[3], hi[3];
    tf_material_moduli(&p->material, &young, &poisson);
    tf_problem_bounds(p, lo, hi);
    double e = young / (1 - poisson * poisson);
    double nu = poisson / (1 - poisson);
    double len = hi[0] - lo[0], d = hi[1] - lo[1];
    double x = at[0] - lo[0], y = at[1] - 0.5 * (lo[1] + hi[1]);
    double c = p->analytic.load / (6 * e * (d * d * d / 12)); /* P / (6 E I) */
    double d2 = d * d;
    u[0] = -c * y * ((6 * len - 3 * x) * x + (2 + nu) * (y * y - d2 / 4));
    u[1] = c * (3 * nu * y * y * (len - x) + (4 + 5 * nu) * d2 * x / 4 + (3 * len - x) * x * x);
    u[2] = 0;
    for (int k = 0; k < 9; ++k) {
        g[k] = 0;
    }
    g[0] = -c * y * (6 * len - 6 * x);
    g[1] = -c * ((6 * len - 3 * x) * x + (2 + nu) * (3 * y * y - d2 / 4));
    g[3] = c * (-3 * nu * y * y + (4 + 5 * nu) * d2 / 4 + 6 * len * x - 3 * x * x);
    g[4] = c * 6 * nu * y * (len - x);
}

void tf_analytic_eval(const tf_problem *p, const double x[3], double u[3], double g[9])
{
    const tf_analytic *r = &p->analytic;
    if (r->kind == TF_ANALYTIC_CANTILEVER) {
        cantilever(p, x, u, g);
        return;
    }
    for (int i = 0; i < 3; ++i) {
        u[i] = r->kind == TF_ANALYTIC_LINEAR ? r->offset[i] : 0;
        for (int j = 0; j < 3; ++j) {
            g[3 * i + j] = r->kind == TF_ANALYTIC_LINEAR ? r->gradient[3 * i + j] : 0;
            u[i] += g[3 * i + j] * x[j];
        }
    }
}

void tf_analytic_traction(const tf_problem *p, tf_face face, const double x[3], double t[3])
{
    double u[3], g[9], sigma[9];
    tf_lame l = tf_material_lame(&p->material);
    tf_analytic_eval(p, x, u, g);
    tf_stress(&l, g, sigma);
    int a = tf_face_axis(face);
    double sign = tf_face_is_max(face) ? 1 : -1;
    for (int i = 0; i < 3; ++i) {
        t[i] = sign * sigma[3 * i + a];
    }
}
