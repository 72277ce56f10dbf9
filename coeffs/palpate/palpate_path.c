/*
 * palpate_path.c — the instruments' tip paths of make demo-palpate
 * (palpate.h), at the servo's 1 kHz: one tick a millisecond.
 *
 * Instrument 1: 3 mm above site A, it comes down (100 ticks), presses to
 * the depth (300), holds (100), slides to A' pressed (800), lifts to 3 mm
 * above (300), moves in the air to B (200), presses at B (300), slides to
 * B' pressed (800) and lifts (300).  Instrument 2 joins at C for the last
 * three phases: it presses while instrument 1 presses at B, holds while
 * instrument 1 slides, and lifts with it; during those 1,400 ticks both
 * go through the two-instrument calls.  Sites are fractions of the
 * region's domain, chosen so that the tips (8 mm discs) stay at least
 * 25 mm apart.
 */
#include <math.h>

#include "coeffs/palpate/palpate.h"

#define ABOVE 3.0 /* mm above the rest surface, out of contact */

/* A phase: from (a, b, depth) to (a, b, depth) over n ticks (fractions of
 * the domain; depth as a fraction of the pressing depth, < 0 above). */
typedef struct phase {
    double from[3], to[3];
    unsigned n;
} phase;

static const phase path1[] = {
    {{0.30, 0.30, -1}, {0.30, 0.30, 0}, 100},   /* come down to the surface at A */
    {{0.30, 0.30, 0}, {0.30, 0.30, 1}, 300},    /* press */
    {{0.30, 0.30, 1}, {0.30, 0.30, 1}, 100},    /* hold */
    {{0.30, 0.30, 1}, {0.70, 0.40, 1}, 800},    /* slide to A' */
    {{0.70, 0.40, 1}, {0.70, 0.40, -1}, 300},   /* lift */
    {{0.70, 0.40, -1}, {0.30, 0.70, -1}, 200},  /* move to B in the air */
    {{0.30, 0.70, -1}, {0.30, 0.70, 1}, 300},   /* press at B */
    {{0.30, 0.70, 1}, {0.45, 0.85, 1}, 800},    /* slide to B' */
    {{0.45, 0.85, 1}, {0.45, 0.85, -1}, 300},   /* lift */
};
#define PAIR_FROM 6 /* instrument 2 takes part from phase 6 on */
static const phase path2[] = {
    {{0.75, 0.75, -1}, {0.75, 0.75, 1}, 300},   /* press at C */
    {{0.75, 0.75, 1}, {0.75, 0.75, 1}, 800},    /* hold */
    {{0.75, 0.75, 1}, {0.75, 0.75, -1}, 300},   /* lift */
};

/* The tip at (a, b) fractions of the domain and depth fraction d. */
static void tip_at(const tf_model *law, const palpate_grid *g, double depth, const double f[3],
                   float tip[3])
{
    const double gg[2] = {f[0] * (g->nx - 1), f[1] * (g->ny - 1)};
    double x[3], p[3];
    palpate_rest_point(law, gg, x);
    x[2] -= f[2] >= 0 ? f[2] * depth : f[2] * ABOVE; /* f[2] < 0: above */
    palpate_to_scene(g, x, p);
    for (int i = 0; i < 3; ++i) {
        tip[i] = (float)p[i];
    }
}

static void lerp(const phase *ph, unsigned k, double f[3])
{
    double t = (k + 1.0) / ph->n;
    for (int i = 0; i < 3; ++i) {
        f[i] = ph->from[i] + t * (ph->to[i] - ph->from[i]);
    }
}

size_t palpate_script(const tf_model *law, const palpate_grid *g, double depth,
                      palpate_tick *t, size_t max)
{
    size_t n = 0;
    unsigned p2 = 0, k2 = 0;
    for (size_t p = 0; p < sizeof path1 / sizeof path1[0]; ++p) {
        for (unsigned k = 0; k < path1[p].n && n < max; ++k, ++n) {
            double f[3];
            lerp(&path1[p], k, f);
            tip_at(law, g, depth, f, t[n].tip[0]);
            t[n].two = p >= PAIR_FROM && p2 < sizeof path2 / sizeof path2[0];
            if (t[n].two) {
                lerp(&path2[p2], k2, f);
                tip_at(law, g, depth, f, t[n].tip[1]);
                if (++k2 == path2[p2].n) {
                    k2 = 0;
                    ++p2;
                }
            } else {
                t[n].tip[1][0] = t[n].tip[1][1] = t[n].tip[1][2] = 0.0f;
            }
        }
    }
    return n;
}
