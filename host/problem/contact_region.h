/*
 * contact_region.h — a contact region: a part of the body's surface where
 * the haptic tool may touch anywhere ("palpation anywhere"), as a scene
 * gives it (a rectangle of a box face, or a rectangle of an organ's surface
 * around a point), the probe's patch, the friction coefficient, and the
 * chart it is resolved to (problem/region_chart.h).
 *
 * The chart is an orthonormal frame: origin o and rows e1, e2, n of R, such
 * that the region's rest surface is the graph c = h(a, b) over the domain
 * [0, len[0]] x [0, len[1]] of the (a, b) plane, the body below (c < h) and
 * n the outward direction.  The chart coordinates of a point p are
 * q = R (p - o) = (a, b, c).  A box face has h = 0 (o on the face); an
 * organ's h is the outermost intersection of the line o + R^T (a, b, t)
 * with its surface, found among the triangles the chart keeps.
 */
#ifndef TF_CONTACT_REGION_H
#define TF_CONTACT_REGION_H

#include <stddef.h>
#include <stdint.h>

#include "problem/nodes.h"

typedef enum tf_contact_region_kind {
    TF_CONTACT_REGION_NONE,  /* a contact site, not a region */
    TF_CONTACT_REGION_FACE,  /* a rectangle of a box face */
    TF_CONTACT_REGION_ORGAN, /* a rectangle of an organ's surface, in its fitted plane */
} tf_contact_region_kind;

/* The probe's patch around each site: a disc of the chart plane (on an
 * organ: the part of the surface that projects into it), or a rectangle
 * with sides along the chart's a and b axes (a box face only). */
typedef enum tf_tip_shape { TF_TIP_DISC, TF_TIP_RECT } tf_tip_shape;

/* The resolved chart (region_chart.h). */
typedef struct tf_region_chart {
    double o[3];     /* the domain's corner (a, b) = (0, 0), on the chart plane, mm */
    double R[9];     /* rows e1, e2, n */
    double len[2];   /* the domain's sides along a and b, mm */
    int flat;        /* 1: h = 0 (a box face) */
    /* An organ: the surface triangles a line over the domain widened by
     * the tip may meet, as node triples (tri, 3 per triangle) and their
     * corners in chart coordinates (q, 9 per triangle, corner after
     * corner); graph[k] = 1 when triangle k is part of the graph (the
     * outermost surface at its centroid's line, facing out).  Owned. */
    uint32_t *tri;
    double *q;
    unsigned char *graph;
    size_t n_tri;
} tf_region_chart;

typedef struct tf_contact_region {
    tf_contact_region_kind kind;
    tf_face face;       /* FACE: the box face */
    double rect[4];     /* FACE: a0, a1, b0, b1 in the face's in-face coordinates (u, v), mm */
    double centre[3];   /* ORGAN: the point the region is around, mm */
    double size[2];     /* ORGAN: the domain's sides along a and b, mm (radius R: 2R, 2R) */
    tf_tip_shape tip;
    double tip_radius;  /* DISC, mm */
    double tip_size[2]; /* RECT: along a and b, mm */
    double friction;    /* mu >= 0 */
    double spacing;     /* the site spacing, mm; 0: chosen by the site density rule */
    tf_region_chart chart;
} tf_contact_region;

#endif /* TF_CONTACT_REGION_H */
