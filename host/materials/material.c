/*
 * material.c — a material's parameters and what a solver asks of it
 * (material.h): each answer comes from the law's operations.
 */
#include "materials/material.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

int tf_law_param_index(const tf_law_ops *law, const char *key)
{
    for (size_t i = 0; i < law->n_params; ++i) {
        if (strcmp(law->params[i].key, key) == 0) {
            return (int)i;
        }
    }
    return -1;
}

void tf_law_param_list(const tf_law_ops *law, int required, char *out, size_t outlen)
{
    size_t n = 0, k = 0, used = 0;
    for (size_t i = 0; i < law->n_params; ++i) {
        n += !required || isnan(law->params[i].fallback);
    }
    out[0] = '\0';
    for (size_t i = 0; i < law->n_params && used < outlen; ++i) {
        if (required && !isnan(law->params[i].fallback)) {
            continue;
        }
        const char *sep = k == 0 ? "" : k + 1 == n ? " and " : ", ";
        int w = snprintf(out + used, outlen - used, "%s%s", sep, law->params[i].key);
        used += w > 0 ? (size_t)w : 0;
        ++k;
    }
}

tf_material tf_material_of(const tf_law_ops *law)
{
    tf_material m = {.law = law};
    for (size_t i = 0; i < TF_MATERIAL_MAX_PARAMS; ++i) {
        m.p[i] = i < law->n_params ? law->params[i].fallback : NAN;
    }
    return m;
}

int tf_material_set(tf_material *m, const char *key, double v)
{
    int i = tf_law_param_index(m->law, key);
    if (i < 0) {
        return -1;
    }
    m->p[i] = v;
    return 0;
}

double tf_material_get(const tf_material *m, const char *key)
{
    int i = tf_law_param_index(m->law, key);
    return i < 0 ? NAN : m->p[i];
}

const char *tf_material_name(const tf_material *m) { return m->law->name; }

unsigned tf_material_caps(const tf_material *m)
{
    return m->law->caps | (m->law->caps_at ? m->law->caps_at(m->p) : 0u);
}

int tf_material_linear_elastic(const tf_material *m)
{
    return (tf_material_caps(m) & (TF_MATERIAL_HOOKE | TF_MATERIAL_FINITE)) == TF_MATERIAL_HOOKE;
}

const char *tf_material_region_misfit(const tf_material *body, const tf_material *m)
{
    if (m->law == body->law) {
        return NULL;
    }
    if (tf_material_linear_elastic(body)) {
        return "a linear elastic body takes material regions of its own law";
    }
    if (tf_material_kinematics(m) != tf_material_kinematics(body)) {
        return tf_material_kinematics(body) == TF_KIN_FINITE
                   ? "the body's law is finite-strain and this law small-strain"
                   : "the body's law is small-strain and this law finite-strain";
    }
    if (tf_material_volume(m) != tf_material_volume(body)) {
        return "the two laws' volumetric energies take different volume measures (J - 1 and "
               "tr E), which one volumetric correction cannot average";
    }
    return NULL;
}

tf_kinematics tf_material_kinematics(const tf_material *m)
{
    return m->law->caps & TF_MATERIAL_FINITE ? TF_KIN_FINITE : TF_KIN_SMALL;
}

tf_volume_measure tf_material_volume(const tf_material *m) { return m->law->volume; }

size_t tf_material_history_size(const tf_material *m) { return m->law->history; }

void tf_material_history_init(const tf_material *m, double *h)
{
    if (m->law->history_init != NULL) {
        m->law->history_init(m->p, h);
        return;
    }
    for (size_t k = 0; k < m->law->history; ++k) {
        h[k] = 0;
    }
}

void tf_material_moduli(const tf_material *m, double *young, double *poisson)
{
    m->law->moduli(m->p, young, poisson);
}

tf_lame tf_material_lame(const tf_material *m)
{
    double e, nu;
    m->law->moduli(m->p, &e, &nu);
    return tf_lame_from(e, nu);
}

void tf_material_relaxation(const tf_material *m, double *g_inf, double *tau)
{
    if (m->law->relaxation == NULL) {
        *g_inf = 1;
        *tau = INFINITY;
        return;
    }
    m->law->relaxation(m->p, g_inf, tau);
}

const char *tf_material_check(const tf_material *m, char *msg, size_t len)
{
    msg[0] = '\0';
    return m->law->check(m->p, msg, len);
}

int tf_material_eval(const tf_material *m, const double F[9], double dt, const double *hold,
                     double *hnew, double S[6], double C[36], double *W)
{
    if (W) {
        *W = NAN;
    }
    return m->law->eval(m->p, F, dt, hold, hnew, S, C, W);
}
