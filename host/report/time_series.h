/*
 * time_series.h — the displacements of a time-dependent solve, step by step:
 * one CSV (step,time,node,x,y,z,ux,uy,uz; mm, s, %.17g) and a ParaView time
 * series, a .pvd collection naming one .vtu per step (displacement_out.h).
 */
#ifndef TF_TIME_SERIES_H
#define TF_TIME_SERIES_H

#include <stddef.h>
#include <stdio.h>

#include "problem/nodes.h"

/* Every node at each of n steps (times t, displacements u: 3N x n). */
void tf_report_series_csv(FILE *fp, const tf_cloud *c, size_t n, const double *t,
                          const double *u);

/* The .pvd collection of n steps whose .vtu files are named files[k]
 * (written into the collection as given: relative to the .pvd). */
void tf_report_series_pvd(FILE *fp, size_t n, const double *t, const char *const *files);

#endif /* TF_TIME_SERIES_H */
