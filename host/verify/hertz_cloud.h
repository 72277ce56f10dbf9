/*
 * hertz_cloud.h — particle clouds for the Hertz test (seed 004 §3.3): a
 * quarter of a block [-L, L]^2 x [-L, 0] (top face z = 0, the indenter on
 * the z axis), x, y >= 0, with the planes x = 0 and y = 0 as mirror planes;
 * bottom and sides clamped as in seed 004's FEBio set-up.
 *
 * The particles form nested grids: spacing h0 in the box [0, L0]^2 x
 * [-L0, 0] (L0 = cells h0); level l = 1 .. levels - 1 is a grid of spacing
 * h_l = ratio^l h0 over the box of L_l = cells h_l, without its points
 * inside the box before or closer to it than h_l / 2.  So the cloud is
 * fine under the indenter and coarse far away (the block's half-width is
 * L = L_(levels-1)); levels = 1 is a uniform grid, ratio 2 nests the grids
 * exactly (every coarse point outside is a whole coarse spacing from the
 * fine box).
 *
 * Volumes are those of the particles' Voronoi cells within the quarter
 * block, measured by sampling each level's region at h_l / 4 (cells of
 * the sampling grid given to the particle nearest their centre, ties by
 * index, the part of a cell inside the finer box left out): exact for a
 * uniform grid (the tributary volumes), and summing to the block's volume.
 */
#ifndef TF_HERTZ_CLOUD_H
#define TF_HERTZ_CLOUD_H

#include <stddef.h>

typedef struct tf_hertz_cloud {
    size_t n;
    double *X;            /* 3n */
    double *volume;       /* n */
    unsigned char *fixed; /* n */
    double L;             /* half-width and depth of the block, mm */
    double volume_total;  /* of the quarter block, mm^3 */
} tf_hertz_cloud;

/* Returns 0, or -1 when out of memory or the arguments make no cloud
 * (cells >= 2, levels >= 1, h0 > 0, ratio in [1.2, 4]). */
int tf_hertz_cloud_make(tf_hertz_cloud *hc, double h0, int cells, int levels, double ratio);
void tf_hertz_cloud_free(tf_hertz_cloud *hc);

#endif /* TF_HERTZ_CLOUD_H */
