/*
 * surface_pieces.h — the connected pieces of a triangle surface
 * (triangles joined through shared vertices).
 */
#ifndef TF_SURFACE_PIECES_H
#define TF_SURFACE_PIECES_H

#include <stddef.h>

#include "geometry/surface.h"

/* piece[t] = the piece of triangle t, numbered 0, 1, ... in order of their
 * first triangle; *npieces their count.  Returns 0, or -1 when out of
 * memory. */
int tf_surface_pieces(const tf_surface *s, size_t *piece, size_t *npieces);

#endif /* TF_SURFACE_PIECES_H */
