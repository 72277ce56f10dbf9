/*
 * region_sweep.h — the speed/accuracy trade of a contact region's models
 * (docs/tradeoff.md, "Contact regions"): the spacings tissuefit fit's
 * density rule fits (fitting/region_fit.h, the device's rule: at most
 * TFIT_REGION_MAX_RANK modes) and, at each, the surface at ranks 1, 2, 4
 * ... up to the modes there are and the device's cap, each with its near
 * field: the law's and the surface's held-out errors at the spacing's cell
 * centres (sites never fitted), the two-instrument coupling error, table
 * bytes and the Cortex-M4F cycle bounds of a law tick and a surface update
 * (the device models built as tissuefit fit builds them).
 */
#ifndef TF_REGION_SWEEP_H
#define TF_REGION_SWEEP_H

#include <stddef.h>
#include <stdio.h>

#include "base/context.h"
#include "problem/problem.h"
#include "solvers/solver.h"

typedef struct tf_region_sweep_row {
    unsigned nx, ny;
    double h;           /* site spacing, mm (the larger axis') */
    unsigned rank, near;
    double force;       /* law: worst force on the envelope's sphere, fraction of R_F */
    double surface;     /* largest output error, fraction of the peak */
    double surface_rms;
    double coupling;    /* fraction of R_F */
    unsigned law_bytes, surface_bytes;
    double law_cycles, surface_cycles; /* Cortex-M4F upper bounds */
    int chosen;         /* the spacing and rank tissuefit fit emits */
} tf_region_sweep_row;

typedef struct tf_region_sweep {
    tf_region_sweep_row *row;
    size_t n;
    double peak;        /* mm, of the last spacing */
    double seconds;     /* the fit's regeneration time, last spacing */
} tf_region_sweep;

/* Sweeps contact region `contact` of p with solver s (affine).  Returns 0,
 * or -1 with the message. */
int tf_region_sweep_run(tf_ctx *ctx, const tf_problem *p, tf_solver *s, int contact,
                        tf_region_sweep *out);
void tf_region_sweep_free(tf_region_sweep *sw);

/* The rows as CSV (a header line, one line a row), and as a Markdown
 * table. */
int tf_region_sweep_csv(const tf_region_sweep *sw, FILE *f);
int tf_region_sweep_markdown(const tf_region_sweep *sw, FILE *f);
/* A PNG of the surface error against the surface table's bytes, one
 * series per spacing, the chosen row circled (gnuplot).  Returns 0, or -1
 * with the message. */
int tf_region_sweep_plot(tf_ctx *ctx, const tf_region_sweep *sw, const char *path);

#endif /* TF_REGION_SWEEP_H */
