/*
 * scene_regions.h — the parts of a scene document resolved against the node
 * cloud: load patches checked against their face, and the output selection.
 */
#ifndef TF_SCENE_REGIONS_H
#define TF_SCENE_REGIONS_H

#include <stddef.h>
#include <stdint.h>

#include "problem/problem.h"
#include "scene/scene_schema.h"

/* A patch from its document form: shape defaulted from the keys given,
 * extent inside the face.  Returns 0, or -1 with a message. */
int sd_resolve_patch(const sd_patch *d, const tf_cloud *c, tf_patch *p, char *msg, size_t msglen);

/* The output nodes.  Returns 0, or -1 with a message (e.g. none selected). */
/* What to add to "holds no node": where the body's nodes lie, and for an
 * organ that its mesh may be in other units than mm. */
void sd_body_extent(const tf_problem *s, char *buf, size_t len);

int sd_resolve_outputs(const sd_outputs *d, const tf_problem *s, tf_outputs *o, char *msg,
                       size_t msglen);

#endif /* TF_SCENE_REGIONS_H */
