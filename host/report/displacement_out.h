/*
 * displacement_out.h — nodal displacements to files: CSV (the format the
 * project compares with CalculiX: header node,x,y,z,ux,uy,uz, mm, %.17g)
 * and VTK XML unstructured grids for ParaView (hexahedra of the node grid,
 * or an organ's tetrahedra; point data "displacement" and "node", and
 * "material" when the body has material regions: 0 the body, k the k-th
 * inclusion).  The
 * grid cells a cut passes through are left out, so the cut's faces show as
 * a gap whose two lips are the faces of the cells beside it.
 */
#ifndef TF_DISPLACEMENT_OUT_H
#define TF_DISPLACEMENT_OUT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "meshfree/cut.h"
#include "problem/problem.h"

/* Rows for the n nodes idx[] (all nodes when idx is NULL, n ignored). */
void tf_report_csv_displacements(FILE *fp, const tf_cloud *c, const uint32_t *idx, size_t n,
                                 const double *u);

/* A problem's outputs (values v[3 j + a], solvers/probe.h) with header
 * output,x,y,z,ux,uy,uz: output is the node number for outputs at nodes,
 * the point number 1, 2, ... for outputs at points. */
void tf_report_csv_outputs(FILE *fp, const tf_problem *p, const double *v);

/* The hexahedra of a box's grid that the VTU file has: 8 node indices per
 * cell in VTK_HEXAHEDRON order, without the cells the n cuts pass through,
 * malloc'ed into *conn (free() it); their count in *nc.  Returns 0, or -1
 * (out of memory). */
int tf_report_grid_cells(const tf_cloud *c, const tf_cut *cuts, size_t n_cuts, size_t **conn,
                         size_t *nc);

/* A box's whole cloud as a VTU file, without the cells its cuts pass
 * through.  Returns 0, or -1 (out of memory: nothing written). */
int tf_report_vtu_displacements(FILE *fp, const tf_problem *p, const double *u);

/* An organ's cloud as a VTU file: its tetrahedra (4 node indices each). */
void tf_report_vtu_displacements_tets(FILE *fp, const tf_problem *p, const size_t *tet,
                                      size_t ntet, const double *u);

#endif /* TF_DISPLACEMENT_OUT_H */
