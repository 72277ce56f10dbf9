/*
 * material_of.c — see material_of.h.
 */
#include "material_of.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

tf_material tf_test_material(const char *law, const char *params)
{
    const tf_law_ops *ops = tf_law_find(law);
    if (ops == NULL) {
        fprintf(stderr, "tf_test_material: no law '%s'\n", law);
        abort();
    }
    tf_material m = tf_material_of(ops);
    char buf[256], *save = NULL;
    snprintf(buf, sizeof buf, "%s", params);
    for (char *t = strtok_r(buf, " ,", &save); t != NULL; t = strtok_r(NULL, " ,", &save)) {
        char *eq = strchr(t, '='), *end = NULL;
        double v = eq ? strtod(eq + 1, &end) : 0;
        if (eq == NULL || *end != '\0') {
            fprintf(stderr, "tf_test_material: '%s' is not key=number\n", t);
            abort();
        }
        *eq = '\0';
        if (tf_material_set(&m, t, v) != 0) {
            fprintf(stderr, "tf_test_material: the %s law has no parameter '%s'\n", law, t);
            abort();
        }
    }
    return m;
}
