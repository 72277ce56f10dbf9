/*
 * scene_ranges.h — the range every number of a scene file must lie in.
 *
 * A number far outside what a tissue scene means (E = 1e308 MPa, an
 * envelope of 1e308 N, E = 5e-324) used to pass the checks of its key and
 * fail deep in the fit with a message about NaN or a singular matrix.  The
 * ranges below are checked while the file is read (scene_strict.c), so the
 * message names file, line and field.  Keys with a physical meaning have
 * their own range and unit; every other number is 0 or between 1e-15 and
 * 1e15 in magnitude, so that no product of scene values overflows or
 * underflows a double, and a new key is covered without an entry here.
 */
#ifndef TF_SCENE_RANGES_H
#define TF_SCENE_RANGES_H

#include <stddef.h>

/* Checks the number v found at path (scene_schema.h path syntax, e.g.
 * "material.E", "fixed.2.box.min.0").  Returns 0, or -1 with a message. */
int sd_range_check(const char *path, double v, char *msg, size_t msglen);

#endif /* TF_SCENE_RANGES_H */
