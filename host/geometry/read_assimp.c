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

/* Whether line t (blanks skipped) begins with word, then a blank or the
 * line's end. */
static int keyword(const char *t, const char *word)
{
    size_t n = strlen(word);
    return strncmp(t, word, n) == 0 && (t[n] == '\0' || strchr(" \t\r\n", t[n]) != NULL);
}

/* What is wrong with the header of a file that assimp would take for a PLY
 * file (it begins "ply" or "PLY"), or NULL.  assimp 5.2's PLY reader never
 * returns on a header without an end_header line (measured: still running
 * after 2 minutes), and frees memory it did not allocate with malloc on a
 * header holding lines of no PLY keyword (ASan, a fuzzed file), so such
 * files are refused before assimp sees them.  A line ends the header as it
 * does for assimp: blanks, "end_header", then a blank or the line's end. */
static const char *ply_header_problem(const char *path, size_t *bad_line)
{
    static const char *const words[] = {"format", "element", "property", "comment", "obj_info"};
    FILE *f = fopen(path, "rb");
    char line[256];
    if (f == NULL) {
        return NULL; /* assimp says why it cannot read it */
    }
    int ply = fgets(line, sizeof line, f) != NULL && strncasecmp(line, "ply", 3) == 0;
    int at_start = ply && strchr(line, '\n') != NULL, ended = 0;
    const char *why = NULL;
    for (size_t n = 2; ply && !ended && fgets(line, sizeof line, f) != NULL; ++n) {
        const char *t = line + strspn(line, " \t");
        ended = at_start && keyword(t, "end_header");
        int known = !at_start || ended || *t == '\n' || *t == '\r';
        for (size_t w = 0; !known && w < sizeof words / sizeof *words; ++w) {
            known = keyword(t, words[w]);
        }
        if (!known && why == NULL) { /* the first; a missing end_header says more */
            why = "a PLY header line of none of its keywords (format, element, property, comment, "
                  "obj_info, end_header)";
            *bad_line = n;
        }
        n -= strchr(line, '\n') == NULL; /* a piece of a longer line */
        at_start = strchr(line, '\n') != NULL; /* the next piece begins a line */
    }
    fclose(f);
    if (ply && !ended) {
        *bad_line = 0;
        return "a PLY header without its end_header line";
    }
    return why;
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
    size_t bad_line = 0;
    const char *header = ply_header_problem(path, &bad_line);
    if (header != NULL) {
        aiReleasePropertyStore(props);
        if (bad_line > 0) {
            return tf_geom_fail(m, TF_GEOM_BAD_INPUT, "cannot read mesh '%s': line %zu: %s", path,
                                bad_line, header);
        }
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT, "cannot read mesh '%s': %s", path, header);
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
