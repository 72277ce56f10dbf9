/*
 * history.h — a load history (scene key `history:`, docs/scene-format.md):
 * how the loads change in time for a time-dependent solve, and its samples
 * at the time step.
 *
 * Segments describe a factor a(t), 0 at rest, that multiplies the contact
 * force and the problem's loads and prescribed displacements:
 *   step      jumps to `to` (instantaneous)
 *   release   jumps to 0
 *   ramp      goes linearly to `to` in `time` seconds
 *   hold      stays for `time` seconds
 *   sinusoid  adds amplitude sin(2 pi (t - t0) / period) to the level it
 *             starts from, for `time` seconds
 * and a(t) keeps its last value after the last segment.  A table instead
 * gives the contact force itself, (t, fx, fy, fz) rows, linear in between
 * (the problem's loads then act fully from t = 0).
 */
#ifndef TF_HISTORY_H
#define TF_HISTORY_H

#include <stddef.h>

typedef enum tf_segment_kind {
    TF_SEG_STEP,
    TF_SEG_RELEASE,
    TF_SEG_RAMP,
    TF_SEG_HOLD,
    TF_SEG_SINUSOID,
} tf_segment_kind;

typedef struct tf_segment {
    tf_segment_kind kind;
    double to;        /* STEP, RAMP */
    double time;      /* RAMP, HOLD, SINUSOID: s */
    double amplitude; /* SINUSOID */
    double period;    /* SINUSOID: s */
} tf_segment;

typedef struct tf_history {
    int present;
    double dt, duration; /* s */
    double force[3];     /* N at the contact site, times a(t) (segments) */
    int contact;         /* site index, -1 without one */
    tf_segment *seg;
    size_t n_seg;
    double *table;       /* rows of (t, fx, fy, fz), t increasing; NULL: segments */
    size_t n_rows;
} tf_history;

/* The states a time-dependent solve goes through: times t (s, non-
 * decreasing: an instantaneous jump is a sample at the same time as the one
 * before), the factor of the problem's loads and the contact force. */
typedef struct tf_samples {
    size_t n;
    double *t, *scale;
    double (*force)[3];
} tf_samples;

/* Samples at every multiple of dt up to the duration and at every jump
 * (from rest at t = 0).  Returns 0, or -1 when out of memory. */
int tf_history_sample(const tf_history *h, tf_samples *s);
void tf_samples_free(tf_samples *s);

/* The factor a(t) just after t (segments). */
double tf_history_factor(const tf_history *h, double t);

void tf_history_release(tf_history *h);

#endif /* TF_HISTORY_H */
