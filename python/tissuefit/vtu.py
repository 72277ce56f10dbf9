"""Fields to VTK unstructured grids with meshio, named as the files
`tissuefit solve --vtk` writes (report/displacement_out.c): point data
"displacement" (3 components, mm) and "node" (node numbers from 1)."""

import meshio
import numpy as np


def mesh_of(solution):
    """The meshio.Mesh of a Solution: the scene's nodes and cells."""
    sc = solution.scene
    kind, conn = sc.cells()
    return meshio.Mesh(
        points=sc.nodes,
        cells=[(kind, conn)],
        point_data={
            "displacement": np.asarray(solution.u, dtype=np.float64),
            "node": np.arange(1, len(sc.nodes) + 1, dtype=np.uint32),
        },
    )


def write_vtu(path, solution):
    """Writes the solution to path (.vtu) and returns the path."""
    meshio.write(path, mesh_of(solution), file_format="vtu")
    return path
