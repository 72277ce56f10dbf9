/*
 * scene_material.c — a scene's material from the law registry
 * (scene_material.h).
 */
#include "scene/scene_material.h"

#include <math.h>
#include <stdio.h>

/* "kelvin and kelvin-neo-hookean": the laws with parameter key. */
static void laws_with(const char *key, char *out, size_t len)
{
    size_t n = 0, k = 0, used = 0;
    for (size_t i = 0; i < tf_law_count(); ++i) {
        n += tf_law_param_index(tf_law_at(i), key) >= 0;
    }
    out[0] = '\0';
    for (size_t i = 0; i < tf_law_count() && used < len; ++i) {
        const tf_law_ops *l = tf_law_at(i);
        if (tf_law_param_index(l, key) >= 0) {
            const char *sep = k == 0 ? "" : k + 1 == n ? " and " : ", ";
            int w = snprintf(out + used, len - used, "%s%s", sep, l->name);
            used += w > 0 ? (size_t)w : 0;
            ++k;
        }
    }
}

/* A parameter the law needs and the section lacks. */
static int missing(const tf_law_ops *law, size_t i, const char *at, sd_issue *is)
{
    char path[96], needs[256];
    const tf_law_param *p = &law->params[i];
    snprintf(path, sizeof path, "%s.%s", at, p->key);
    tf_law_param_list(law, 1, needs, sizeof needs);
    return sd_fail(is, path, "'%s' is missing: the %s law needs %s (%s: %s)", p->key, law->name,
                   needs, p->key, p->what);
}

/* A key the section gives that belongs to other laws. */
static int foreign(const tf_law_ops *law, const char *key, const char *at, sd_issue *is)
{
    char path[96], takes[256], owners[256];
    snprintf(path, sizeof path, "%s.%s", at, key);
    tf_law_param_list(law, 0, takes, sizeof takes);
    laws_with(key, owners, sizeof owners);
    return sd_fail(is, path, "the %s law takes %s, not %s (a parameter of %s)", law->name, takes,
                   key, owners);
}

int sd_build_material(const sd_material *d, const char *at, tf_material *m, sd_issue *is)
{
    const tf_law_ops *law = d->law ? tf_law_find(d->law) : tf_law_default();
    if (law == NULL) {
        char names[256], path[96];
        tf_law_names(names, sizeof names);
        snprintf(path, sizeof path, "%s.law", at);
        return sd_fail(is, path, "'%s' is not one of: %s", d->law, names);
    }
    *m = tf_material_of(law);
    size_t nkeys = tf_law_key_count();
    for (size_t k = 0; k < nkeys && k < SD_MATERIAL_KEYS; ++k) {
        if (d->param[k] != NULL) {
            tf_material_set(m, tf_law_key_at(k), *d->param[k]); /* (another law's: below) */
        }
    }
    for (size_t i = 0; i < law->n_params; ++i) {
        if (isnan(m->p[i])) {
            return missing(law, i, at, is);
        }
    }
    for (size_t k = 0; k < nkeys && k < SD_MATERIAL_KEYS; ++k) {
        if (d->param[k] != NULL && tf_law_param_index(law, tf_law_key_at(k)) < 0) {
            return foreign(law, tf_law_key_at(k), at, is);
        }
    }
    char why[256], path[96];
    const char *bad = tf_material_check(m, why, sizeof why);
    if (bad != NULL) {
        snprintf(path, sizeof path, "%s.%s", at, bad);
        return sd_fail(is, path, "%s", why);
    }
    return 0;
}
