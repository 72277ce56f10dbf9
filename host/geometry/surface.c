/*
 * surface.c — triangle surface storage and its integral quantities
 * (surface.h).
 */
#include "geometry/surface.h"

#include "geometry/vec3.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int tf_surface_alloc(tf_surface *s, size_t nv, size_t nt)
{
    memset(s, 0, sizeof *s);
    s->xyz = malloc((3 * nv + 1) * sizeof *s->xyz);
    s->source = malloc((nv + 1) * sizeof *s->source);
    s->tri = malloc((3 * nt + 1) * sizeof *s->tri);
    if (s->xyz == NULL || s->source == NULL || s->tri == NULL) {
        tf_surface_free(s);
        return -1;
    }
    s->nv = nv;
    s->nt = nt;
    for (size_t i = 0; i < nv; ++i) {
        s->source[i] = (long)i;
    }
    return 0;
}

void tf_surface_free(tf_surface *s)
{
    free(s->xyz);
    free(s->source);
    free(s->tri);
    free(s->tri_parent);
    memset(s, 0, sizeof *s);
}

void tf_surface_bbox(const tf_surface *s, double lo[3], double hi[3])
{
    for (int a = 0; a < 3; ++a) {
        lo[a] = s->nv ? INFINITY : 0;
        hi[a] = s->nv ? -INFINITY : 0;
    }
    for (size_t i = 0; i < s->nv; ++i) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = fmin(lo[a], s->xyz[3 * i + a]);
            hi[a] = fmax(hi[a], s->xyz[3 * i + a]);
        }
    }
}

/* Corners of triangle t relative to the origin o. */
static void corners(const tf_surface *s, size_t t, const double o[3], double p[3][3])
{
    for (int k = 0; k < 3; ++k) {
        const double *x = s->xyz + 3 * s->tri[3 * t + k];
        for (int a = 0; a < 3; ++a) {
            p[k][a] = x[a] - o[a];
        }
    }
}

void tf_surface_centre(const tf_surface *s, double o[3])
{
    double lo[3], hi[3];
    tf_surface_bbox(s, lo, hi);
    for (int a = 0; a < 3; ++a) {
        o[a] = 0.5 * (lo[a] + hi[a]);
    }
}

double tf_surface_cone_volume(const tf_surface *s, size_t t, const double o[3])
{
    double p[3][3];
    corners(s, t, o, p);
    return tf_v3_det(p[0], p[1], p[2]) / 6;
}

double tf_surface_volume(const tf_surface *s)
{
    double o[3], sum = 0;
    tf_surface_centre(s, o);
    for (size_t t = 0; t < s->nt; ++t) {
        sum += tf_surface_cone_volume(s, t, o);
    }
    return sum;
}

double tf_surface_area(const tf_surface *s)
{
    double sum = 0;
    for (size_t t = 0; t < s->nt; ++t) {
        const size_t *v = s->tri + 3 * t;
        sum += tf_v3_area(s->xyz + 3 * v[0], s->xyz + 3 * v[1], s->xyz + 3 * v[2]);
    }
    return sum;
}

void tf_surface_reverse(tf_surface *s)
{
    for (size_t t = 0; t < s->nt; ++t) {
        size_t v = s->tri[3 * t + 1];
        s->tri[3 * t + 1] = s->tri[3 * t + 2];
        s->tri[3 * t + 2] = v;
    }
}

int tf_surface_select(tf_surface *s, const unsigned char *keep)
{
    const size_t USED = SIZE_MAX - 1;
    size_t *renum = malloc((s->nv + 1) * sizeof *renum);
    if (renum == NULL) {
        return -1;
    }
    for (size_t i = 0; i < s->nv; ++i) {
        renum[i] = SIZE_MAX;
    }
    size_t nt = 0, nv = 0;
    for (size_t t = 0; t < s->nt; ++t) {
        if (keep[t]) {
            for (int k = 0; k < 3; ++k) {
                renum[s->tri[3 * t + k]] = USED;
            }
        }
    }
    for (size_t i = 0; i < s->nv; ++i) {
        if (renum[i] == USED) {
            renum[i] = nv;
            memmove(s->xyz + 3 * nv, s->xyz + 3 * i, 3 * sizeof *s->xyz);
            s->source[nv] = s->source[i];
            nv++;
        }
    }
    for (size_t t = 0; t < s->nt; ++t) {
        if (keep[t]) {
            for (int k = 0; k < 3; ++k) {
                s->tri[3 * nt + k] = renum[s->tri[3 * t + k]];
            }
            if (s->tri_parent != NULL) {
                s->tri_parent[nt] = s->tri_parent[t];
            }
            nt++;
        }
    }
    free(renum);
    s->nv = nv;
    s->nt = nt;
    return 0;
}
