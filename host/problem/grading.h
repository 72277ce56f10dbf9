/*
 * grading.h — the grid lines of a graded box axis: nodes denser near the
 * places a solution varies fastest (a load patch's edges, a clamped face)
 * and sparser away from them, for the same node count.
 *
 * Along one axis the spacing grows linearly with the distance d from the
 * nearest attractor interval,
 *
 *     h(x) ∝ 1 + (ratio - 1) d(x) / d_max,
 *
 * from its smallest value on the attractors to ratio times that at the
 * point of the axis farthest from all of them (d_max).  The n grid lines
 * are equidistant in the stretched coordinate ∫ dx / h (trapezoid rule on
 * 256 sub-steps per interval, inverted linearly: only + - * /, so the lines
 * are the same bits on every machine).  ratio 1, or no attractor, gives the
 * uniform axis.
 */
#ifndef TF_GRADING_H
#define TF_GRADING_H

#include <stddef.h>

#define TF_CLOUD_GRADING_MAX 16

/* Grading of a box grid, per axis. */
typedef struct tf_cloud_grading {
    double ratio[3];                 /* largest / smallest spacing per axis, >= 1 */
    size_t n[3];                     /* attractor intervals per axis */
    double at[3][TF_CLOUD_GRADING_MAX][2]; /* [lo, hi] on that axis (lo = hi: a plane), mm */
} tf_cloud_grading;

/* Adds the attractor interval [a0, a1] (clamped to [lo, hi]) to axis a,
 * unless it is there already or the axis is full (then it is dropped: 16
 * per axis are plenty).  a0 > a1 are swapped. */
void tf_cloud_grading_add(tf_cloud_grading *g, int a, double a0, double a1, double lo, double hi);

/* The n >= 2 grid lines x[0] = lo < ... < x[n-1] = hi of an axis graded by
 * ratio towards the na intervals at[].  Returns 0, or -1 when out of
 * memory. */
int tf_cloud_grading_axis(double lo, double hi, unsigned n, double ratio, const double (*at)[2],
                    size_t na, double *x);

/* The interval i of n >= 2 ascending lines with lines[i] <= x < lines[i+1],
 * clamped to 0 .. n - 2 (binary search). */
unsigned tf_cloud_lines_interval(const double *lines, unsigned n, double x);

#endif /* TF_GRADING_H */
