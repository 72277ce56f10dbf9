"""`tissuefit.fit` writes the tool's header, byte for byte, and the
header's numbers and golden vectors come back through Header."""

import os

import numpy as np
import pytest

import tissuefit
from conftest import golden_mismatches, tool, tool_error

SCENE = "tests/solver/block48_seed.yaml"  # the fastest scene the tests fit (about 1 s)


@pytest.fixture(scope="module")
def fitted(tmp_path_factory):
    d = tmp_path_factory.mktemp("fit")
    os.mkdir(d / "tool")
    os.mkdir(d / "python")
    tool("-q", "fit", SCENE, "-o", d / "tool/seed.h")
    return d, tissuefit.fit(SCENE, str(d / "python/seed.h"), log_level=0)


def test_the_tools_bytes(fitted):
    d, h = fitted
    for f in ("seed.h", "seed_golden.h"):
        assert (d / "python" / f).read_bytes() == (d / "tool" / f).read_bytes(), f


def test_no_discretisation(tmp_path):
    """discretisation=False is --no-discretisation: the header says so."""
    tissuefit.fit(SCENE, str(tmp_path / "n.h"), discretisation=False, log_level=0)
    text = (tmp_path / "n.h").read_text()
    assert "error of the solve against the physics: not measured (--no-discretisation;" in text


def test_numbers(fitted):
    d, h = fitted
    assert h.models == ["seed_forward", "seed_contact"]
    fwd = h.info("seed_forward")
    assert fwd["FAMILY"] == "nodal" and fwd["N_OUT"] == 121 and fwd["HELDOUT_CASES"] == 50
    assert 0 < fwd["HELDOUT_MAX_MM"] < 1e-6  # docs/fitting.md: linear scenes within 1 um
    assert fwd["OPS"] == fwd["OPS_ADD"] + fwd["OPS_MUL"] + fwd["OPS_DIV"]


def test_emitted_header_evaluates(fitted):
    d, h = fitted
    sets = h.goldens()
    assert [m.name for m, *_ in sets] == ["seed_forward", "seed_contact"]
    for m, x, st, y in sets:
        assert m.check == 0
        assert golden_mismatches(m, x, st, y) == 0
    fwd = h.model("seed_forward")
    u, status = fwd.evaluate([0.3, 0.0, -0.4])
    assert u.shape == (121, 3) and u.dtype == np.float32 and status == 0
    assert fwd.evaluate([3.0, 0.0, 0.0])[1] == 1  # TFIT_CLAMPED beyond the 1 N envelope
    assert fwd.evaluate([np.nan, 0.0, 0.0])[1] == -1  # TFIT_ERR_INPUT


def test_refused_fit_writes_nothing(tmp_path):
    rc, err = tool("fit", SCENE, "--family", "cubic", "-o", tmp_path / "a.h", check=False)
    assert rc == 2
    with pytest.raises(tissuefit.Error) as e:
        tissuefit.fit(SCENE, str(tmp_path / "b.h"), family="cubic")
    assert str(e.value) == tool_error(err)
    assert os.listdir(tmp_path) == []
