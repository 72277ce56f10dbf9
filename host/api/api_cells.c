/*
 * api_cells.c — the cells of the scene's VTU file (api.h), as `tissuefit
 * solve --vtk` chooses them (cli/cmd_solve.c, write_vtu): an organ's
 * tetrahedra, else the grid's hexahedra without those a cut passes through
 * (report/displacement_out.c).
 */
#include <stdlib.h>

#include "api/api_internal.h"
#include "problem/mesh_geometry.h"
#include "report/displacement_out.h"

int tf_api_cells(tf_ctx *ctx, const tf_api_scene *s, size_t *count, unsigned *corners,
                 uint64_t *conn)
{
    const tf_problem *p = &s->scene->problem;
    const tf_mesh_geometry *m = tf_problem_mesh(p);
    if (m != NULL) {
        *count = m->tm.ntet;
        *corners = 4;
        for (size_t i = 0; conn != NULL && i < 4 * m->tm.ntet; ++i) {
            conn[i] = m->tm.tet[i];
        }
        return 0;
    }
    size_t *hex, nc;
    if (tf_report_grid_cells(&p->cloud, p->cuts, p->n_cuts, &hex, &nc) != 0) {
        return tf_fail(ctx, "cells: %s: out of memory for the VTK cells", s->path);
    }
    *count = nc;
    *corners = 8;
    for (size_t i = 0; conn != NULL && i < 8 * nc; ++i) {
        conn[i] = hex[i];
    }
    free(hex);
    return 0;
}
