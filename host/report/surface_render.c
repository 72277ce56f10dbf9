/*
 * surface_render.c — shaded surface pictures in depth order
 * (surface_render.h).
 */
#include "report/surface_render.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/plot.h"

typedef struct facet {
    double depth; /* of the centroid; larger is nearer the camera */
    size_t t;
} facet;

static int far_first(const void *a, const void *b)
{
    const facet *p = a, *q = b;
    if (p->depth != q->depth) {
        return p->depth < q->depth ? -1 : 1;
    }
    return (p->t > q->t) - (p->t < q->t);
}

/* Camera frame: right, up, and towards the camera (right-handed). */
static void camera(const tf_report_render *r, double right[3], double up[3], double toward[3])
{
    double az = r->azimuth * M_PI / 180, el = r->elevation * M_PI / 180;
    toward[0] = cos(el) * cos(az);
    toward[1] = cos(el) * sin(az);
    toward[2] = sin(el);
    right[0] = -sin(az);
    right[1] = cos(az);
    right[2] = 0;
    up[0] = -sin(el) * cos(az);
    up[1] = -sin(el) * sin(az);
    up[2] = cos(el);
}

/* Node i in camera coordinates (x right, y up, z towards the camera). */
static void project(const tf_report_render *r, const double basis[3][3], size_t i, double c[3])
{
    double p[3];
    for (int a = 0; a < 3; ++a) {
        p[a] = r->xyz[3 * i + (size_t)a] + (r->u ? r->u[3 * i + (size_t)a] : 0);
    }
    p[2] *= r->zscale;
    for (int k = 0; k < 3; ++k) {
        c[k] = basis[k][0] * p[0] + basis[k][1] * p[1] + basis[k][2] * p[2];
    }
}

/* The facets to draw, far first; back faces dropped on a closed surface. */
static facet *order(const tf_report_render *r, const double basis[3][3], size_t *n)
{
    facet *f = malloc((r->ntri + 1) * sizeof *f);
    *n = 0;
    for (size_t t = 0; f != NULL && t < r->ntri; ++t) {
        double c[3][3];
        for (int k = 0; k < 3; ++k) {
            project(r, basis, r->tri[3 * t + (size_t)k], c[k]);
        }
        double facing = (c[1][0] - c[0][0]) * (c[2][1] - c[0][1]) -
                        (c[1][1] - c[0][1]) * (c[2][0] - c[0][0]);
        if (r->closed && !(facing > 0)) {
            continue;
        }
        f[*n].depth = (c[0][2] + c[1][2] + c[2][2]) / 3;
        f[*n].t = t;
        (*n)++;
    }
    if (f != NULL) {
        qsort(f, *n, sizeof *f, far_first);
    }
    return f;
}

static void settings(FILE *gp, const tf_report_render *r)
{
    fprintf(gp,
            "set view 0,0,1.4,1\nset view equal xy\nunset border\nunset tics\nunset key\n"
            "set xlabel ''\nset ylabel ''\nset zlabel ''\n"
            "set pm3d scansforward corners2color mean\n"
            "set pm3d lighting primary 0.45 specular 0.15\n"
            "set palette %s\nset cbrange [%.9g:%.9g]\n",
            r->palette, r->vmin, r->vmax > r->vmin ? r->vmax : r->vmin + 1e-9);
    if (r->cblabel != NULL) {
        fprintf(gp, "set colorbox vertical user origin 0.88,0.2 size 0.025,0.6\n"
                    "set cbtics\nset cblabel '%s'\n",
                r->cblabel);
    } else {
        fprintf(gp, "unset colorbox\n");
    }
    fputs("set title '", gp);
    for (const char *c = r->title; *c != '\0'; ++c) { /* '' is a quote in gnuplot's strings */
        fputs(*c == '\'' ? "''" : (char[2]){*c, '\0'}, gp);
    }
    fputs("'\n", gp);
}

int tf_report_render_png(tf_ctx *ctx, const char *path, const tf_report_render *r)
{
    double basis[3][3];
    camera(r, basis[0], basis[1], basis[2]);
    size_t n;
    facet *f = order(r, basis, &n);
    if (f == NULL || n == 0) {
        free(f);
        return tf_fail(ctx, "%s: %s", path, f ? "no facet faces the camera" : "out of memory");
    }
    tf_plot p;
    if (tf_plot_open(ctx, &p, path, r->width, r->height) != 0) {
        free(f);
        return -1;
    }
    settings(p.gp, r);
    fprintf(p.gp, "splot '-' using 1:2:3:4 with pm3d\n");
    /* Each triangle is a degenerate pm3d quadrangle: scans (a, b) and (c, c). */
    for (size_t k = 0; k < n; ++k) {
        const size_t *v = r->tri + 3 * f[k].t;
        const size_t order4[4] = {v[0], v[1], v[2], v[2]};
        for (int q = 0; q < 4; ++q) {
            double c[3];
            project(r, basis, order4[q], c);
            double val = r->tri_value ? r->tri_value[f[k].t] : r->value[order4[q]];
            fprintf(p.gp, "%.6g %.6g %.6g %.6g\n%s", c[0], c[1], c[2], val,
                    q == 1 ? "\n" : q == 3 ? "\n\n" : "");
        }
    }
    fprintf(p.gp, "e\n");
    free(f);
    return tf_plot_close(ctx, &p);
}
