"""Fields to VTK unstructured grids with meshio, named as the files
`tissuefit solve --vtk` writes (report/displacement_out.c): point data
"displacement" (3 components, mm), "node" (node numbers from 1) and, for a
body with material regions, "material" (Scene.regions)."""

import meshio
import numpy as np


def mesh_of(solution):
    """The meshio.Mesh of a Solution: the scene's nodes and cells."""
    sc = solution.scene
    kind, conn = sc.cells()
    data = {
        "displacement": np.asarray(solution.u, dtype=np.float64),
        "node": np.arange(1, len(sc.nodes) + 1, dtype=np.uint32),
    }
    regions = sc.regions()
    if regions is not None:
        data["material"] = regions
    return meshio.Mesh(points=sc.nodes, cells=[(kind, conn)], point_data=data)


def write_vtu(path, solution):
    """Writes the solution to path (.vtu) and returns the path."""
    meshio.write(path, mesh_of(solution), file_format="vtu")
    return path
