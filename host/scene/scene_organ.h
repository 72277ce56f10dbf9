/*
 * scene_organ.h — the organ parts of a scene (geometry.surface): the mesh
 * file found beside the scene, read, filled and checked; contact sites and
 * loads on its surface; surface vertex lists.  Geometry messages come back
 * as issues naming the field (file:line:field once scene.c places them).
 */
#ifndef TF_SCENE_ORGAN_H
#define TF_SCENE_ORGAN_H

#include <stddef.h>
#include <stdint.h>

#include "problem/problem.h"
#include "scene/scene_issue.h"
#include "scene/scene_schema.h"

/* geometry.surface, .spacing and .refine into s->geometry (a mesh) and
 * s->cloud.  s->source is the scene file (relative mesh paths start from
 * its folder). */
int sd_organ_geometry(const sd_scene *doc, tf_problem *s, sd_issue *is);

/* A site {point, radius} at path: the contact node is the surface vertex
 * nearest point, the patch the triangles around it (tf_problem_mesh_site). */
int sd_organ_site(const sd_site *d, const tf_problem *s, const char *path, tf_patch *p,
                  uint32_t *node, sd_issue *is);

/* Vertices by their index in the mesh file into node indices (in list
 * order).  nodes holds n entries. */
int sd_organ_vertices(const uint32_t *v, size_t n, const tf_problem *s, const char *path,
                      uint32_t *nodes, sd_issue *is);

#endif /* TF_SCENE_ORGAN_H */
