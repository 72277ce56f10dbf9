/*
 * organ_pictures.h — an organ scene as pictures (surface_render.h): the
 * surface at rest with its fixed region and contact sites, and the surface
 * deformed by a solve, coloured by |u|.  The camera looks at the contact
 * site from outside, turned 35 degrees about the vertical and raised 20
 * degrees so that a dent shows its relief.
 */
#ifndef TF_ORGAN_PICTURES_H
#define TF_ORGAN_PICTURES_H

#include <stddef.h>

#include "base/context.h"
#include "problem/problem.h"

typedef struct tf_report_organ_view {
    int contact;       /* site the camera looks at (>= 0) */
    double exaggerate; /* displacements drawn this many times their size (1: to scale) */
    const char *title; /* first line of the title, or NULL for the scene's name */
    double azimuth, elevation; /* camera (degrees, surface_render.h), NAN: at the site */
} tf_report_organ_view;

/* The rest surface: tissue, fixed nodes (blue) and contact patches (red). */
int tf_report_organ_rest_png(tf_ctx *ctx, const char *path, const tf_problem *p,
                             const tf_report_organ_view *v);

/* The surface moved by u (3 per node), coloured by |u|; force is what
 * caused it (N, for the title). */
int tf_report_organ_deformed_png(tf_ctx *ctx, const char *path, const tf_problem *p,
                                 const double *u, const double force[3],
                                 const tf_report_organ_view *v);

#endif /* TF_ORGAN_PICTURES_H */
