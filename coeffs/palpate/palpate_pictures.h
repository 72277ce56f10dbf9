/*
 * palpate_pictures.h — make demo-palpate's pictures: the force map over the
 * region and the deformed surface at a few ticks, as PNG (gnuplot) and VTK
 * (ParaView).
 */
#ifndef PALPATE_PICTURES_H
#define PALPATE_PICTURES_H

#include "coeffs/palpate/palpate_replay.h"

/* The press depth (mm) at which the largest |F| of one tick from a reset
 * state over an n x n grid of sites is `fraction` of the envelope radius. */
double palpate_depth(const palpate_models *m, double fraction, unsigned n);

/* The force map: |F| (N) of one tick from a reset state with the tip at
 * `depth` (mm) below the rest surface, over an n x n grid of sites of the
 * region, with the instruments' paths in contact drawn over it:
 * DIR/force_map.png and DIR/force_map.vtk.  Returns 0, or -1 with the
 * message; *lo, *hi the smallest and largest |F| of the map. */
int palpate_force_map(tf_ctx *ctx, const char *dir, const palpate_models *m, double depth,
                      unsigned n, const palpate_tick *t, const palpate_run *run, double *lo,
                      double *hi);

/* The deformed surface (the outputs: rest position + the firmware's
 * displacement) at the display frames frames[0..nf): DIR/surface.png
 * (one panel per frame, the outputs in the chart's (a, b) plane coloured
 * by |u|) and DIR/surface_TICK.vtk (points, the displacement as a vector:
 * ParaView's Warp By Vector). */
int palpate_surfaces(tf_ctx *ctx, const char *dir, const palpate_models *m, const tf_problem *p,
                     const palpate_tick *t, const palpate_run *run, const size_t *frames,
                     size_t nf);

#endif /* PALPATE_PICTURES_H */
