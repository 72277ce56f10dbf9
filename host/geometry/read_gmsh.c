/*
 * read_gmsh.c — legacy VTK surfaces through gmsh (surface_read.h).  gmsh
 * numbers a VTK file's points 1, 2, ... in file order; the surface keeps
 * that order and source = tag - 1.
 */
#include "geometry/surface_read.h"

#include <gmshc.h>
#include <math.h>
#include <stdlib.h>

#include "geometry/gmsh_session.h"

#define GMSH_TRIANGLE 2 /* gmsh element type: 3-node triangle */

/* Node coordinates by tag (1 .. max tag); unused tags keep NaN. */
static int copy_nodes(const char *path, tf_surface *s, size_t nt, tf_geom_msg *m)
{
    size_t *tags = NULL, ntags = 0, ncoord = 0, npar = 0, maxtag = 0;
    double *coord = NULL, *par = NULL;
    int ierr = 0;
    gmshModelMeshGetNodes(&tags, &ntags, &coord, &ncoord, &par, &npar, -1, -1, 0, 0, &ierr);
    for (size_t i = 0; i < ntags; ++i) {
        maxtag = tags[i] > maxtag ? tags[i] : maxtag;
    }
    int rc = TF_GEOM_OK;
    if (ierr != 0) {
        rc = tf_gmsh_fail(m, TF_GEOM_BAD_INPUT, path);
    } else if (tf_surface_alloc(s, maxtag, nt) != 0) {
        rc = tf_geom_fail(m, TF_GEOM_FAILED, "'%s': out of memory", path);
    } else {
        for (size_t i = 0; i < 3 * maxtag; ++i) {
            s->xyz[i] = NAN;
        }
        for (size_t i = 0; i < ntags; ++i) {
            for (int a = 0; a < 3; ++a) {
                s->xyz[3 * (tags[i] - 1) + a] = coord[3 * i + a];
            }
        }
    }
    gmshFree(tags);
    gmshFree(coord);
    gmshFree(par);
    return rc;
}

/* Elements of every type in the model. */
static size_t element_count(void)
{
    int *types = NULL, ierr = 0;
    size_t ntypes = 0, **etags = NULL, *etags_n = NULL, netags = 0, **enodes = NULL,
           *enodes_n = NULL, nenodes = 0, count = 0;
    gmshModelMeshGetElements(&types, &ntypes, &etags, &etags_n, &netags, &enodes, &enodes_n,
                             &nenodes, -1, -1, &ierr);
    for (size_t k = 0; k < ntypes; ++k) {
        count += etags_n[k];
        gmshFree(etags[k]);
        gmshFree(enodes[k]);
    }
    gmshFree(types);
    gmshFree(etags);
    gmshFree(etags_n);
    gmshFree(enodes);
    gmshFree(enodes_n);
    return count;
}

/* Every element must be a 3-node triangle; their node tags (gmshFree). */
static int triangles(const char *path, size_t **tri, size_t *nt, tf_geom_msg *m)
{
    size_t *tags = NULL, ntags = 0, nnodes = 0;
    int ierr = 0;
    gmshModelMeshGetElementsByType(GMSH_TRIANGLE, &tags, &ntags, tri, &nnodes, -1, 0, 1, &ierr);
    gmshFree(tags);
    *nt = nnodes / 3;
    size_t other = element_count() - *nt;
    int rc = TF_GEOM_OK;
    if (ierr != 0) {
        rc = tf_gmsh_fail(m, TF_GEOM_BAD_INPUT, path);
    } else if (other) {
        rc = tf_geom_fail(m, TF_GEOM_BAD_INPUT, "'%s': %zu cells are not triangles", path, other);
    } else if (*nt == 0) {
        rc = tf_geom_fail(m, TF_GEOM_BAD_INPUT, "'%s': no triangles", path);
    }
    if (rc != TF_GEOM_OK) {
        gmshFree(*tri);
        *tri = NULL;
    }
    return rc;
}

static int read_open_model(const char *path, tf_surface *s, tf_geom_msg *m)
{
    size_t *tri, nt;
    int rc = triangles(path, &tri, &nt, m);
    if (rc == TF_GEOM_OK) {
        rc = copy_nodes(path, s, nt, m);
    }
    if (rc == TF_GEOM_OK) {
        for (size_t i = 0; i < 3 * nt; ++i) {
            s->tri[i] = tri[i] - 1;
        }
    }
    gmshFree(tri);
    return rc;
}

int tf_surface_read_gmsh(const char *path, tf_surface *s, tf_geom_msg *m)
{
    int ierr = 0;
    tf_gmsh_begin();
    gmshOpen(path, &ierr);
    int rc = ierr != 0 ? tf_gmsh_fail(m, TF_GEOM_BAD_INPUT, "cannot read mesh")
                       : read_open_model(path, s, m);
    tf_gmsh_end();
    return rc;
}
