/*
 * registry.c — every material law, by name (material.h); the first is the
 * law of a scene that names none.
 *
 * Adding a law: a file in this folder that defines
 * `const tf_law_ops tf_law_NAME`, and NAME in the list below.  The scene
 * then accepts its name as material.law and its parameters' keys under
 * material, and `tissuefit --help` lists it.
 */
#include <stdio.h>
#include <string.h>

#include "materials/material.h"

#define LAWS(X) X(linear) X(svk) X(neohooke) X(kelvin) X(kelvin_nh)

#define DECLARE(name) extern const tf_law_ops tf_law_##name;
LAWS(DECLARE)
#define ENTRY(name) &tf_law_##name,
static const tf_law_ops *const laws[] = {LAWS(ENTRY)};

size_t tf_law_count(void) { return sizeof laws / sizeof laws[0]; }

const tf_law_ops *tf_law_at(size_t i) { return i < tf_law_count() ? laws[i] : NULL; }

const tf_law_ops *tf_law_find(const char *name)
{
    for (size_t i = 0; i < tf_law_count(); ++i) {
        if (strcmp(laws[i]->name, name) == 0) {
            return laws[i];
        }
    }
    return NULL;
}

const tf_law_ops *tf_law_default(void) { return laws[0]; }

void tf_law_names(char *out, size_t outlen)
{
    size_t k = 0;
    out[0] = '\0';
    for (size_t i = 0; i < tf_law_count() && k < outlen; ++i) {
        int n = snprintf(out + k, outlen - k, "%s%s", i ? ", " : "", laws[i]->name);
        k += n > 0 ? (size_t)n : 0;
    }
}

/* Whether law i's parameter j is the first of its key over the registry. */
static int first_of_key(size_t i, size_t j)
{
    const char *key = laws[i]->params[j].key;
    for (size_t a = 0; a <= i; ++a) {
        for (size_t b = 0; b < (a < i ? laws[a]->n_params : j); ++b) {
            if (strcmp(laws[a]->params[b].key, key) == 0) {
                return 0;
            }
        }
    }
    return 1;
}

size_t tf_law_key_count(void)
{
    size_t n = 0;
    for (size_t i = 0; i < tf_law_count(); ++i) {
        for (size_t j = 0; j < laws[i]->n_params; ++j) {
            n += (size_t)first_of_key(i, j);
        }
    }
    return n;
}

const char *tf_law_key_at(size_t k)
{
    for (size_t i = 0; i < tf_law_count(); ++i) {
        for (size_t j = 0; j < laws[i]->n_params; ++j) {
            if (first_of_key(i, j) && k-- == 0) {
                return laws[i]->params[j].key;
            }
        }
    }
    return NULL;
}
