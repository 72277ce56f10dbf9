/*
 * shapes.h — closed surfaces the geometry tests generate (no data files):
 * a cube, a latitude-longitude sphere, and writers for the mesh formats the
 * readers take.  Header-only (static) so that each test program includes
 * what it uses.
 */
#ifndef TF_TEST_SHAPES_H
#define TF_TEST_SHAPES_H

#include <math.h>
#include <stdio.h>

#include "geometry/surface.h"

/* Cube [x0, x0 + size]^3, 8 vertices, 12 triangles wound outward. */
static inline int shape_cube(tf_surface *s, double x0, double size)
{
    static const size_t tri[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7},
                                      {0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5},
                                      {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    if (tf_surface_alloc(s, 8, 12) != 0) {
        return -1;
    }
    for (size_t v = 0; v < 8; ++v) {
        s->xyz[3 * v] = x0 + size * (double)((v == 1 || v == 2 || v == 5 || v == 6));
        s->xyz[3 * v + 1] = x0 + size * (double)((v == 2 || v == 3 || v == 6 || v == 7));
        s->xyz[3 * v + 2] = x0 + size * (double)(v >= 4);
    }
    for (size_t t = 0; t < 12; ++t) {
        for (int k = 0; k < 3; ++k) {
            s->tri[3 * t + k] = tri[t][k];
        }
    }
    return 0;
}

/* Sphere of radius r about c: two poles and nlat - 1 rings of nlon
 * vertices, wound outward. */
static inline int shape_sphere(tf_surface *s, const double c[3], double r, size_t nlat,
                               size_t nlon)
{
    size_t rings = nlat - 1, nv = 2 + rings * nlon, nt = 2 * nlon * (nlat - 1);
    if (tf_surface_alloc(s, nv, nt) != 0) {
        return -1;
    }
    double *x = s->xyz;
    x[0] = c[0], x[1] = c[1], x[2] = c[2] + r; /* north pole, vertex 0 */
    for (size_t i = 0; i < rings; ++i) {
        double th = M_PI * (double)(i + 1) / (double)nlat;
        for (size_t j = 0; j < nlon; ++j) {
            double ph = 2 * M_PI * (double)j / (double)nlon;
            double *p = x + 3 * (1 + i * nlon + j);
            p[0] = c[0] + r * sin(th) * cos(ph);
            p[1] = c[1] + r * sin(th) * sin(ph);
            p[2] = c[2] + r * cos(th);
        }
    }
    x[3 * (nv - 1)] = c[0], x[3 * (nv - 1) + 1] = c[1], x[3 * (nv - 1) + 2] = c[2] - r;
    size_t *t = s->tri;
    for (size_t j = 0; j < nlon; ++j) {
        size_t j1 = (j + 1) % nlon;
        *t++ = 0, *t++ = 1 + j, *t++ = 1 + j1;
        for (size_t i = 0; i + 1 < rings; ++i) {
            size_t a = 1 + i * nlon + j, b = 1 + i * nlon + j1;
            size_t a2 = a + nlon, b2 = b + nlon;
            *t++ = a, *t++ = a2, *t++ = b2;
            *t++ = a, *t++ = b2, *t++ = b;
        }
        *t++ = nv - 1, *t++ = 1 + (rings - 1) * nlon + j1, *t++ = 1 + (rings - 1) * nlon + j;
    }
    return 0;
}

static inline int shape_write_obj(const tf_surface *s, const char *path)
{
    FILE *fp = fopen(path, "w");
    if (fp == NULL) {
        return -1;
    }
    for (size_t v = 0; v < s->nv; ++v) {
        fprintf(fp, "v %.17g %.17g %.17g\n", s->xyz[3 * v], s->xyz[3 * v + 1], s->xyz[3 * v + 2]);
    }
    for (size_t t = 0; t < s->nt; ++t) {
        fprintf(fp, "f %zu %zu %zu\n", s->tri[3 * t] + 1, s->tri[3 * t + 1] + 1,
                s->tri[3 * t + 2] + 1);
    }
    return fclose(fp);
}

static inline int shape_write_stl(const tf_surface *s, const char *path)
{
    FILE *fp = fopen(path, "w");
    if (fp == NULL) {
        return -1;
    }
    fprintf(fp, "solid shape\n");
    for (size_t t = 0; t < s->nt; ++t) {
        fprintf(fp, " facet normal 0 0 0\n  outer loop\n");
        for (int k = 0; k < 3; ++k) {
            const double *x = s->xyz + 3 * s->tri[3 * t + k];
            fprintf(fp, "   vertex %.9g %.9g %.9g\n", x[0], x[1], x[2]);
        }
        fprintf(fp, "  endloop\n endfacet\n");
    }
    fprintf(fp, "endsolid shape\n");
    return fclose(fp);
}

/* Legacy VTK, ASCII POLYDATA. */
static inline int shape_write_vtk(const tf_surface *s, const char *path)
{
    FILE *fp = fopen(path, "w");
    if (fp == NULL) {
        return -1;
    }
    fprintf(fp, "# vtk DataFile Version 3.0\nshape\nASCII\nDATASET POLYDATA\nPOINTS %zu double\n",
            s->nv);
    for (size_t v = 0; v < s->nv; ++v) {
        fprintf(fp, "%.17g %.17g %.17g\n", s->xyz[3 * v], s->xyz[3 * v + 1], s->xyz[3 * v + 2]);
    }
    fprintf(fp, "POLYGONS %zu %zu\n", s->nt, 4 * s->nt);
    for (size_t t = 0; t < s->nt; ++t) {
        fprintf(fp, "3 %zu %zu %zu\n", s->tri[3 * t], s->tri[3 * t + 1], s->tri[3 * t + 2]);
    }
    return fclose(fp);
}

#endif /* TF_TEST_SHAPES_H */
