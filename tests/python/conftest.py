"""Shared set-up of the Python module's tests (tests/python.mk runs them
against a `make install` into build/tests/python/install).

The package is imported first, before numpy, as docs/python.md asks: it
pins OpenBLAS as the tool does before anything loads it."""

import os
import subprocess

import tissuefit  # (first: see above)

import numpy as np
import pytest

ROOT = os.environ.get("TISSUEFIT_ROOT", os.getcwd())
TOOL = os.environ.get("TISSUEFIT_TOOL", os.path.join(ROOT, "build/bin/tissuefit"))


def tool(*args, check=True):
    """Runs the tissuefit tool from the repository's top; (rc, stderr)."""
    r = subprocess.run([TOOL, *map(str, args)], cwd=ROOT, capture_output=True, text=True)
    if check and r.returncode != 0:
        raise AssertionError(f"tissuefit {' '.join(map(str, args))}: exit {r.returncode}\n{r.stderr}")
    return r.returncode, r.stderr


def tool_error(stderr):
    """The message of the tool's last "tissuefit: error: " line."""
    lines = [ln for ln in stderr.splitlines() if ln.startswith("tissuefit: error: ")]
    assert lines, f"the tool printed no error: {stderr!r}"
    return lines[-1][len("tissuefit: error: "):]


def read_csv(path):
    """A CSV file the tool writes (%.17g: exact doubles) as an array."""
    return np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


def same_bits(a, b):
    """True when two float64 arrays hold the same bits."""
    a, b = np.ascontiguousarray(a, dtype=np.float64), np.ascontiguousarray(b, dtype=np.float64)
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


def golden_mismatches(model, inputs, statuses, outputs):
    """Mismatching words (statuses and output bits) when the model
    evaluates the golden inputs, as tfit_golden_run counts them."""
    s = model.cut_golden_s(len(inputs)) if model.family == "cut" else None
    got, st = model.evaluate(inputs, s)
    word = np.int32 if model.q31 else np.uint32
    return int((st != statuses).sum()) + int((got.view(word) != outputs.view(word)).sum())


@pytest.fixture(scope="session")
def root():
    return ROOT


BLOCK48_FORCE = (0.9, -0.7, -0.22)  # the seed's ANSYS load case (docs/validation.md)


@pytest.fixture(scope="session")
def block48(tmp_path_factory):
    """coeffs/block48.yaml solved once by the tool (CSV, outputs, VTU) and
    once from Python (with the field at its output points): (dir, scene,
    solution)."""
    d = tmp_path_factory.mktemp("block48")
    tool("-q", "solve", "coeffs/block48.yaml", "--force", ",".join(map(str, BLOCK48_FORCE)),
         "-o", d / "u.csv", "--outputs", d / "outputs.csv", "--vtk", d / "tool.vtu")
    sc = tissuefit.Scene("coeffs/block48.yaml")
    return d, sc, sc.solve(BLOCK48_FORCE, points=sc.outputs)
