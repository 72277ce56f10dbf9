/*
 * homogeneous.c — the cube in uniaxial stress and its closed form
 * (homogeneous.h).
 */
#include "homogeneous.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* S_yy and P_xx at axial stretch lam, lateral stretch t. */
static int stresses(const tf_material *m, double lam, double t, double *syy, double *pxx)
{
    double F[9] = {lam, 0, 0, 0, t, 0, 0, 0, t}, S[6];
    double *h = NULL, hist[16] = {0};
    if (tf_material_history_size(m) > 0) {
        h = hist; /* from rest, an instantaneous step: t = 0 (Kelvin: E_0) */
    }
    if (tf_material_eval(m, F, 0, h, h, S, NULL, NULL) != TF_MAT_OK) {
        return -1;
    }
    *syy = S[1];
    *pxx = tf_material_kinematics(m) == TF_KIN_SMALL ? S[0] : lam * S[0];
    return 0;
}

int homog_uniaxial(const tf_material *m, double lam, double *lateral, double *p)
{
    double t = 1, syy, pxx;
    for (int it = 0; it < 100; ++it) {
        double s1, s2, dummy, h = 1e-7;
        if (stresses(m, lam, t, &syy, &pxx) != 0 || stresses(m, lam, t + h, &s1, &dummy) != 0 ||
            stresses(m, lam, t - h, &s2, &dummy) != 0) {
            return -1;
        }
        double step = syy / ((s1 - s2) / (2 * h));
        t -= step;
        if (fabs(step) < 1e-15) {
            break;
        }
    }
    if (stresses(m, lam, t, &syy, &pxx) != 0 || fabs(syy) > 1e-13 * fabs(pxx) + 1e-300) {
        return -1;
    }
    *lateral = t;
    *p = pxx;
    return 0;
}

tf_scene *homog_scene(tf_ctx *ctx, const char *method, const char *material, int stretch,
                      double lam_max, double force_max, const char *const *sets, size_t n_sets)
{
    char text[2048];
    double L = HOMOG_L;
    int n = snprintf(text, sizeof text,
                     "name: cube\n"
                     "geometry:\n"
                     "  box: {min: [0, 0, 0], max: [%g, %g, %g]}\n"
                     "  grid: [4, 4, 4]\n"
                     "  jitter: 0.25\n"
                     "  seed: 7\n"
                     "material: %s\n"
                     "fixed:\n"
                     "  - {face: x-, components: [x]}\n"
                     "  - {face: y-, components: [y]}\n"
                     "  - {face: z-, components: [z]}\n",
                     L, L, L, material);
    if (stretch) {
        n += snprintf(text + n, sizeof text - (size_t)n,
                      "  - {face: x+, components: [x], displacement: [%.17g, 0, 0]}\n",
                      (lam_max - 1) * L);
    } else {
        n += snprintf(text + n, sizeof text - (size_t)n,
                      "loads:\n  - {patch: {face: x+}, force: [%.17g, 0, 0]}\n", force_max);
    }
    snprintf(text + n, sizeof text - (size_t)n,
             "outputs: {select: all}\n"
             "solver:\n"
             "  method: %s\n"
             "  integration: vci\n"
             "  bc: nitsche\n"
             "  newton: {tolerance: 1.0e-11, energy_tolerance: 1.0e-22}\n",
             method);
    return tf_scene_load_text(ctx, text, strlen(text), "cube.yaml", sets, n_sets);
}

double homog_field_error(const tf_problem *p, const double *u, double lam, double lat)
{
    double worst = 0, scale = 0;
    for (size_t i = 0; i < p->cloud.n; ++i) {
        const double *x = p->cloud.xyz + 3 * i;
        double ue[3] = {(lam - 1) * x[0], (lat - 1) * x[1], (lat - 1) * x[2]};
        for (int a = 0; a < 3; ++a) {
            worst = fmax(worst, fabs(u[3 * i + (size_t)a] - ue[a]));
            scale = fmax(scale, fabs(ue[a]));
        }
    }
    return worst / scale;
}
