/*
 * reference.c — analytic reference solutions (reference.h).
 */
#include "verify/reference.h"

#include "materials/elasticity.h"

static void cantilever(const tf_scene *s, const double p[3], double u[3], double g[9])
{
    double e = s->young / (1 - s->poisson * s->poisson);
    double nu = s->poisson / (1 - s->poisson);
    double len = s->box_max[0] - s->box_min[0], d = s->box_max[1] - s->box_min[1];
    double x = p[0] - s->box_min[0], y = p[1] - 0.5 * (s->box_min[1] + s->box_max[1]);
    double c = s->reference.load / (6 * e * (d * d * d / 12)); /* P / (6 E I) */
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

void tf_reference_eval(const tf_scene *s, const double x[3], double u[3], double g[9])
{
    const tf_reference *r = &s->reference;
    if (r->kind == TF_REF_CANTILEVER) {
        cantilever(s, x, u, g);
        return;
    }
    for (int i = 0; i < 3; ++i) {
        u[i] = r->kind == TF_REF_LINEAR ? r->offset[i] : 0;
        for (int j = 0; j < 3; ++j) {
            g[3 * i + j] = r->kind == TF_REF_LINEAR ? r->gradient[3 * i + j] : 0;
            u[i] += g[3 * i + j] * x[j];
        }
    }
}

void tf_reference_traction(const tf_scene *s, tf_face face, const double x[3], double t[3])
{
    double u[3], g[9], sigma[9];
    tf_lame l = tf_lame_from(s->young, s->poisson);
    tf_reference_eval(s, x, u, g);
    tf_stress(&l, g, sigma);
    int a = tf_face_axis(face);
    double sign = tf_face_is_max(face) ? 1 : -1;
    for (int i = 0; i < 3; ++i) {
        t[i] = sign * sigma[3 * i + a];
    }
}
