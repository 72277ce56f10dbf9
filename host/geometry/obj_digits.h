/*
 * obj_digits.h — an OBJ file's vertex coordinates as the file writes them,
 * for a surface read through assimp.  Debian's assimp parses coordinates
 * into float32, whose 24 bits keep about 7 significant digits: a vertex at
 * z = 1073.67 comes back as 1073.6700439, an offset of -1061.67 then leaves
 * 12.0000439, and a clamp "z <= 12" loses the vertex.
 */
#ifndef TF_OBJ_DIGITS_H
#define TF_OBJ_DIGITS_H

#include "geometry/geom_msg.h"
#include "geometry/surface.h"

/* Replaces each finite vertex of s (as assimp read the OBJ at path, whose
 * len bytes of text are given, NUL-terminated: it is cut into lines in
 * place) by the coordinates of the `v` record it came from, parsed as
 * double.  Returns TF_GEOM_OK; TF_GEOM_BAD_INPUT when the text holds a NUL
 * byte, when a vertex matches no record, or when two different records lie
 * closer than float32 tells apart (assimp has then joined them), naming the
 * lines; TF_GEOM_FAILED when out of memory. */
int tf_obj_digits_restore(const char *path, char *text, size_t len, tf_surface *s,
                          tf_geom_msg *m);

#endif /* TF_OBJ_DIGITS_H */
