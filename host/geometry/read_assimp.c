/*
 * read_assimp.c — OBJ, STL, PLY and OFF surfaces through assimp's C API
 * (surface_read.h).
 */
#include "geometry/surface_read.h"

#include <assimp/cimport.h>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

/* Whether every mesh's declared primitive kinds hold a polygon when they
 * say so: assimp's triangulation asserts, and so aborts the process, on a
 * mesh marked as holding polygons that holds none, which a loader leaves
 * behind on some malformed files (a PLY face list that breaks off). */
static int polygons_as_declared(const struct aiScene *sc)
{
    for (unsigned k = 0; k < sc->mNumMeshes; ++k) {
        const struct aiMesh *me = sc->mMeshes[k];
        unsigned polygons = 0;
        for (unsigned f = 0; f < me->mNumFaces; ++f) {
            polygons += me->mFaces[f].mNumIndices > 3;
        }
        if ((me->mPrimitiveTypes & aiPrimitiveType_POLYGON) && polygons == 0) {
            return 0;
        }
    }
    return 1;
}

/* Everything but positions and faces is removed before vertices are
 * joined, so that normals, texture seams or materials cannot split one
 * position into several vertices (which would open the surface); the
 * scene graph's transforms are applied and its meshes merged.  The scene
 * a loader built is validated and checked before any of that: a loader
 * can leave a malformed mesh behind on a malformed file (faces without
 * indices: an OFF file announcing more faces than it holds; polygons
 * declared and none there), on which a later step asserts and aborts the
 * process.  NULL with *why set when the file is refused. */
static const struct aiScene *import(const char *path, struct aiPropertyStore *props,
                                    const char **why)
{
    aiSetImportPropertyInteger(props, AI_CONFIG_PP_RVC_FLAGS,
                               aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS |
                                   aiComponent_COLORS | aiComponent_TEXCOORDS |
                                   aiComponent_BONEWEIGHTS | aiComponent_ANIMATIONS |
                                   aiComponent_TEXTURES | aiComponent_LIGHTS |
                                   aiComponent_CAMERAS | aiComponent_MATERIALS);
    const struct aiScene *sc =
        aiImportFileExWithProperties(path, aiProcess_ValidateDataStructure, NULL, props);
    if (sc == NULL) {
        *why = aiGetErrorString();
        return NULL;
    }
    if (!polygons_as_declared(sc)) {
        aiReleaseImport(sc);
        *why = "a mesh declared to hold polygons holds none (a malformed face list)";
        return NULL;
    }
    unsigned flags = aiProcess_RemoveComponent | aiProcess_Triangulate |
                     aiProcess_PreTransformVertices | aiProcess_JoinIdenticalVertices;
    sc = aiApplyPostProcessing(sc, flags);
    *why = sc == NULL ? aiGetErrorString() : NULL;
    return sc;
}

/* Whether a file that assimp would take for a PLY file (it begins "ply"
 * or "PLY") ends its header: assimp 5.2's PLY reader never returns on a
 * header without an end_header line (measured: still running after
 * 2 minutes), so such a file is refused before assimp sees it.  A line
 * ends the header as it does for assimp: blanks, "end_header", then a
 * blank or the line's end. */
static int ply_header_unended(const char *path)
{
    FILE *f = fopen(path, "rb");
    char line[256];
    if (f == NULL) {
        return 0; /* assimp says why it cannot read it */
    }
    int ply = fgets(line, sizeof line, f) != NULL && strncasecmp(line, "ply", 3) == 0;
    int at_start = ply && strchr(line, '\n') != NULL, ended = 0;
    while (ply && !ended && fgets(line, sizeof line, f) != NULL) {
        const char *t = line + strspn(line, " \t");
        ended = at_start && strncmp(t, "end_header", 10) == 0 &&
                (t[10] == '\0' || strchr(" \t\r\n", t[10]) != NULL);
        at_start = strchr(line, '\n') != NULL; /* the next piece begins a line */
    }
    fclose(f);
    return ply && !ended;
}

/* Vertices and triangles of all meshes, meshes one after the other. */
static int copy_meshes(const struct aiScene *sc, const char *path, tf_surface *s, tf_geom_msg *m)
{
    size_t nv = 0, nt = 0, other = 0;
    for (unsigned k = 0; k < sc->mNumMeshes; ++k) {
        const struct aiMesh *me = sc->mMeshes[k];
        nv += me->mNumVertices;
        for (unsigned f = 0; f < me->mNumFaces; ++f) {
            if (me->mFaces[f].mNumIndices == 3) {
                nt++;
            } else {
                other++;
            }
        }
    }
    if (other) {
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                            "'%s': %zu faces are points or lines, not triangles", path, other);
    }
    if (nt == 0) {
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT, "'%s': no triangles", path);
    }
    if (tf_surface_alloc(s, nv, nt) != 0) {
        return tf_geom_fail(m, TF_GEOM_FAILED, "'%s': out of memory", path);
    }
    size_t v0 = 0, t = 0;
    for (unsigned k = 0; k < sc->mNumMeshes; ++k) {
        const struct aiMesh *me = sc->mMeshes[k];
        for (unsigned i = 0; i < me->mNumVertices; ++i) {
            s->xyz[3 * (v0 + i)] = me->mVertices[i].x;
            s->xyz[3 * (v0 + i) + 1] = me->mVertices[i].y;
            s->xyz[3 * (v0 + i) + 2] = me->mVertices[i].z;
        }
        for (unsigned f = 0; f < me->mNumFaces; ++f, ++t) {
            for (int c = 0; c < 3; ++c) {
                s->tri[3 * t + c] = v0 + me->mFaces[f].mIndices[c];
            }
        }
        v0 += me->mNumVertices;
    }
    return TF_GEOM_OK;
}

int tf_surface_read_assimp(const char *path, tf_surface *s, tf_geom_msg *m)
{
    struct aiPropertyStore *props = aiCreatePropertyStore();
    if (props == NULL) {
        return tf_geom_fail(m, TF_GEOM_FAILED, "'%s': out of memory", path);
    }
    if (ply_header_unended(path)) {
        aiReleasePropertyStore(props);
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                            "cannot read mesh '%s': a PLY header without its end_header line",
                            path);
    }
    const char *why;
    const struct aiScene *sc = import(path, props, &why);
    int rc;
    if (sc == NULL) {
        rc = tf_geom_fail(m, TF_GEOM_BAD_INPUT, "cannot read mesh '%s': %s", path, why);
    } else {
        rc = copy_meshes(sc, path, s, m);
        aiReleaseImport(sc);
    }
    aiReleasePropertyStore(props);
    return rc;
}
