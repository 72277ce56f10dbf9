/*
 * volume_mesh.c — gmsh fills a closed surface with tetrahedra
 * (volume_mesh.h).
 */
#include "geometry/volume_mesh.h"

#include <gmshc.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/gmsh_session.h"
#include "geometry/tetmesh_check.h"

#define GMSH_TRIANGLE 2
#define GMSH_TET 4
#define SURFACE_TAG 1

int tf_volume_mesh_check_options(const tf_surface *s, const tf_mesh_options *o, tf_geom_msg *m)
{
    if (!(o->spacing > 0) || !isfinite(o->spacing)) {
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT, "spacing %g: must be a positive number of mm",
                            o->spacing);
    }
    double volume = tf_surface_volume(s), fine = 0;
    if (o->graded) {
        double at = o->grade_at[0] + o->grade_at[1] + o->grade_at[2];
        if (!(o->grade_spacing > 0 && o->grade_spacing <= o->spacing) ||
            !(o->grade_radius >= 0 && o->grade_ramp > o->grade_radius) ||
            !isfinite(o->grade_ramp) || !isfinite(at)) {
            return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                                "grading: need 0 < spacing at the point (%g) <= spacing (%g), "
                                "0 <= radius (%g) < ramp (%g) and a finite point",
                                o->grade_spacing, o->spacing, o->grade_radius, o->grade_ramp);
        }
        fine = fmin(volume, 4.0 / 3 * M_PI * pow(o->grade_ramp, 3));
    }
    /* A regular tetrahedron of edge h has volume h^3 / (6 sqrt 2). */
    double tets = 6 * sqrt(2) * ((volume - fine) / pow(o->spacing, 3) +
                                 (o->graded ? fine / pow(o->grade_spacing, 3) : 0));
    if (tets > TF_MESH_MAX_TETS) {
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                            "spacing %g mm would make about %.3g tetrahedra (at most %.3g): "
                            "use a larger spacing",
                            o->graded ? o->grade_spacing : o->spacing, tets, TF_MESH_MAX_TETS);
    }
    return TF_GEOM_OK;
}

double tf_mesh_size_at(const tf_mesh_options *o, const double x[3])
{
    if (!o->graded) {
        return o->spacing;
    }
    const double *p = o->grade_at;
    double d = sqrt((x[0] - p[0]) * (x[0] - p[0]) + (x[1] - p[1]) * (x[1] - p[1]) +
                    (x[2] - p[2]) * (x[2] - p[2]));
    if (d <= o->grade_radius) {
        return o->grade_spacing;
    }
    if (d >= o->grade_ramp) {
        return o->spacing;
    }
    double f = (d - o->grade_radius) / (o->grade_ramp - o->grade_radius);
    return o->grade_spacing + f * (o->spacing - o->grade_spacing);
}

/* The surface as gmsh's discrete surface `tag`: node tag = vertex index +
 * first + 1, triangle tag = triangle index + first_tri + 1 (the body's
 * surface is tag SURFACE_TAG with first = first_tri = 0; inner surfaces
 * follow with their own tags and numbers). */
static int add_surface(const tf_surface *s, int tag, size_t first, size_t first_tri)
{
    int ierr = 0;
    size_t *ntag = malloc((s->nv + 1) * sizeof *ntag);
    size_t *etag = malloc((s->nt + 1) * sizeof *etag);
    size_t *enode = malloc((3 * s->nt + 1) * sizeof *enode);
    if (ntag && etag && enode) {
        for (size_t i = 0; i < s->nv; ++i) {
            ntag[i] = first + i + 1;
        }
        for (size_t t = 0; t < s->nt; ++t) {
            etag[t] = first_tri + t + 1;
            for (int k = 0; k < 3; ++k) {
                enode[3 * t + k] = first + s->tri[3 * t + k] + 1;
            }
        }
        gmshModelAddDiscreteEntity(2, tag, NULL, 0, &ierr);
        if (ierr == 0) {
            gmshModelMeshAddNodes(2, tag, ntag, s->nv, s->xyz, 3 * s->nv, NULL, 0, &ierr);
        }
        if (ierr == 0) {
            gmshModelMeshAddElementsByType(tag, GMSH_TRIANGLE, etag, s->nt, enode,
                                           3 * s->nt, &ierr);
        }
    } else {
        ierr = -1;
    }
    free(ntag);
    free(etag);
    free(enode);
    return ierr;
}

/* The volume bounded by the surface (geo kernel: surface loop, volume),
 * volume tag 1; with inner surfaces, each is a hole of volume 1 and the
 * boundary of volume k + 2 (surface tag SURFACE_TAG + k + 1). */
static int add_volumes(size_t n_inner)
{
    int ierr = 0, loops[1 + TF_MESH_MAX_INNER];
    for (size_t k = 0; ierr == 0 && k <= n_inner; ++k) {
        int surface = SURFACE_TAG + (int)k;
        loops[k] = gmshModelGeoAddSurfaceLoop(&surface, 1, -1, &ierr);
    }
    if (ierr == 0) {
        gmshModelGeoAddVolume(loops, 1 + n_inner, 1, &ierr);
    }
    for (size_t k = 1; ierr == 0 && k <= n_inner; ++k) {
        gmshModelGeoAddVolume(&loops[k], 1, (int)k + 1, &ierr);
    }
    return ierr;
}

/* Each inner surface's size: gmsh's Threshold of the distance to its
 * ball's centre (a MathEval field): the inner spacing up to the ball's
 * radius, rising linearly to `spacing` one radius further out; the
 * background is the least of these and the body's field. */
static int add_inner_fields(int field, const tf_mesh_inner *inner, size_t n_inner,
                            double spacing)
{
    int ierr = 0, failed = 0, fields[1 + TF_MESH_MAX_INNER] = {field};
    char text[256];
    for (size_t k = 0; k < n_inner; ++k) {
        const tf_mesh_inner *c = &inner[k];
        int distance = gmshModelMeshFieldAdd("MathEval", -1, &ierr);
        failed |= ierr;
        snprintf(text, sizeof text, "Sqrt((x-(%.17g))^2+(y-(%.17g))^2+(z-(%.17g))^2)",
                 c->centre[0], c->centre[1], c->centre[2]);
        gmshModelMeshFieldSetString(distance, "F", text, &ierr);
        failed |= ierr;
        fields[k + 1] = gmshModelMeshFieldAdd("Threshold", -1, &ierr);
        failed |= ierr;
        const char *name[5] = {"InField", "SizeMin", "SizeMax", "DistMin", "DistMax"};
        double value[5] = {distance, c->spacing, spacing, c->radius, 2 * c->radius};
        for (int j = 0; j < 5; ++j) {
            gmshModelMeshFieldSetNumber(fields[k + 1], name[j], value[j], &ierr);
            failed |= ierr;
        }
    }
    if (n_inner == 0) {
        return field;
    }
    int min = gmshModelMeshFieldAdd("Min", -1, &ierr);
    failed |= ierr;
    double list[1 + TF_MESH_MAX_INNER];
    for (size_t k = 0; k <= n_inner; ++k) {
        list[k] = fields[k];
    }
    gmshModelMeshFieldSetNumbers(min, "FieldsList", list, 1 + n_inner, &ierr);
    return failed | ierr ? -1 : min;
}

/* Background size: the constant spacing (MathEval), or gmsh's Threshold of
 * the Distance to a point: grade_spacing up to grade_radius, rising
 * linearly to spacing at grade_ramp.  The point is a free geo point; its
 * node belongs to no tetrahedron and is not collected. */
static int add_size_field(const tf_mesh_options *o, const tf_mesh_inner *inner,
                          size_t n_inner)
{
    int ierr = 0, failed = 0, field;
    char text[64];
    if (!o->graded) {
        field = gmshModelMeshFieldAdd("MathEval", -1, &ierr);
        failed |= ierr;
        snprintf(text, sizeof text, "%.17g", o->spacing);
        gmshModelMeshFieldSetString(field, "F", text, &ierr);
        failed |= ierr;
    } else {
        double point = (double)gmshModelGeoAddPoint(o->grade_at[0], o->grade_at[1],
                                                    o->grade_at[2], o->spacing, -1, &ierr);
        failed |= ierr;
        int distance = gmshModelMeshFieldAdd("Distance", -1, &ierr);
        failed |= ierr;
        gmshModelMeshFieldSetNumbers(distance, "PointsList", &point, 1, &ierr);
        failed |= ierr;
        field = gmshModelMeshFieldAdd("Threshold", -1, &ierr);
        failed |= ierr;
        const char *name[5] = {"InField", "SizeMin", "SizeMax", "DistMin", "DistMax"};
        double value[5] = {distance, o->grade_spacing, o->spacing, o->grade_radius, o->grade_ramp};
        for (int k = 0; k < 5; ++k) {
            gmshModelMeshFieldSetNumber(field, name[k], value[k], &ierr);
            failed |= ierr;
        }
    }
    field = failed ? -1 : add_inner_fields(field, inner, n_inner, o->spacing);
    if (field < 0) {
        return -1;
    }
    gmshModelMeshFieldSetAsBackgroundMesh(field, &ierr);
    return failed | ierr;
}

/* Sizes from the field only (not from the surface's edges, points or
 * curvature), gmsh's Delaunay 3-D mesher with its default optimisation. */
static void set_options(void)
{
    int ierr = 0;
    gmshOptionSetNumber("Mesh.MeshSizeExtendFromBoundary", 0, &ierr);
    gmshOptionSetNumber("Mesh.MeshSizeFromPoints", 0, &ierr);
    gmshOptionSetNumber("Mesh.MeshSizeFromCurvature", 0, &ierr);
    gmshOptionSetNumber("Mesh.Algorithm3D", 1, &ierr);
    /* Keep node tags: the surface's are its vertex indices + 1, and the
     * grading point's node (dimension 0) would otherwise be renumbered
     * in front of them. */
    gmshOptionSetNumber("Mesh.Renumber", 0, &ierr);
}

int tf_volume_mesh_model(const tf_surface *s, const tf_mesh_options *o,
                         const tf_mesh_inner *inner, size_t n_inner)
{
    if (n_inner > TF_MESH_MAX_INNER) {
        return -1;
    }
    int ierr = 0;
    gmshModelAdd("tissuefit", &ierr);
    ierr = ierr ? ierr : add_surface(s, SURFACE_TAG, 0, 0);
    size_t first = s->nv, first_tri = s->nt;
    for (size_t k = 0; ierr == 0 && k < n_inner; ++k) {
        ierr = add_surface(inner[k].surface, SURFACE_TAG + (int)k + 1, first, first_tri);
        first += inner[k].surface->nv;
        first_tri += inner[k].surface->nt;
    }
    ierr = ierr ? ierr : add_volumes(n_inner);
    ierr = ierr ? ierr : add_size_field(o, inner, n_inner);
    if (ierr == 0) {
        gmshModelGeoSynchronize(&ierr);
    }
    set_options();
    if (ierr == 0) {
        gmshModelMeshGenerate(3, &ierr);
    }
    return ierr;
}

typedef struct gmsh_nodes {
    size_t *tag, n, ncoord, npar;
    double *coord, *par;
} gmsh_nodes;

static void gmsh_nodes_free(gmsh_nodes *g)
{
    gmshFree(g->tag);
    gmshFree(g->coord);
    gmshFree(g->par);
}

/* Node index of every gmsh node tag (SIZE_MAX: in no tetrahedron):
 * surface tags 1 .. nv are vertices 0 .. nv - 1, interior tags used by a
 * tetrahedron follow in increasing tag order. */
static size_t *node_index(const size_t *tets, size_t ntet, size_t nv, size_t maxtag, size_t *nn)
{
    size_t *index = malloc((maxtag + 1) * sizeof *index);
    if (index == NULL) {
        return NULL;
    }
    for (size_t g = 0; g <= maxtag; ++g) {
        index[g] = g >= 1 && g <= nv ? g - 1 : SIZE_MAX;
    }
    for (size_t k = 0; k < 4 * ntet; ++k) {
        if (tets[k] > nv) {
            index[tets[k]] = 0;
        }
    }
    *nn = nv;
    for (size_t g = nv + 1; g <= maxtag; ++g) {
        if (index[g] == 0) {
            index[g] = (*nn)++;
        }
    }
    return index;
}

static int fill(tf_tetmesh *t, const tf_surface *s, const gmsh_nodes *g, const size_t *index,
                const size_t *tets)
{
    t->xyz = malloc((3 * t->nn + 1) * sizeof *t->xyz);
    t->source = malloc((t->nn + 1) * sizeof *t->source);
    t->tet = malloc((4 * t->ntet + 1) * sizeof *t->tet);
    t->tet_volume = malloc((t->ntet + 1) * sizeof *t->tet_volume);
    t->tri = malloc((3 * s->nt + 1) * sizeof *t->tri);
    if (!t->xyz || !t->source || !t->tet || !t->tet_volume || !t->tri) {
        return -1;
    }
    for (size_t i = 0; i < t->nn; ++i) {
        t->source[i] = i < s->nv ? s->source[i] : -1;
        t->xyz[3 * i] = NAN; /* a surface vertex gmsh lost stays NaN (caught by the check) */
    }
    for (size_t k = 0; k < g->n; ++k) {
        size_t i = index[g->tag[k]];
        if (i != SIZE_MAX) {
            memcpy(t->xyz + 3 * i, g->coord + 3 * k, 3 * sizeof *t->xyz);
        }
    }
    for (size_t k = 0; k < 4 * t->ntet; ++k) {
        t->tet[k] = index[tets[k]];
    }
    t->nsurf = s->nv;
    t->ntri = s->nt;
    memcpy(t->tri, s->tri, 3 * s->nt * sizeof *t->tri);
    if (s->tri_parent != NULL) {
        t->tri_parent = malloc((s->nt + 1) * sizeof *t->tri_parent);
        if (t->tri_parent == NULL) {
            return -1;
        }
        memcpy(t->tri_parent, s->tri_parent, s->nt * sizeof *t->tri_parent);
    }
    t->enclosed_volume = tf_surface_volume(s);
    tf_tetmesh_volumes(t);
    return 0;
}

/* The generated mesh into t. */
static int collect(const tf_surface *s, tf_tetmesh *t, tf_geom_msg *m)
{
    int ierr = 0;
    size_t *etag = NULL, ne = 0, *tets = NULL, ntn = 0, maxtag = 0, *index = NULL;
    gmsh_nodes g = {0};
    gmshModelMeshGetElementsByType(GMSH_TET, &etag, &ne, &tets, &ntn, -1, 0, 1, &ierr);
    if (ierr == 0) {
        gmshModelMeshGetNodes(&g.tag, &g.n, &g.coord, &g.ncoord, &g.par, &g.npar, -1, -1, 0, 0,
                              &ierr);
    }
    int rc = ierr ? tf_gmsh_fail(m, TF_GEOM_FAILED, "reading gmsh's mesh") : TF_GEOM_OK;
    if (rc == TF_GEOM_OK && ntn == 0) {
        rc = tf_geom_fail(m, TF_GEOM_FAILED, "gmsh made no tetrahedra");
    }
    for (size_t k = 0; k < g.n; ++k) {
        maxtag = g.tag[k] > maxtag ? g.tag[k] : maxtag;
    }
    t->ntet = ntn / 4;
    if (rc == TF_GEOM_OK &&
        ((index = node_index(tets, t->ntet, s->nv, maxtag, &t->nn)) == NULL ||
         fill(t, s, &g, index, tets) != 0)) {
        rc = tf_geom_fail(m, TF_GEOM_FAILED, "out of memory");
    }
    free(index);
    gmshFree(etag);
    gmshFree(tets);
    gmsh_nodes_free(&g);
    return rc;
}

int tf_volume_mesh(const tf_surface *s, const tf_mesh_options *o, tf_tetmesh *t, tf_geom_msg *m)
{
    memset(t, 0, sizeof *t);
    int rc = tf_volume_mesh_check_options(s, o, m);
    if (rc) {
        return rc;
    }
    tf_gmsh_begin();
    if (tf_volume_mesh_model(s, o, NULL, 0) != 0) {
        rc = tf_gmsh_fail(m, TF_GEOM_FAILED, "gmsh could not mesh the volume");
    } else {
        rc = collect(s, t, m);
    }
    tf_gmsh_end();
    if (rc == TF_GEOM_OK) {
        rc = tf_tetmesh_check_topology(t, s, m);
    }
    if (rc) {
        tf_tetmesh_free(t);
    }
    return rc;
}
