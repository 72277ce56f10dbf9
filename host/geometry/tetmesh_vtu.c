/*
 * tetmesh_vtu.c — VTU writer for tetrahedral node clouds (tetmesh_vtu.h).
 */
#include "geometry/tetmesh_vtu.h"

#include "base/atomic_file.h"

#define VTK_TETRA 10

static void array_head(FILE *fp, const char *type, const char *name, int components)
{
    fprintf(fp, "<DataArray type=\"%s\"%s%s%s NumberOfComponents=\"%d\" format=\"ascii\">\n",
            type, name ? " Name=\"" : "", name ? name : "", name ? "\"" : "", components);
}

void tf_tetmesh_write_vtu(FILE *fp, const tf_tetmesh *t)
{
    fprintf(fp, "<?xml version=\"1.0\"?>\n"
                "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                "<UnstructuredGrid>\n<Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n"
                "<PointData Scalars=\"source\">\n",
            t->nn, t->ntet);
    array_head(fp, "Int64", "source", 1);
    for (size_t i = 0; i < t->nn; ++i) {
        fprintf(fp, "%ld\n", t->source[i]);
    }
    fprintf(fp, "</DataArray>\n</PointData>\n<CellData Scalars=\"volume\">\n");
    array_head(fp, "Float64", "volume", 1);
    for (size_t e = 0; e < t->ntet; ++e) {
        fprintf(fp, "%.17g\n", t->tet_volume[e]);
    }
    fprintf(fp, "</DataArray>\n</CellData>\n<Points>\n");
    array_head(fp, "Float64", NULL, 3);
    for (size_t i = 0; i < t->nn; ++i) {
        fprintf(fp, "%.17g %.17g %.17g\n", t->xyz[3 * i], t->xyz[3 * i + 1], t->xyz[3 * i + 2]);
    }
    fprintf(fp, "</DataArray>\n</Points>\n<Cells>\n");
    array_head(fp, "UInt64", "connectivity", 1);
    for (size_t e = 0; e < t->ntet; ++e) {
        const size_t *v = t->tet + 4 * e;
        fprintf(fp, "%zu %zu %zu %zu\n", v[0], v[1], v[2], v[3]);
    }
    fprintf(fp, "</DataArray>\n");
    array_head(fp, "UInt64", "offsets", 1);
    for (size_t e = 1; e <= t->ntet; ++e) {
        fprintf(fp, "%zu\n", 4 * e);
    }
    fprintf(fp, "</DataArray>\n");
    array_head(fp, "UInt8", "types", 1);
    for (size_t e = 0; e < t->ntet; ++e) {
        fprintf(fp, "%d\n", VTK_TETRA);
    }
    fprintf(fp, "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
}

int tf_tetmesh_save_vtu(const char *path, const tf_tetmesh *t, tf_geom_msg *m)
{
    tf_ctx ctx; /* the atomic file's message goes into m->error, as geometry reports */
    tf_ctx_init(&ctx);
    tf_afile a;
    if (tf_afile_open(&ctx, &a, path) != 0) {
        snprintf(m->error, sizeof m->error, "%.*s", (int)sizeof m->error - 1, ctx.err);
        return TF_GEOM_FAILED;
    }
    tf_tetmesh_write_vtu(a.fp, t);
    if (tf_afile_commit(&ctx, &a) != 0) {
        snprintf(m->error, sizeof m->error, "%.*s", (int)sizeof m->error - 1, ctx.err);
        return TF_GEOM_FAILED;
    }
    return TF_GEOM_OK;
}
