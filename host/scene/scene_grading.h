/*
 * scene_grading.h — a scene's graded grid (geometry.grading): the ratio per
 * axis from the file, the attractors from the scene itself.  Nodes are
 * drawn towards the places where the solution varies fastest: every fixed
 * face or plane (along its normal) and fixed box, every load and contact
 * patch (along its face's normal, and the patch's extent in the face: its
 * edges are where the traction jumps), and every load or contact point.
 */
#ifndef TF_SCENE_GRADING_H
#define TF_SCENE_GRADING_H

#include <stddef.h>

#include "problem/grading.h"
#include "scene/scene_schema.h"

/* Fills g for the box [lo, hi] from doc (ratio 1 everywhere when doc has no
 * geometry.grading).  Returns 0, or -1 with a message (a ratio below 1 or
 * above 20). */
int sd_grading(const sd_scene *doc, const double lo[3], const double hi[3], tf_cloud_grading *g,
               char *msg, size_t msglen);

#endif /* TF_SCENE_GRADING_H */
