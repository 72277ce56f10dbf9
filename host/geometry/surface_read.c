/*
 * surface_read.c — which library reads which mesh format (surface_read.h).
 */
#include "geometry/surface_read.h"

#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "base/input_file.h"
#include "geometry/obj_digits.h"

typedef int (*reader)(const char *, tf_surface *, tf_geom_msg *);

/* The reader for a file name's extension, or NULL. */
static reader reader_for(const char *ext)
{
    static const char *const by_assimp[] = {"obj", "stl", "ply", "off"};
    if (strcasecmp(ext, "vtk") == 0) {
        return tf_surface_read_gmsh;
    }
    for (size_t k = 0; k < sizeof by_assimp / sizeof by_assimp[0]; ++k) {
        if (strcasecmp(ext, by_assimp[k]) == 0) {
            return tf_surface_read_assimp;
        }
    }
    return NULL;
}

/* An OBJ's coordinates as the file writes them (assimp's are float32). */
static int obj_digits(const char *path, tf_surface *s, tf_geom_msg *m)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    size_t len;
    char *text = tf_input_file_read(&ctx, path, "surface mesh", TF_SURFACE_MAX_BYTES, &len);
    int rc = text != NULL ? tf_obj_digits_restore(path, text, len, s, m)
                          : tf_geom_fail(m, TF_GEOM_FAILED, "%s", ctx.err);
    free(text);
    if (rc != TF_GEOM_OK) {
        tf_surface_free(s);
    }
    return rc;
}

int tf_surface_read(const char *path, tf_surface *s, tf_geom_msg *m)
{
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    const char *ext = dot && (slash == NULL || dot > slash) ? dot + 1 : "";
    reader read = reader_for(ext);
    if (read == NULL) {
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                            "'%s': unknown mesh format '.%s' (read: .obj .stl .ply .off .vtk)",
                            path, ext);
    }
    /* gmsh takes a missing file for a new, empty model, a FIFO would block
     * either library, and nothing bounds their time on a huge mesh: the
     * file is checked first (base/input_file.h) */
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    if (tf_input_file_check(&ctx, path, "surface mesh", TF_SURFACE_MAX_BYTES) != 0) {
        size_t n = strlen(path); /* the message begins "PATH: " */
        const char *why = strncmp(ctx.err, path, n) == 0 ? ctx.err + n + 2 : ctx.err;
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT, "cannot read mesh '%s': %s", path, why);
    }
    int rc = read(path, s, m);
    if (rc == TF_GEOM_OK && strcasecmp(ext, "obj") == 0) {
        rc = obj_digits(path, s, m);
    }
    return rc;
}
