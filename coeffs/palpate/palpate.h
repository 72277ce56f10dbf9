/*
 * palpate.h — make demo-palpate (coeffs/demo_palpate.mk): a probe palpating
 * the liver's anterior region through the firmware's region calls, replayed
 * against true solves.  The parts of the program:
 *
 *   palpate.c          the run: scene, solver, fit, models, verdict
 *   palpate_models.c   the fitted region as device models (the model
 *                      layer's builders, model/region_model.h) and their
 *                      rest surface
 *   palpate_path.c     the instruments' tip paths
 *   palpate_replay.c   the firmware loop and its replay against site solves
 *   palpate_pictures.c the force map and the deformed surfaces (PNG, VTK)
 *
 * palpate_models.c builds the model layer's grid of a region
 * (tf_region_grid) from plain numbers.
 */
#ifndef PALPATE_H
#define PALPATE_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "model/model.h"
#include "tfit.h"

/* A region's grid for the device: the chart's frame and the sites. */
typedef struct palpate_grid {
    double origin[3], rot[9]; /* o (the domain's corner), R (rows e1, e2, n) */
    unsigned nx, ny;
    double ha, hb; /* site spacing, mm */
} palpate_grid;

/* The law's rest surface point at grid coordinates g (chart frame, mm). */
void palpate_rest_point(const tf_model *law, const double g[2], double x[3]);

/* Chart <-> scene frame. */
void palpate_to_scene(const palpate_grid *g, const double q[3], double p[3]);
void palpate_to_chart(const palpate_grid *g, const double p[3], double q[3]);

/* ---- the instruments' paths (palpate_path.c) ---------------------------- */

/* One tick of the script: the tips (scene frame, mm) and whether the
 * second instrument is in the scene (then both go through the pair calls). */
typedef struct palpate_tick {
    float tip[2][3];
    int two;
} palpate_tick;

/* The script over the law's region: press, slide, lift, move, press
 * elsewhere, slide, lift, with a second instrument pressing, holding and
 * lifting for part of the second contact; depth below the rest surface
 * (mm).  Returns the number of ticks written to t (at most max). */
size_t palpate_script(const tf_model *law, const palpate_grid *g, double depth,
                      palpate_tick *t, size_t max);

#endif /* PALPATE_H */
