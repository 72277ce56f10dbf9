"""A solve from Python is `tissuefit solve`'s, to the last bit."""

import numpy as np
import pytest

import tissuefit
from conftest import read_csv, same_bits, tool, tool_error


def test_nodes_bit_for_bit(block48):
    d, sc, sol = block48
    cli = read_csv(d / "u.csv")
    assert np.array_equal(cli[:, 0], np.arange(1, len(sc.nodes) + 1))
    assert same_bits(cli[:, 1:4], sc.nodes)
    assert same_bits(cli[:, 4:7], sol.u)
    assert sol.u.shape == (4056, 3)


def test_outputs_bit_for_bit(block48):
    d, sc, sol = block48
    cli = read_csv(d / "outputs.csv")
    assert np.array_equal(cli[:, 0], sc.output_ids)
    assert same_bits(cli[:, 1:4], sc.outputs)
    assert same_bits(cli[:, 4:7], sol.outputs)
    # block48's outputs are points: the field at them is the same probe
    assert same_bits(cli[:, 4:7], sol.at_points)


def test_one_bit_off_is_seen(block48):
    """The comparison can fail: the last bit of one value flipped."""
    d, sc, sol = block48
    u = sol.u.copy()
    u.view(np.uint64)[60, 2] ^= np.uint64(1)
    assert not same_bits(read_csv(d / "u.csv")[:, 4:7], u)


def test_cut_progress_as_the_tool(tmp_path):
    tool("-q", "solve", "coeffs/block48_cut.yaml", "--force", "1,0,0", "--cut-progress", "0.5",
         "-o", tmp_path / "u.csv")
    sc = tissuefit.Scene("coeffs/block48_cut.yaml")
    whole = sc.solve((1, 0, 0))
    half = sc.solve((1, 0, 0), cut_progress=0.5)
    cli = read_csv(tmp_path / "u.csv")[:, 4:7]
    assert same_bits(cli, half.u)
    assert not same_bits(cli, whole.u)


def test_solve_errors_are_the_tools(tmp_path):
    scene = "tests/solver/block48_seed.yaml"  # relative: the tests run from the top
    sc = tissuefit.Scene(scene)
    for args, kw in (([], {}), (["--force", "1,0,0", "--contact", "nowhere"],
                                {"force": (1, 0, 0), "contact": "nowhere"})):
        rc, err = tool("solve", scene, *args, "-o", tmp_path / "u.csv", check=False)
        assert rc == 2
        with pytest.raises(tissuefit.Error) as e:
            sc.solve(**kw)
        assert str(e.value) == tool_error(err)
    assert not (tmp_path / "u.csv").exists()


def _series(path, n_nodes):
    """tissuefit solve's time series CSV: (times (S,), u (S, N, 3))."""
    rows = read_csv(path)
    steps = rows.reshape(-1, n_nodes, rows.shape[1])
    return steps[:, 0, 1], steps[:, :, 6:9]


@pytest.mark.parametrize("force", [None, (0, 0, -0.3)])
def test_history_as_the_tool(tmp_path, force):
    """A history: section solved as `tissuefit solve` solves it: the times
    and every step's displacements to the last bit, and each step's
    outputs."""
    scene = "tests/solver/kelvin_block48.yaml"  # nonlinear Kelvin: pressed, held, released
    args = [] if force is None else ["--force", ",".join(map(str, force))]
    tool("-q", "solve", scene, *args, "-o", tmp_path / "h.csv")
    sc = tissuefit.Scene(scene)
    h = sc.solve_history(force)
    t, u = _series(tmp_path / "h.csv", len(sc.nodes))
    assert h.u.shape == (len(t), len(sc.nodes), 3) and len(t) > 2
    assert same_bits(t, h.t)
    assert same_bits(u, h.u)
    assert np.abs(h.u).max() > 0.01  # not a body at rest
    # this scene's outputs are nodes (the top face): their nodal values
    assert same_bits(h.outputs, h.u[:, sc.output_ids.astype(np.int64) - 1])
    # each call starts from rest: the same again
    assert same_bits(sc.solve_history(force).u, h.u)


def test_history_refusals(tmp_path):
    """Where the tool refuses, the module says the same; a scene without a
    history is not a time series."""
    sc = tissuefit.Scene("tests/solver/kelvin_block48.yaml")
    with pytest.raises(tissuefit.Error, match="has a history: section: solve it as a time series"):
        sc.solve((0, 0, -1))
    with pytest.raises(tissuefit.Error, match="has no contact site 'nowhere'"):
        sc.solve_history(contact="nowhere")
    with pytest.raises(tissuefit.Error, match="has no history: section"):
        tissuefit.Scene("tests/solver/block48_seed.yaml").solve_history()
