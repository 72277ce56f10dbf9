/*
 * transform.c — scale, centre, rotate, translate (transform.h).
 */
#include "geometry/transform.h"

#include <math.h>

tf_transform tf_transform_identity(void)
{
    tf_transform t = {.scale = 1};
    return t;
}

/* Rodrigues: R = I + sin(a) K + (1 - cos(a)) K^2, K the cross-product
 * matrix of the unit axis. */
void tf_transform_rotation(const tf_transform *t, double r[3][3])
{
    double n = sqrt(t->axis[0] * t->axis[0] + t->axis[1] * t->axis[1] + t->axis[2] * t->axis[2]);
    double a = t->angle_deg * (M_PI / 180);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            r[i][j] = i == j;
        }
    }
    if (n == 0 || a == 0) {
        return;
    }
    double k[3] = {t->axis[0] / n, t->axis[1] / n, t->axis[2] / n};
    double kx[3][3] = {{0, -k[2], k[1]}, {k[2], 0, -k[0]}, {-k[1], k[0], 0}};
    double s = sin(a), c = 1 - cos(a);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double kk = 0;
            for (int l = 0; l < 3; ++l) {
                kk += kx[i][l] * kx[l][j];
            }
            r[i][j] += s * kx[i][j] + c * kk;
        }
    }
}

static int finite3(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

int tf_transform_apply(const tf_transform *t, tf_surface *s, tf_geom_msg *m)
{
    if (!(t->scale > 0) || !isfinite(t->scale)) {
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT, "scale %g: must be a positive number",
                            t->scale);
    }
    if (!finite3(t->axis) || !isfinite(t->angle_deg) || !finite3(t->translate)) {
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT, "rotation or translation is not finite");
    }
    double r[3][3], c[3] = {0, 0, 0};
    tf_transform_rotation(t, r);
    if (t->centre) {
        double lo[3], hi[3];
        tf_surface_bbox(s, lo, hi);
        for (int a = 0; a < 3; ++a) {
            c[a] = 0.5 * (t->scale * lo[a] + t->scale * hi[a]);
        }
    }
    for (size_t i = 0; i < s->nv; ++i) {
        double *x = s->xyz + 3 * i, y[3];
        for (int a = 0; a < 3; ++a) {
            y[a] = t->scale * x[a] - c[a];
        }
        for (int a = 0; a < 3; ++a) {
            x[a] = r[a][0] * y[0] + r[a][1] * y[1] + r[a][2] * y[2] + t->translate[a];
        }
    }
    return TF_GEOM_OK;
}
