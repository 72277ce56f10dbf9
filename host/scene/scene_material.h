/*
 * scene_material.h — a scene's material section into a material
 * (materials/material.h): the law named by material.law, looked up in the
 * law registry, and its parameters by their keys.  Nothing here names a
 * law or a parameter: adding a law to the registry adds its name and keys
 * to the scene.
 */
#ifndef TF_SCENE_MATERIAL_H
#define TF_SCENE_MATERIAL_H

#include "materials/material.h"
#include "scene/scene_issue.h"
#include "scene/scene_schema.h"

/* The material of section d, found at `at` ("material", or
 * "inclusions.0.material").  Refuses, with the path of the key at fault:
 * a law the registry lacks (naming those it has), a parameter the law
 * needs that is missing, a key of another law, and what the law's own
 * check refuses.  Returns 0, or -1 with the issue. */
int sd_build_material(const sd_material *d, const char *at, tf_material *m, sd_issue *is);

#endif /* TF_SCENE_MATERIAL_H */
