/*
 * history.c — load histories and their samples (history.h).
 */
#include "problem/history.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Length of a segment in time. */
static double seg_time(const tf_segment *g)
{
    return g->kind == TF_SEG_STEP || g->kind == TF_SEG_RELEASE ? 0 : g->time;
}

/* The factor at the end of a segment that starts at value v. */
static double seg_end(const tf_segment *g, double v)
{
    switch (g->kind) {
    case TF_SEG_STEP:
    case TF_SEG_RAMP:
        return g->to;
    case TF_SEG_RELEASE:
        return 0;
    case TF_SEG_HOLD:
        return v;
    case TF_SEG_SINUSOID:
        return v + g->amplitude * sin(2 * M_PI * g->time / g->period);
    }
    return v;
}

/* a(t), the limit from the right (right) or the left. */
static double factor_at(const tf_history *h, double t, int right)
{
    double start = 0, v = 0;
    for (size_t k = 0; k < h->n_seg; ++k) {
        const tf_segment *g = &h->seg[k];
        double len = seg_time(g);
        if (len == 0) { /* a jump at start */
            if (t > start || (t == start && right)) {
                v = seg_end(g, v);
                continue;
            }
            return v;
        }
        if (t < start + len || (t == start + len && !right)) {
            if (t <= start) {
                return v;
            }
            double s = t - start;
            switch (g->kind) {
            case TF_SEG_RAMP:
                return v + (g->to - v) * s / len;
            case TF_SEG_SINUSOID:
                return v + g->amplitude * sin(2 * M_PI * s / g->period);
            default:
                return v;
            }
        }
        v = seg_end(g, v);
        start += len;
    }
    return v;
}

double tf_history_factor(const tf_history *h, double t) { return factor_at(h, t, 1); }

/* The table's contact force at t (linear, held beyond its ends). */
static void table_force(const tf_history *h, double t, double f[3])
{
    const double *r = h->table;
    size_t n = h->n_rows, k = 0;
    if (t <= r[0]) {
        memcpy(f, r + 1, 3 * sizeof *f);
        return;
    }
    while (k + 1 < n && r[4 * (k + 1)] < t) {
        k++;
    }
    if (k + 1 >= n) {
        memcpy(f, r + 4 * (n - 1) + 1, 3 * sizeof *f);
        return;
    }
    double t0 = r[4 * k], t1 = r[4 * (k + 1)], w = (t - t0) / (t1 - t0);
    for (int a = 0; a < 3; ++a) {
        f[a] = r[4 * k + 1 + a] + w * (r[4 * (k + 1) + 1 + a] - r[4 * k + 1 + a]);
    }
}

static int add(tf_samples *s, size_t *cap, double t, double scale, const double f[3])
{
    if (s->n == *cap) {
        *cap = 2 * *cap + 16;
        double *nt = realloc(s->t, *cap * sizeof *nt), *ns = realloc(s->scale, *cap * sizeof *ns);
        double(*nf)[3] = realloc(s->force, *cap * sizeof *nf);
        s->t = nt ? nt : s->t;
        s->scale = ns ? ns : s->scale;
        s->force = nf ? nf : s->force;
        if (!nt || !ns || !nf) {
            return -1;
        }
    }
    s->t[s->n] = t;
    s->scale[s->n] = scale;
    memcpy(s->force[s->n], f, sizeof s->force[s->n]);
    s->n++;
    return 0;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The jump times within [0, duration] (sorted, unique), in *out. */
static size_t jump_times(const tf_history *h, double **out)
{
    size_t n = 0;
    *out = malloc((h->n_seg + h->n_rows + 2) * sizeof **out);
    if (*out == NULL) {
        return SIZE_MAX;
    }
    if (h->table != NULL) {
        (*out)[n++] = 0; /* from rest to the table's first force */
    }
    double start = 0;
    for (size_t k = 0; h->table == NULL && k < h->n_seg; ++k) {
        if (seg_time(&h->seg[k]) == 0 && start <= h->duration) {
            (*out)[n++] = start;
        }
        start += seg_time(&h->seg[k]);
    }
    qsort(*out, n, sizeof **out, cmp_double);
    size_t u = 0;
    for (size_t k = 0; k < n; ++k) {
        if (u == 0 || (*out)[k] != (*out)[u - 1]) {
            (*out)[u++] = (*out)[k];
        }
    }
    return u;
}

/* The state at time t, from the left or the right. */
static void state_at(const tf_history *h, double t, int right, double *scale, double f[3])
{
    if (h->table != NULL) {
        *scale = 1;
        if (t == 0 && !right) {
            *scale = 0;
            f[0] = f[1] = f[2] = 0;
        } else {
            table_force(h, t, f);
        }
        return;
    }
    *scale = factor_at(h, t, right);
    for (int a = 0; a < 3; ++a) {
        f[a] = *scale * h->force[a];
    }
}

int tf_history_sample(const tf_history *h, tf_samples *s)
{
    memset(s, 0, sizeof *s);
    double *jumps;
    size_t nj = jump_times(h, &jumps), cap = 0;
    if (nj == SIZE_MAX) {
        return -1;
    }
    size_t steps = (size_t)llround(h->duration / h->dt), nt = 0;
    double *times = malloc((steps + nj + 1) * sizeof *times);
    if (times == NULL) {
        free(jumps);
        return -1;
    }
    for (size_t k = 1; k <= steps; ++k) {
        times[nt++] = k == steps ? h->duration : (double)k * h->dt;
    }
    memcpy(times + nt, jumps, nj * sizeof *jumps);
    nt += nj;
    qsort(times, nt, sizeof *times, cmp_double);
    int rc = 0;
    size_t j = 0;
    double sc, f[3], last = 0;
    for (size_t k = 0; k < nt && rc == 0; ++k) {
        double t = times[k];
        if (k > 0 && t == times[k - 1]) {
            continue;
        }
        while (j < nj && jumps[j] < t) {
            j++;
        }
        if (j < nj && jumps[j] == t) { /* reach the jump continuously, then take it */
            if (t > last) {
                state_at(h, t, 0, &sc, f);
                rc = add(s, &cap, t, sc, f);
            }
        }
        if (rc == 0) {
            state_at(h, t, 1, &sc, f);
            rc = add(s, &cap, t, sc, f);
        }
        last = t;
    }
    free(jumps);
    free(times);
    if (rc != 0) {
        tf_samples_free(s);
    }
    return rc;
}

void tf_samples_free(tf_samples *s)
{
    free(s->t);
    free(s->scale);
    free(s->force);
    memset(s, 0, sizeof *s);
}

void tf_history_release(tf_history *h)
{
    free(h->seg);
    free(h->table);
    memset(h, 0, sizeof *h);
}
