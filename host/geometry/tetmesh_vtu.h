/*
 * tetmesh_vtu.h — a node cloud with its tetrahedral cells as a VTK
 * XML unstructured grid (.vtu) for ParaView: point data `source` (file
 * vertex index, -1 inside), cell data `volume`.
 */
#ifndef TF_TETMESH_VTU_H
#define TF_TETMESH_VTU_H

#include <stdio.h>

#include "geometry/geom_msg.h"
#include "geometry/tetmesh.h"

void tf_tetmesh_write_vtu(FILE *fp, const tf_tetmesh *t);

/* Writes path through a temporary file renamed on success (nothing
 * half-written).  TF_GEOM_OK or TF_GEOM_FAILED with m->error. */
int tf_tetmesh_save_vtu(const char *path, const tf_tetmesh *t, tf_geom_msg *m);

#endif /* TF_TETMESH_VTU_H */
