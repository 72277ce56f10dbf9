/*
 * winding.h — the generalised winding number of a point with respect to a
 * closed triangle surface: the solid angle the surface subtends at the
 * point over 4 pi (Jacobson, Kavan and Sorkine-Hornung 2013, eq. 2-3), with
 * each triangle's signed solid angle from Van Oosterom and Strackee (1983):
 *
 *     tan(Omega / 2) = a . (b x c) / (|a||b||c| + (a.b)|c| + (b.c)|a| + (c.a)|b|)
 *
 * for a, b, c the corners relative to the point.  It is 1 inside an
 * outward-wound closed surface, 0 outside, 1/2 on it, and degrades smoothly
 * (no ray to cast, no degenerate case to resolve) near defects.
 */
#ifndef TF_WINDING_H
#define TF_WINDING_H

#include <stddef.h>

#include "geometry/surface.h"

double tf_winding_number(const tf_surface *s, const double p[3]);

/* w[k] for the n points p[3k .. 3k+2] (OpenMP over points). */
void tf_winding_numbers(const tf_surface *s, const double *p, size_t n, double *w);

#endif /* TF_WINDING_H */
