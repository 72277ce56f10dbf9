/*
 * gmsh_session.c — initialise and finalise gmsh for one job
 * (gmsh_session.h).
 */
#include "geometry/gmsh_session.h"

#include <gmshc.h>
#include <stdio.h>

void tf_gmsh_begin(void)
{
    int ierr = 0;
    gmshInitialize(0, NULL, 0, &ierr);
    gmshOptionSetNumber("General.Terminal", 0, &ierr);
    gmshOptionSetNumber("General.Verbosity", 1, &ierr); /* errors */
    gmshOptionSetNumber("General.NumThreads", 1, &ierr);
    gmshOptionSetNumber("Mesh.MaxNumThreads1D", 1, &ierr);
    gmshOptionSetNumber("Mesh.MaxNumThreads2D", 1, &ierr);
    gmshOptionSetNumber("Mesh.MaxNumThreads3D", 1, &ierr);
    gmshOptionSetNumber("Mesh.RandomSeed", 1, &ierr);
    gmshLoggerStart(&ierr);
}

void tf_gmsh_end(void)
{
    int ierr = 0;
    gmshLoggerStop(&ierr);
    gmshFinalize(&ierr);
}

int tf_gmsh_fail(tf_geom_msg *m, int code, const char *what)
{
    int ierr = 0;
    char *last = NULL;
    gmshLoggerGetLastError(&last, &ierr);
    tf_geom_fail(m, code, "%s: %s", what,
                 last && last[0] ? last : "gmsh failed without a message");
    gmshFree(last);
    return code;
}
