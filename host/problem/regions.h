/*
 * regions.h — the nodes of a region of a problem's cloud (problem.h,
 * tf_region): within tf_cloud_tol of a face or plane; inside a box, a ball or
 * a half-space with that tolerance; surface vertices (the first n_surface
 * nodes of an organ's cloud) within a distance of a point.  A vertex list
 * selects nothing here: the scene resolves it.
 */
#ifndef TF_REGIONS_H
#define TF_REGIONS_H

#include <stddef.h>
#include <stdint.h>

#include "problem/problem.h"

/* Nodes in a region, ascending, in a malloc'ed array.  Returns 0, or -1
 * when out of memory. */
int tf_region_nodes(const tf_cloud *c, const tf_region *r, uint32_t **nodes, size_t *n);

#endif /* TF_REGIONS_H */
