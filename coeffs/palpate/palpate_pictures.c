/*
 * palpate_pictures.c — the force map and the deformed surfaces of make
 * demo-palpate (palpate_pictures.h).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "base/plot.h"
#include "coeffs/palpate/palpate_pictures.h"

/* The chart (a, b) of a scene point. */
static void chart_ab(const palpate_grid *g, const float p[3], double ab[2])
{
    const double x[3] = {p[0], p[1], p[2]};
    double q[3];
    palpate_to_chart(g, x, q);
    ab[0] = q[0];
    ab[1] = q[1];
}

/* The instruments' tips in contact, as gnuplot data blocks $p1 and $p2. */
static void paths(FILE *gp, const palpate_models *m, const palpate_tick *t, const palpate_run *run)
{
    for (int i = 0; i < 2; ++i) {
        fprintf(gp, "$p%d << EOD\n", i + 1);
        int was = 0;
        for (size_t k = 0; k < run->n; k += 4) {
            int on = (i == 0 || t[k].two) && run->state[k][i][2] == 1.0f;
            if (on) {
                double ab[2];
                chart_ab(&m->grid, t[k].tip[i], ab);
                fprintf(gp, "%.4f %.4f\n", ab[0], ab[1]);
            } else if (was) {
                fputc('\n', gp); /* a break in the line */
            }
            was = on;
        }
        fprintf(gp, "NaN NaN\nEOD\n"); /* (never empty; an undefined point draws nothing) */
    }
}

static int map_vtk(tf_ctx *ctx, const char *dir, const palpate_models *m, double depth,
                   unsigned n, const double *xyz, const float *F)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/force_map.vtk", dir);
    tf_afile a;
    if (tf_afile_open(ctx, &a, path) != 0) {
        return -1;
    }
    FILE *f = a.fp;
    fprintf(f, "# vtk DataFile Version 3.0\n%s: the force of a %.3g mm press at each site (N), "
               "rest surface points (mm)\nASCII\nDATASET STRUCTURED_GRID\n"
               "DIMENSIONS %u %u 1\nPOINTS %u double\n",
            m->name, depth, n, n, n * n);
    for (unsigned k = 0; k < n * n; ++k) {
        fprintf(f, "%.6f %.6f %.6f\n", xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
    }
    fprintf(f, "POINT_DATA %u\nSCALARS force_magnitude_N double 1\nLOOKUP_TABLE default\n", n * n);
    for (unsigned k = 0; k < n * n; ++k) {
        const float *v = F + 3 * k;
        fprintf(f, "%.6g\n", sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]));
    }
    fprintf(f, "VECTORS force_N double\n");
    for (unsigned k = 0; k < n * n; ++k) {
        fprintf(f, "%.6g %.6g %.6g\n", (double)F[3 * k], (double)F[3 * k + 1], (double)F[3 * k + 2]);
    }
    return tf_afile_commit(ctx, &a);
}

/* |F| of one tick from a reset state at each of n x n sites, the tip at
 * depth below the rest surface: F[3 n n] and the rest points xyz[3 n n]. */
static void force_grid(const palpate_models *m, double depth, unsigned n, double *xyz, float *F,
                       double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = 0;
    for (unsigned j = 0; j < n; ++j) {
        for (unsigned i = 0; i < n; ++i) {
            const size_t k = (size_t)j * n + i;
            const double g[2] = {i * (m->grid.nx - 1.0) / (n - 1), j * (m->grid.ny - 1.0) / (n - 1)};
            double x[3], p[3];
            palpate_rest_point(m->law_host, g, x);
            palpate_to_scene(&m->grid, x, xyz + 3 * k);
            x[2] -= depth;
            palpate_to_scene(&m->grid, x, p);
            float st[TFIT_REGION_STATE_WORDS], tip[3] = {(float)p[0], (float)p[1], (float)p[2]};
            tfit_region_reset(m->law, st);
            tfit_region_force(m->law, st, tip, F + 3 * k);
            const float *v = F + 3 * k;
            double mag = sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]);
            *lo = fmin(*lo, mag);
            *hi = fmax(*hi, mag);
        }
    }
}

double palpate_depth(const palpate_models *m, double fraction, unsigned n)
{
    const double trial = 1.0; /* mm: the law is linear in the depth (P = 2) up to rounding */
    double *xyz = malloc(3 * n * n * sizeof *xyz), lo, hi = 0;
    float *F = malloc(3 * n * n * sizeof *F);
    if (xyz && F) {
        force_grid(m, trial, n, xyz, F, &lo, &hi);
    }
    free(xyz);
    free(F);
    return hi > 0 ? trial * fraction * m->R_F / hi : 0;
}

int palpate_force_map(tf_ctx *ctx, const char *dir, const palpate_models *m, double depth,
                      unsigned n, const palpate_tick *t, const palpate_run *run, double *lo,
                      double *hi)
{
    double *xyz = malloc(3 * n * n * sizeof *xyz);
    float *F = malloc(3 * n * n * sizeof *F);
    if (!xyz || !F) {
        free(xyz);
        free(F);
        return tf_fail(ctx, "out of memory");
    }
    force_grid(m, depth, n, xyz, F, lo, hi);
    char path[4200];
    snprintf(path, sizeof path, "%s/force_map.png", dir);
    tf_plot pl;
    int rc = tf_plot_open(ctx, &pl, path, 900, 800);
    if (rc == 0) {
        FILE *gp = pl.gp;
        fprintf(gp, "$map << EOD\n");
        for (unsigned j = 0; j < n; ++j) {
            for (unsigned i = 0; i < n; ++i) {
                const float *v = F + 3 * ((size_t)j * n + i);
                fprintf(gp, "%.4f %.4f %.6g\n", i * (m->grid.nx - 1.0) * m->grid.ha / (n - 1),
                        j * (m->grid.ny - 1.0) * m->grid.hb / (n - 1),
                        sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]));
            }
            fputc('\n', gp);
        }
        fprintf(gp, "EOD\n");
        paths(gp, m, t, run);
        fprintf(gp,
                "set title \"%s: |F| (N) of a %.2f mm press at each site "
                "(tfit_region_force, one tick from reset)\" noenhanced\n"
                "set xlabel 'a (mm, chart)'\nset ylabel 'b (mm, chart)'\nset size ratio -1\n"
                "set view map\nset palette rgbformulae 33,13,10\nset cblabel '|F| (N)'\n"
                "set key outside top center horizontal\n"
                "splot $map using 1:2:3 with pm3d notitle, "
                "$p1 using 1:2:(0) with lines lw 2 lc rgb 'white' title 'instrument 1 in contact', "
                "$p2 using 1:2:(0) with linespoints pt 6 ps 2 lw 2 lc rgb 'black' "
                "title 'instrument 2 in contact'\n",
                m->name, depth);
        rc = tf_plot_close(ctx, &pl);
    }
    if (rc == 0) {
        rc = map_vtk(ctx, dir, m, depth, n, xyz, F);
    }
    free(xyz);
    free(F);
    return rc;
}

/* The output points' rest positions (mm, scene frame). */
static const double *output_xyz(const tf_problem *p, size_t j, double buf[3])
{
    if (p->outputs.points != NULL) {
        return p->outputs.points + 3 * j;
    }
    memcpy(buf, p->cloud.xyz + 3 * (size_t)p->outputs.nodes[j], 3 * sizeof *buf);
    return buf;
}

static int surface_vtk(tf_ctx *ctx, const char *dir, const palpate_models *m, const tf_problem *p,
                       size_t k, const float *u)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/surface_%05zu.vtk", dir, k);
    tf_afile a;
    if (tf_afile_open(ctx, &a, path) != 0) {
        return -1;
    }
    FILE *f = a.fp;
    fprintf(f, "# vtk DataFile Version 3.0\n%s, outputs at tick %zu: rest positions (mm), the "
               "firmware's displacement (mm)\nASCII\nDATASET POLYDATA\nPOINTS %zu double\n",
            m->name, k, m->n_out);
    for (size_t j = 0; j < m->n_out; ++j) {
        double b[3];
        const double *x = output_xyz(p, j, b);
        fprintf(f, "%.6f %.6f %.6f\n", x[0], x[1], x[2]);
    }
    fprintf(f, "VERTICES %zu %zu\n", m->n_out, 2 * m->n_out);
    for (size_t j = 0; j < m->n_out; ++j) {
        fprintf(f, "1 %zu\n", j);
    }
    fprintf(f, "POINT_DATA %zu\nVECTORS displacement_mm double\n", m->n_out);
    for (size_t j = 0; j < m->n_out; ++j) {
        fprintf(f, "%.6g %.6g %.6g\n", (double)u[3 * j], (double)u[3 * j + 1], (double)u[3 * j + 2]);
    }
    return tf_afile_commit(ctx, &a);
}

int palpate_surfaces(tf_ctx *ctx, const char *dir, const palpate_models *m, const tf_problem *p,
                     const palpate_tick *t, const palpate_run *run, const size_t *frames,
                     size_t nf)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/surface.png", dir);
    tf_plot pl;
    if (tf_plot_open(ctx, &pl, path, 1200, 1100) != 0) {
        return -1;
    }
    FILE *gp = pl.gp;
    for (size_t f = 0; f < nf; ++f) {
        const size_t k = frames[f] * PALPATE_DISPLAY_EVERY + PALPATE_DISPLAY_EVERY - 1;
        const float *u = run->surface + frames[f] * 3 * m->n_out;
        fprintf(gp, "$s%zu << EOD\n", f);
        for (size_t j = 0; j < m->n_out; ++j) {
            double b[3], q[3], x[3];
            const double *xs = output_xyz(p, j, b);
            for (int i = 0; i < 3; ++i) {
                x[i] = xs[i] + u[3 * j + (size_t)i];
            }
            palpate_to_chart(&m->grid, x, q);
            fprintf(gp, "%.4f %.4f %.5g\n", q[0], q[1],
                    sqrt((double)u[3 * j] * u[3 * j] + (double)u[3 * j + 1] * u[3 * j + 1] +
                         (double)u[3 * j + 2] * u[3 * j + 2]));
        }
        fprintf(gp, "EOD\n$t%zu << EOD\n", f);
        for (int i = 0; i < 1 + t[k].two; ++i) {
            double ab[2];
            chart_ab(&m->grid, t[k].tip[i], ab);
            fprintf(gp, "%.4f %.4f\n", ab[0], ab[1]);
        }
        fprintf(gp, "EOD\n");
    }
    double top = 0;
    for (size_t f = 0; f < nf; ++f) {
        const float *u = run->surface + frames[f] * 3 * m->n_out;
        for (size_t j = 0; j < m->n_out; ++j) {
            top = fmax(top, sqrt((double)u[3 * j] * u[3 * j] + (double)u[3 * j + 1] * u[3 * j + 1] +
                                 (double)u[3 * j + 2] * u[3 * j + 2]));
        }
    }
    fprintf(gp, "set multiplot layout 2,%zu title \"%s, the outputs under the probes: the "
                "firmware's displacement |u| (mm), deformed positions in the chart's (a, b) plane\" "
                "noenhanced\nset size ratio -1\nset palette rgbformulae 33,13,10\n"
                "set cbrange [0:%.4g]\nset xlabel 'a (mm)'\nset ylabel 'b (mm)'\n",
            (nf + 1) / 2, m->name, top > 0 ? top : 1.0);
    for (size_t f = 0; f < nf; ++f) {
        const size_t k = frames[f] * PALPATE_DISPLAY_EVERY + PALPATE_DISPLAY_EVERY - 1;
        fprintf(gp, "set title 'tick %zu (%s)'\n"
                    "plot $s%zu using 1:2:3 with points pt 7 ps 0.8 palette notitle, "
                    "$t%zu using 1:2 with points pt 6 ps 3 lw 2 lc rgb 'black' notitle\n",
                k, t[k].two ? "two instruments" : "one instrument", f, f);
    }
    fprintf(gp, "unset multiplot\n");
    int rc = tf_plot_close(ctx, &pl);
    for (size_t f = 0; rc == 0 && f < nf; ++f) {
        const size_t k = frames[f] * PALPATE_DISPLAY_EVERY + PALPATE_DISPLAY_EVERY - 1;
        rc = surface_vtk(ctx, dir, m, p, k, run->surface + frames[f] * 3 * m->n_out);
    }
    return rc;
}
