/*
 * region_chart.h — a contact region's chart (contact_region.h): the frame
 * in which its rest surface is a height field c = h(a, b) over a rectangle,
 * the surface point of a site, and the probe's patch at a site.
 *
 * A box face: R a permutation/sign matrix of the face (e1 along the face's
 * u axis, n the outward normal, e2 = n x e1), o the rectangle's corner on
 * the face, h = 0.  An organ: n the area-weighted mean outward normal of
 * the surface triangles over the rectangle (fitted by fixed-point
 * iteration from the triangle nearest the centre), e1 the projection of
 * the scene's x axis (y when x is within 25 degrees of n), e2 = n x e1, o on
 * the fitted plane (through the triangles' area-weighted centroid) so that
 * the rectangle is centred on the surface point nearest `centre`; h the
 * outermost intersection of the line o + R^T (a, b, t) with the surface.
 * The organ is refused when it is not a graph over the rectangle widened
 * by the tip (a line that meets no surface, or an outermost triangle whose
 * normal makes more than TF_REGION_MAX_TILT_DEG with n).
 */
#ifndef TF_REGION_CHART_H
#define TF_REGION_CHART_H

#include <stddef.h>

#include "base/context.h"
#include "problem/problem.h"

/* Largest angle between an outermost surface triangle and the region's
 * normal, degrees. */
#define TF_REGION_MAX_TILT_DEG 75.0

/* Resolves r->chart on problem p (its box or its organ; r's kind says
 * which).  Returns 0, or -1 with the message in ctx (without the scene
 * path, which the caller adds).  Frees nothing of r on failure but its
 * own allocations. */
int tf_region_chart_build(tf_ctx *ctx, const tf_problem *p, tf_contact_region *r);

/* Frees what the chart owns (an organ's triangles). */
void tf_region_chart_free(tf_region_chart *c);

/* Chart coordinates q = R (x - o) of a scene point x, and back. */
void tf_region_chart_coords(const tf_region_chart *c, const double x[3], double q[3]);
void tf_region_chart_point(const tf_region_chart *c, const double q[3], double x[3]);

/* h(a, b): the outermost surface height at (a, b) (0 on a box face).
 * Returns 0, or -1 when the line meets no kept triangle. */
int tf_region_chart_height(const tf_region_chart *c, double a, double b, double *h);

/* The probe's extent from a site along a and b, mm (a disc: its radius). */
void tf_region_tip_extent(const tf_contact_region *r, double w[2]);

/* The probe's patch at site (a, b) of the domain, as quadrature points
 * (TF_PATCH_POINTS): the tip's outline (a rectangle along a and b, or a
 * 128-gon inscribed in its disc) clipped to every cell of a box face's node
 * grid (where the shape functions' supports change), or, on an organ, to
 * the projection of every triangle of the surface graph (the surface that
 * projects into the tip), each piece fanned into triangles with the
 * degree-5 rule on each; the patch moves continuously with the site.  x
 * (may be NULL): the site's surface point.  Returns 0, or -1 with a
 * message in ctx (out of memory, no surface). */
int tf_region_site_patch(tf_ctx *ctx, const tf_problem *p, const tf_contact_region *r, double a,
                         double b, tf_patch *patch, double x[3]);

#endif /* TF_REGION_CHART_H */
