/*
 * displacement_out.c — CSV and VTU writers (displacement_out.h).
 */
#include "report/displacement_out.h"

#include <stdlib.h>

#include "problem/inclusions.h"

void tf_report_csv_displacements(FILE *fp, const tf_cloud *c, const uint32_t *idx, size_t n,
                                 const double *u)
{
    fprintf(fp, "node,x,y,z,ux,uy,uz\n");
    size_t count = idx ? n : c->n;
    for (size_t k = 0; k < count; ++k) {
        size_t i = idx ? idx[k] : k;
        const double *x = c->xyz + 3 * i, *ui = u + 3 * i;
        fprintf(fp, "%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", i + 1, x[0], x[1], x[2], ui[0],
                ui[1], ui[2]);
    }
}

void tf_report_csv_outputs(FILE *fp, const tf_problem *p, const double *v)
{
    const tf_outputs *o = &p->outputs;
    fprintf(fp, "output,x,y,z,ux,uy,uz\n");
    for (size_t j = 0; j < o->n_nodes; ++j) {
        const double *x = o->points ? o->points + 3 * j : p->cloud.xyz + 3 * (size_t)o->nodes[j];
        size_t id = o->points ? j + 1 : (size_t)o->nodes[j] + 1;
        fprintf(fp, "%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", id, x[0], x[1], x[2], v[3 * j],
                v[3 * j + 1], v[3 * j + 2]);
    }
}

/* VTK_HEXAHEDRON corners of grid cell (i, j, k): bottom face then top. */
static void hex(const tf_cloud *c, unsigned i, unsigned j, unsigned k, size_t v[8])
{
    static const unsigned d[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                     {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (int q = 0; q < 8; ++q) {
        v[q] = tf_cloud_index(c, i + d[q][0], j + d[q][1], k + d[q][2]);
    }
}

/* Everything before the cells: header, point data, points.  A body with
 * material regions gets "material" beside "displacement" and "node": 0 for
 * the body, k for the k-th inclusion (the first holding the node, as the
 * solvers take it: problem/inclusions.h), for ParaView's Threshold. */
static void vtu_points(FILE *fp, const tf_problem *p, size_t nc, const double *u)
{
    const tf_cloud *c = &p->cloud;
    fprintf(fp,
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            "<UnstructuredGrid>\n<Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n"
            "<PointData Vectors=\"displacement\">\n"
            "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" "
            "format=\"ascii\">\n",
            c->n, nc);
    for (size_t i = 0; i < c->n; ++i) {
        fprintf(fp, "%.17g %.17g %.17g\n", u[3 * i], u[3 * i + 1], u[3 * i + 2]);
    }
    fprintf(fp, "</DataArray>\n<DataArray type=\"UInt32\" Name=\"node\" format=\"ascii\">\n");
    for (size_t i = 0; i < c->n; ++i) {
        fprintf(fp, "%zu\n", i + 1);
    }
    if (p->n_inclusions > 0) {
        fprintf(fp,
                "</DataArray>\n<DataArray type=\"UInt32\" Name=\"material\" format=\"ascii\">\n");
        for (size_t i = 0; i < c->n; ++i) {
            fprintf(fp, "%zu\n", tf_problem_region_at(p, c->xyz + 3 * i));
        }
    }
    fprintf(fp, "</DataArray>\n</PointData>\n<Points>\n"
                "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for (size_t i = 0; i < c->n; ++i) {
        fprintf(fp, "%.17g %.17g %.17g\n", c->xyz[3 * i], c->xyz[3 * i + 1], c->xyz[3 * i + 2]);
    }
    fprintf(fp, "</DataArray>\n</Points>\n<Cells>\n"
                "<DataArray type=\"UInt64\" Name=\"connectivity\" format=\"ascii\">\n");
}

/* Offsets and types of nc cells of `corners` points and VTK type `type`. */
static void vtu_cells_end(FILE *fp, size_t nc, unsigned corners, unsigned type)
{
    fprintf(fp, "</DataArray>\n<DataArray type=\"UInt64\" Name=\"offsets\" format=\"ascii\">\n");
    for (size_t q = 1; q <= nc; ++q) {
        fprintf(fp, "%zu\n", corners * q);
    }
    fprintf(fp, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for (size_t q = 0; q < nc; ++q) {
        fprintf(fp, "%u\n", type);
    }
    fprintf(fp, "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
}

/* 1 when a cut separates two corners of the cell. */
static int cut_through(const tf_cloud *c, const tf_cut_set *cuts, const size_t v[8])
{
    for (int p = 0; p < 8; ++p) {
        for (int q = p + 1; q < 8; ++q) {
            if (!tf_cut_visible(cuts, c->xyz + 3 * v[p], c->xyz + 3 * v[q])) {
                return 1;
            }
        }
    }
    return 0;
}

/* The cells kept, as corner lists (8 per cell); their count. */
static size_t kept_cells(const tf_cloud *c, const tf_cut_set *cuts, size_t *conn)
{
    size_t nc = 0;
    for (unsigned k = 0; k + 1 < c->grid[2]; ++k) {
        for (unsigned j = 0; j + 1 < c->grid[1]; ++j) {
            for (unsigned i = 0; i + 1 < c->grid[0]; ++i) {
                hex(c, i, j, k, conn + 8 * nc);
                nc += !cut_through(c, cuts, conn + 8 * nc);
            }
        }
    }
    return nc;
}

int tf_report_grid_cells(const tf_cloud *c, const tf_cut *cuts, size_t n_cuts, size_t **conn,
                         size_t *nc)
{
    size_t all = (size_t)(c->grid[0] - 1) * (c->grid[1] - 1) * (c->grid[2] - 1);
    tf_cut_set set;
    tf_ctx scratch; /* the only failure here is out of memory, reported as -1 */
    tf_ctx_init(&scratch);
    *conn = malloc(8 * all * sizeof **conn);
    if (*conn == NULL || tf_cut_set_build(&scratch, &set, cuts, n_cuts) != 0) {
        free(*conn);
        *conn = NULL;
        return -1;
    }
    *nc = kept_cells(c, &set, *conn);
    tf_cut_set_free(&set);
    return 0;
}

int tf_report_vtu_displacements(FILE *fp, const tf_problem *p, const double *u)
{
    size_t *conn, nc;
    if (tf_report_grid_cells(&p->cloud, p->cuts, p->n_cuts, &conn, &nc) != 0) {
        return -1;
    }
    vtu_points(fp, p, nc, u);
    for (size_t q = 0; q < nc; ++q) {
        const size_t *v = conn + 8 * q;
        fprintf(fp, "%zu %zu %zu %zu %zu %zu %zu %zu\n", v[0], v[1], v[2], v[3], v[4], v[5], v[6],
                v[7]);
    }
    free(conn);
    vtu_cells_end(fp, nc, 8, 12);
    return 0;
}

void tf_report_vtu_displacements_tets(FILE *fp, const tf_problem *p, const size_t *tet,
                                      size_t ntet, const double *u)
{
    vtu_points(fp, p, ntet, u);
    for (size_t e = 0; e < ntet; ++e) {
        fprintf(fp, "%zu %zu %zu %zu\n", tet[4 * e], tet[4 * e + 1], tet[4 * e + 2],
                tet[4 * e + 3]);
    }
    vtu_cells_end(fp, ntet, 4, 10);
}
