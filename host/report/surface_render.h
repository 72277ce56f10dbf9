/*
 * surface_render.h — a triangle surface drawn as a shaded PNG with correct
 * depth order (gnuplot pm3d, base/plot.h).
 *
 * gnuplot's own `pm3d depthorder` sorts facets by a single depth each in its
 * view frame and, on block48's dent, drew far facets over near ones.  Here
 * the camera is ours: the points are turned into a camera frame (azimuth
 * about z, then elevation), every triangle that faces away is dropped when
 * the surface is closed, the rest are sorted far to near by their
 * centroid's depth and handed to gnuplot looking straight down the camera
 * axis (`set view 0,0`) with pm3d drawing facets in the order given
 * (scansforward) and lit from the viewer.  Facets of a closed surface that
 * face the camera overlap only where the surface folds over itself; small
 * triangles sorted by centroid then paint correctly (the organ pictures in
 * docs/ were looked at).
 */
#ifndef TF_SURFACE_RENDER_H
#define TF_SURFACE_RENDER_H

#include <stddef.h>

#include "base/context.h"

typedef struct tf_report_render {
    const double *xyz;     /* node coordinates, mm */
    const double *u;       /* displacements (3 per node) added to xyz, or NULL */
    const size_t *tri;     /* 3 node indices per triangle, counter-clockwise from outside */
    size_t ntri;
    int closed;            /* 1: a closed surface (back faces are dropped) */
    const double *value;   /* per node: the colour value (a facet: the mean of its corners') */
    const double *tri_value; /* per triangle instead, or NULL (categories: no blending) */
    double vmin, vmax;     /* colour range */
    const char *palette;   /* gnuplot "set palette" arguments */
    const char *cblabel;   /* colour bar label, or NULL for no colour bar */
    double azimuth, elevation; /* camera, degrees: azimuth about +z from +x towards +y */
    double zscale;         /* vertical exaggeration (1: true shape) */
    const char *title;
    int width, height;     /* pixels */
} tf_report_render;

/* Writes the PNG (temporary file renamed on success).  Returns 0, or -1
 * with a message. */
int tf_report_render_png(tf_ctx *ctx, const char *path, const tf_report_render *r);

#endif /* TF_SURFACE_RENDER_H */
