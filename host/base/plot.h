/*
 * plot.h — PNG plots through gnuplot (a pipe to the gnuplot program; data
 * inline as gnuplot data blocks).  The image is written to a temporary
 * file and renamed when gnuplot succeeded, like every output of the tool.
 */
#ifndef TF_PLOT_H
#define TF_PLOT_H

#include <stddef.h>
#include <stdio.h>

#include "base/context.h"

typedef struct tf_plot {
    FILE *gp;
    char path[4096], tmp[4200];
} tf_plot;

/* 1 when a gnuplot with the pngcairo terminal can be run. */
int tf_plot_available(void);

/* Starts a width x height PNG at path; write gnuplot commands to p->gp.
 * Returns 0, or -1 with a message. */
int tf_plot_open(tf_ctx *ctx, tf_plot *p, const char *path, int width, int height);

/* Finishes the plot; returns 0, or -1 with a message (nothing left behind). */
int tf_plot_close(tf_ctx *ctx, tf_plot *p);

#endif /* TF_PLOT_H */
