/*
 * organ_pictures.c — rest and deformed organ pictures (organ_pictures.h).
 */
#include "report/organ_pictures.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "problem/inclusions.h"
#include "report/surface_render.h"

/* Outward normal at surface node c: the area-weighted mean of its
 * triangles' normals. */
static void vertex_normal(const tf_mesh_geometry *m, size_t c, double n[3])
{
    n[0] = n[1] = n[2] = 0;
    for (size_t t = 0; t < m->tm.ntri; ++t) {
        const size_t *v = m->tm.tri + 3 * t;
        if (v[0] != c && v[1] != c && v[2] != c) {
            continue;
        }
        const double *a = m->tm.xyz + 3 * v[0], *b = m->tm.xyz + 3 * v[1],
                     *d = m->tm.xyz + 3 * v[2];
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        n[0] += u[1] * w[2] - u[2] * w[1];
        n[1] += u[2] * w[0] - u[0] * w[2];
        n[2] += u[0] * w[1] - u[1] * w[0];
    }
}

/* Whether surface triangle t lies over a material region: the line from
 * its centroid along its inward normal meets an inclusion within
 * OVER_DEPTH_MM (sampled every half millimetre): the surface a probe
 * presses to feel it. */
#define OVER_DEPTH_MM 50.0
static int over_inclusion(const tf_problem *p, const tf_mesh_geometry *m, size_t t)
{
    const size_t *v = m->tm.tri + 3 * t;
    const double *a = m->tm.xyz + 3 * v[0], *b = m->tm.xyz + 3 * v[1], *d = m->tm.xyz + 3 * v[2];
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
    double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0)) {
        return 0;
    }
    for (double s = 0; s <= OVER_DEPTH_MM; s += 0.5) {
        double x[3];
        for (int k = 0; k < 3; ++k) {
            x[k] = (a[k] + b[k] + d[k]) / 3 - s * n[k] / len;
        }
        for (size_t k = 0; k < p->n_inclusions; ++k) {
            if (tf_inclusion_holds(&p->inclusions[k], x)) {
                return 1;
            }
        }
    }
    return 0;
}

static void camera_for(const tf_problem *p, const tf_report_organ_view *v, tf_report_render *r)
{
    if (p->n_contacts == 0) { /* nothing to face: the default view, or the one asked */
        r->azimuth = isnan(v->azimuth) ? 300 : v->azimuth;
        r->elevation = isnan(v->elevation) ? 30 : v->elevation;
        return;
    }
    const tf_mesh_geometry *m = tf_problem_mesh(p);
    double n[3];
    vertex_normal(m, p->contacts[v->contact].node, n);
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    double el = len > 0 ? asin(n[2] / len) * 180 / M_PI : 30;
    r->azimuth = isnan(v->azimuth) ? atan2(n[1], n[0]) * 180 / M_PI + 35 : v->azimuth;
    r->elevation = isnan(v->elevation) ? fmax(-80, fmin(80, el + 20)) : v->elevation;
}

static void base(const tf_problem *p, const tf_report_organ_view *v, tf_report_render *r)
{
    const tf_mesh_geometry *m = tf_problem_mesh(p);
    *r = (tf_report_render){.xyz = m->tm.xyz, .tri = m->tm.tri, .ntri = m->tm.ntri, .closed = 1,
                     .zscale = 1, .width = 1000, .height = 800};
    camera_for(p, v, r);
}

int tf_report_organ_rest_png(tf_ctx *ctx, const char *path, const tf_problem *p,
                             const tf_report_organ_view *v)
{
    tf_report_render r;
    char title[512];
    const tf_mesh_geometry *m = tf_problem_mesh(p);
    unsigned char *fixed = calloc(p->cloud.n + 1, 1);
    double *value = calloc(m->tm.ntri + 1, sizeof *value);
    if (value == NULL || fixed == NULL) {
        free(fixed);
        free(value);
        return tf_fail(ctx, "out of memory");
    }
    for (size_t k = 0; k < p->n_fixed; ++k) {
        for (size_t q = 0; q < p->fixed[k].n_nodes; ++q) {
            fixed[p->fixed[k].nodes[q]] = 1;
        }
    }
    /* A triangle is fixed when its three corners are, over a material
     * region (3) when its inward normal meets one, contact when it is one
     * of a site's triangles (the same corners). */
    for (size_t t = 0; t < m->tm.ntri; ++t) {
        const size_t *c = m->tm.tri + 3 * t;
        value[t] = fixed[c[0]] && fixed[c[1]] && fixed[c[2]];
        value[t] = p->n_inclusions > 0 && over_inclusion(p, m, t) ? 3 : value[t];
        for (size_t k = 0; k < p->n_contacts; ++k) {
            const tf_patch *pt = &p->contacts[k].patch;
            for (size_t q = 0; q < pt->n_tri; ++q) {
                const uint32_t *d = pt->tri + 3 * q;
                if (d[0] == c[0] && d[1] == c[1] && d[2] == c[2]) {
                    value[t] = 2;
                }
            }
        }
    }
    free(fixed);
    base(p, v, &r);
    char file[48] = ""; /* a refined skin's vertices beyond the file's */
    if (m->file_nv < p->cloud.n_surface) {
        snprintf(file, sizeof file, " (%zu of them the file's)", m->file_nv);
    }
    snprintf(title, sizeof title,
             "%s at rest: %zu surface vertices%s; fixed region blue%s%s",
             v->title ? v->title : p->name, p->cloud.n_surface, file,
             p->n_contacts == 0 ? "" : p->n_contacts > 1 ? ", contact sites red" : ", contact site red",
             p->n_inclusions > 0 ? ", over a material region green" : "");
    r.tri_value = value;
    r.vmin = 0;
    r.vmax = 3;
    r.palette = "defined (0 '#e0b890', 0.5 '#e0b890', 0.5 '#4070c8', 1.5 '#4070c8', "
                "1.5 '#d83020', 2.5 '#d83020', 2.5 '#30a060', 3 '#30a060')";
    r.cblabel = NULL;
    r.title = title;
    int rc = tf_report_render_png(ctx, path, &r);
    free(value);
    return rc;
}

int tf_report_organ_deformed_png(tf_ctx *ctx, const char *path, const tf_problem *p,
                                 const double *u, const double force[3],
                                 const tf_report_organ_view *v)
{
    tf_report_render r;
    char title[512];
    size_t n = p->cloud.n;
    double *value = malloc((n + 1) * sizeof *value), *drawn = malloc((3 * n + 1) * sizeof *drawn);
    if (value == NULL || drawn == NULL) {
        free(value);
        free(drawn);
        return tf_fail(ctx, "out of memory");
    }
    double top = 0;
    for (size_t i = 0; i < n; ++i) {
        const double *d = u + 3 * i;
        value[i] = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        top = i < p->cloud.n_surface ? fmax(top, value[i]) : top;
        for (int a = 0; a < 3; ++a) {
            drawn[3 * i + (size_t)a] = v->exaggerate * d[a];
        }
    }
    base(p, v, &r);
    snprintf(title, sizeof title,
             "%s deformed by F = (%.3g, %.3g, %.3g) N at %s: largest |u| %.3g mm%s",
             v->title ? v->title : p->name, force[0], force[1], force[2],
             p->contacts[v->contact].name, top,
             v->exaggerate == 1 ? " (to scale)" : " (exaggerated)");
    if (v->exaggerate != 1) {
        size_t k = strlen(title);
        snprintf(title + k, sizeof title - k, " x%g", v->exaggerate);
    }
    r.u = drawn;
    r.value = value;
    r.vmin = 0;
    r.vmax = top;
    r.palette = "defined (0 '#e0b890', 0.35 '#f0a040', 0.7 '#d83020', 1 '#601010')";
    r.cblabel = "|u| (mm)";
    r.title = title;
    int rc = tf_report_render_png(ctx, path, &r);
    free(value);
    free(drawn);
    return rc;
}
