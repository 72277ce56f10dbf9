/*
 * material_of.h — a material for a test, by its law's registered name and
 * "key=value" parameters, as a scene would give them.
 */
#ifndef TF_TEST_MATERIAL_OF_H
#define TF_TEST_MATERIAL_OF_H

#include "materials/material.h"

/* The law registered as law with the parameters in params ("E=2 nu=0.3",
 * separated by spaces or commas; the others at their fallbacks).  Aborts
 * with a message when the law or a key is unknown: a test's own error. */
tf_material tf_test_material(const char *law, const char *params);

#endif /* TF_TEST_MATERIAL_OF_H */
