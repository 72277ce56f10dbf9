/*
 * gmsh_session.h — gmsh is one process-wide state.  A session initialises
 * it for one job and finalises it afterwards: no configuration files read,
 * nothing printed, one thread everywhere and gmsh's fixed random seed (so
 * that the same input gives the same mesh bits), messages kept so that a
 * failure can say what gmsh said.  Not re-entrant, not thread-safe.
 */
#ifndef TF_GMSH_SESSION_H
#define TF_GMSH_SESSION_H

#include "geometry/geom_msg.h"

void tf_gmsh_begin(void);
void tf_gmsh_end(void);

/* Sets m->error to "WHAT: <gmsh's last error>" and returns code. */
int tf_gmsh_fail(tf_geom_msg *m, int code, const char *what);

#endif /* TF_GMSH_SESSION_H */
