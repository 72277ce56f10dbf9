"""A solve written as VTU with meshio reads back with the point data the
tool's VTU files have ("displacement", "node") and the tool's cells."""

import meshio
import numpy as np
import pytest

import tissuefit
from conftest import same_bits, tool


@pytest.fixture(scope="module")
def written(block48):
    d, sc, sol = block48
    return sc, sol, meshio.read(sol.write_vtu(str(d / "python.vtu"))), meshio.read(d / "tool.vtu")


def test_point_data(written):
    sc, sol, mine, theirs = written
    assert set(mine.point_data) == {"displacement", "node"} == set(theirs.point_data)
    assert same_bits(mine.point_data["displacement"], sol.u)
    assert same_bits(mine.point_data["displacement"], theirs.point_data["displacement"])
    assert np.array_equal(mine.point_data["node"], np.arange(1, len(sc.nodes) + 1))
    assert np.array_equal(mine.point_data["node"], theirs.point_data["node"])
    assert same_bits(mine.points, sc.nodes)


def test_cells(written):
    sc, sol, mine, theirs = written
    assert [c.type for c in mine.cells] == ["hexahedron"] == [c.type for c in theirs.cells]
    assert mine.cells[0].data.shape == (3125, 8)  # the 26 x 26 x 6 graded grid's cells
    assert np.array_equal(mine.cells[0].data, theirs.cells[0].data)


def test_a_cut_leaves_its_cells_out(tmp_path):
    sc = tissuefit.Scene("coeffs/block48_cut.yaml")
    sol = sc.solve((1, 0, 0))
    whole = len(sc.cells()[1])
    tool("-q", "solve", "coeffs/block48_cut.yaml", "--force", "1,0,0", "-o", tmp_path / "u.csv",
         "--vtk", tmp_path / "tool.vtu")
    assert np.array_equal(meshio.read(sol.write_vtu(str(tmp_path / "cut.vtu"))).cells[0].data,
                          meshio.read(tmp_path / "tool.vtu").cells[0].data)
    assert whole < 10 * 10 * 2  # the 11 x 11 x 3 grid without the cells the incision crosses


def test_material_regions(tmp_path):
    bar = "tests/solver/inclusion_bar.yaml"
    sc = tissuefit.Scene(bar)
    r = sc.regions()
    assert r.dtype == np.uint32 and r.shape == (len(sc.nodes),)
    assert np.array_equal(r, (sc.nodes[:, 0] >= 20).astype(np.uint32))  # the stiff half, x >= 20
    tool("-q", "solve", bar, "-o", tmp_path / "u.csv", "--vtk", tmp_path / "tool.vtu")
    mine = meshio.read(sc.solve().write_vtu(str(tmp_path / "bar.vtu")))
    assert np.array_equal(mine.point_data["material"], meshio.read(tmp_path / "tool.vtu").point_data["material"])
    assert tissuefit.Scene("tests/solver/block48_seed.yaml").regions() is None
