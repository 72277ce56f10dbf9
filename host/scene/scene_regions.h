/*
 * scene_regions.h — scene regions resolved against the node cloud: the
 * nodes of a face, plane or box; load patches checked against their face;
 * the output selection.
 */
#ifndef TF_SCENE_REGIONS_H
#define TF_SCENE_REGIONS_H

#include <stddef.h>
#include <stdint.h>

#include "scene/scene.h"
#include "scene/scene_schema.h"

/* Nodes in a region (within tf_cloud_tol of a face or plane, inside a box
 * with that tolerance), ascending.  Returns 0, or -1 when out of memory. */
int sd_region_nodes(const tf_cloud *c, const tf_region *r, uint32_t **nodes, size_t *n);

/* A patch from its document form: shape defaulted from the keys given,
 * extent inside the face.  Returns 0, or -1 with a message. */
int sd_resolve_patch(const sd_patch *d, const tf_cloud *c, tf_patch *p, char *msg, size_t msglen);

/* The output nodes.  Returns 0, or -1 with a message (e.g. none selected). */
int sd_resolve_outputs(const sd_outputs *d, const tf_scene *s, tf_outputs *o, char *msg, size_t msglen);

#endif /* TF_SCENE_REGIONS_H */
