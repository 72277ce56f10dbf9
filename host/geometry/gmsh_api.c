/*
 * gmsh_api.c — the functions of gmsh's C API (gmshc.h) that the host
 * calls, bound from libgmsh at each call.
 *
 * Why not link libgmsh: it brings about 90 shared libraries (OpenCASCADE,
 * VTK, MED, ...) whose 160,000 symbol relocations cost every start of every
 * program that links it about 0.16 s of CPU, and every AddressSanitizer
 * link about 0.7 s, whether it meshes or not.  Most runs of the tool (box
 * scenes, headers, eval) and most tests never touch gmsh.  The definitions
 * below have gmshc.h's prototypes (a mismatch does not compile), so the
 * callers are unchanged.  The library is opened by its soname, which the
 * header's version gives (or the path in $TISSUEFIT_GMSH), with
 * RTLD_NODELETE: every call opens it (the first loads it, the others find
 * it loaded, in microseconds) and closes it again, and it stays loaded, so
 * that this file keeps no state.
 *
 * If libgmsh cannot be opened or lacks a function, the call sets *ierr to
 * 1 and does nothing, and gmshLoggerGetLastError returns the loader's
 * message, so that a caller's ordinary gmsh error path reports it.
 */
#include <dlfcn.h>
#include <gmshc.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TF_STR2(x) #x
#define TF_STR(x) TF_STR2(x)
#define TF_GMSH_SONAME \
    "libgmsh.so." TF_STR(GMSH_API_VERSION_MAJOR) "." TF_STR(GMSH_API_VERSION_MINOR)

/* The library: $TISSUEFIT_GMSH when set (a gmsh built elsewhere), else the
 * soname of the gmshc.h this file was compiled with. */
static const char *gmsh_library(void)
{
    const char *path = getenv("TISSUEFIT_GMSH");
    return path && path[0] ? path : TF_GMSH_SONAME;
}

static void *gmsh_open(void)
{
    return dlopen(gmsh_library(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
}

/* The address of gmsh's NAME, or NULL with *ierr = 1. */
static void *gmsh_symbol(const char *name, int *ierr)
{
    void *lib = gmsh_open();
    void *p = lib ? dlsym(lib, name) : NULL;
    if (lib) {
        dlclose(lib); /* RTLD_NODELETE: it stays loaded */
    }
    if (!p && ierr) {
        *ierr = 1;
    }
    return p;
}

/* NAME, (its parameters as in gmshc.h), (the arguments to pass on). */
#define TF_GMSH_VOID_CALLS(X)                                                                  \
    X(gmshInitialize, (int argc, char **argv, const int readConfigFiles, int *ierr),            \
      (argc, argv, readConfigFiles, ierr))                                                      \
    X(gmshFinalize, (int *ierr), (ierr))                                                        \
    X(gmshOpen, (const char *fileName, int *ierr), (fileName, ierr))                            \
    X(gmshLoggerStart, (int *ierr), (ierr))                                                     \
    X(gmshLoggerStop, (int *ierr), (ierr))                                                      \
    X(gmshOptionSetNumber, (const char *name, const double value, int *ierr),                   \
      (name, value, ierr))                                                                      \
    X(gmshModelAdd, (const char *name, int *ierr), (name, ierr))                                \
    X(gmshModelGeoSynchronize, (int *ierr), (ierr))                                             \
    X(gmshModelMeshAddElementsByType,                                                           \
      (const int tag, const int elementType, size_t *elementTags, size_t elementTags_n,         \
       size_t *nodeTags, size_t nodeTags_n, int *ierr),                                         \
      (tag, elementType, elementTags, elementTags_n, nodeTags, nodeTags_n, ierr))               \
    X(gmshModelMeshAddNodes,                                                                    \
      (const int dim, const int tag, size_t *nodeTags, size_t nodeTags_n, double *coord,        \
       size_t coord_n, double *parametricCoord, size_t parametricCoord_n, int *ierr),           \
      (dim, tag, nodeTags, nodeTags_n, coord, coord_n, parametricCoord, parametricCoord_n,      \
       ierr))                                                                                   \
    X(gmshModelMeshFieldSetAsBackgroundMesh, (const int tag, int *ierr), (tag, ierr))          \
    X(gmshModelMeshFieldSetNumber,                                                              \
      (const int tag, const char *option, const double value, int *ierr),                       \
      (tag, option, value, ierr))                                                               \
    X(gmshModelMeshFieldSetNumbers,                                                             \
      (const int tag, const char *option, double *value, size_t value_n, int *ierr),            \
      (tag, option, value, value_n, ierr))                                                      \
    X(gmshModelMeshFieldSetString,                                                              \
      (const int tag, const char *option, const char *value, int *ierr),                        \
      (tag, option, value, ierr))                                                               \
    X(gmshModelMeshGenerate, (const int dim, int *ierr), (dim, ierr))                           \
    X(gmshModelMeshGetElements,                                                                 \
      (int **elementTypes, size_t *elementTypes_n, size_t ***elementTags,                       \
       size_t **elementTags_n, size_t *elementTags_nn, size_t ***nodeTags, size_t **nodeTags_n, \
       size_t *nodeTags_nn, const int dim, const int tag, int *ierr),                           \
      (elementTypes, elementTypes_n, elementTags, elementTags_n, elementTags_nn, nodeTags,      \
       nodeTags_n, nodeTags_nn, dim, tag, ierr))                                                \
    X(gmshModelMeshGetElementsByType,                                                           \
      (const int elementType, size_t **elementTags, size_t *elementTags_n, size_t **nodeTags,   \
       size_t *nodeTags_n, const int tag, const size_t task, const size_t numTasks, int *ierr), \
      (elementType, elementTags, elementTags_n, nodeTags, nodeTags_n, tag, task, numTasks,      \
       ierr))                                                                                   \
    X(gmshModelMeshGetNodes,                                                                    \
      (size_t **nodeTags, size_t *nodeTags_n, double **coord, size_t *coord_n,                  \
       double **parametricCoord, size_t *parametricCoord_n, const int dim, const int tag,       \
       const int includeBoundary, const int returnParametricCoord, int *ierr),                  \
      (nodeTags, nodeTags_n, coord, coord_n, parametricCoord, parametricCoord_n, dim, tag,      \
       includeBoundary, returnParametricCoord, ierr))                                           \
    X(gmshModelMeshRefine, (int *ierr), (ierr))                                                 \
    X(gmshModelMeshSetOrder, (const int order, int *ierr), (order, ierr))

#define TF_GMSH_INT_CALLS(X)                                                                   \
    X(gmshModelAddDiscreteEntity,                                                               \
      (const int dim, const int tag, int *boundary, size_t boundary_n, int *ierr),              \
      (dim, tag, boundary, boundary_n, ierr))                                                   \
    X(gmshModelGeoAddPoint,                                                                     \
      (const double x, const double y, const double z, const double meshSize, const int tag,    \
       int *ierr),                                                                              \
      (x, y, z, meshSize, tag, ierr))                                                           \
    X(gmshModelGeoAddSurfaceLoop, (int *surfaceTags, size_t surfaceTags_n, const int tag,       \
                                   int *ierr),                                                  \
      (surfaceTags, surfaceTags_n, tag, ierr))                                                  \
    X(gmshModelGeoAddVolume, (int *shellTags, size_t shellTags_n, const int tag, int *ierr),    \
      (shellTags, shellTags_n, tag, ierr))                                                      \
    X(gmshModelMeshFieldAdd, (const char *fieldType, const int tag, int *ierr),                 \
      (fieldType, tag, ierr))

/* A POSIX object pointer holds a function's address (dlsym's contract);
 * memcpy converts it without the cast ISO C leaves undefined. */
#define TF_GMSH_DEFINE_VOID(name, params, args)                                                \
    void name params                                                                            \
    {                                                                                           \
        void (*fn) params;                                                                      \
        void *p = gmsh_symbol(#name, ierr);                                                     \
        if (p) {                                                                                \
            memcpy(&fn, &p, sizeof fn);                                                         \
            fn args;                                                                            \
        }                                                                                       \
    }
#define TF_GMSH_DEFINE_INT(name, params, args)                                                 \
    int name params                                                                             \
    {                                                                                           \
        int (*fn) params;                                                                       \
        void *p = gmsh_symbol(#name, ierr);                                                     \
        if (!p) {                                                                               \
            return -1;                                                                          \
        }                                                                                       \
        memcpy(&fn, &p, sizeof fn);                                                             \
        return fn args;                                                                         \
    }

TF_GMSH_VOID_CALLS(TF_GMSH_DEFINE_VOID)
TF_GMSH_INT_CALLS(TF_GMSH_DEFINE_INT)

/* gmsh's last error, or the loader's when libgmsh cannot be used. */
void gmshLoggerGetLastError(char **error, int *ierr)
{
    void *p = gmsh_symbol("gmshLoggerGetLastError", ierr);
    if (p) {
        void (*fn)(char **, int *);
        memcpy(&fn, &p, sizeof fn);
        fn(error, ierr);
        return;
    }
    void *lib = gmsh_open();
    const char *why = lib ? "a function is missing" : dlerror();
    if (lib) {
        dlclose(lib);
    }
    why = why ? why : "no reason given";
    const size_t n = strlen(gmsh_library()) + strlen(why) + 32;
    *error = malloc(n);
    if (*error) {
        snprintf(*error, n, "cannot use gmsh (%s): %s", gmsh_library(), why);
    }
}

/* gmsh allocates what it returns with malloc (gmshc.h: "free with
 * gmshFree"), and the loader's message above is malloc'ed too. */
void gmshFree(void *p)
{
    free(p);
}
