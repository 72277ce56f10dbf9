"""The package as `make install` puts it: importable by Debian's python3
from PREFIX/lib/python3.X/dist-packages, its shared library beside it."""

import os
import subprocess
import sys

import tissuefit


def test_imported_from_the_install():
    site = os.environ.get("TISSUEFIT_SITE")
    assert site, "tests/python.mk sets TISSUEFIT_SITE to the installed dist-packages"
    pkg = os.path.dirname(tissuefit.__file__)
    assert os.path.realpath(pkg) == os.path.realpath(os.path.join(site, "tissuefit"))
    for f in ("libtissuefit.so", "libtfit_pic.a", "tfit_shim.c", "include/tfit.h",
              "include/tfit_q31.h"):
        assert os.path.exists(os.path.join(pkg, f)), f


def test_import_in_a_fresh_interpreter():
    r = subprocess.run([sys.executable, "-c", "import tissuefit; print(tissuefit.blas_pinned)"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "True"


def test_blas_pinned_as_the_tool():
    assert tissuefit.blas_pinned


def test_installed_tool_evaluates_as_the_module(tmp_path):
    """`tissuefit eval` from PREFIX/bin finds its evaluator, tfit.h and the
    position-independent libtfit in the install (docs/header-format.md §11)
    and gives the module's bits."""
    import numpy as np
    from conftest import ROOT

    prefix = os.path.abspath(os.path.join(os.environ["TISSUEFIT_SITE"], "..", "..", ".."))
    tool = os.path.join(prefix, "bin", "tissuefit")
    for f in ("share/tfit/tfit_shim.c", "lib/tfit/native-pic/libtfit.a", "include/tfit.h"):
        assert os.path.exists(os.path.join(prefix, f)), f
    header = os.path.join(ROOT, "coeffs", "block48.h")
    forces = np.array([[0.1, 0.2, -0.3], [0.9, -0.7, -0.22], [5, 5, 5], [0, 0, 0]], np.float32)
    src, out = tmp_path / "in.csv", tmp_path / "out.csv"
    src.write_text("fx,fy,fz\n" + "".join("%.9g,%.9g,%.9g\n" % tuple(f) for f in forces))
    r = subprocess.run([tool, "-q", "eval", header, "-i", str(src), "-o", str(out)],
                       capture_output=True, text=True, env=dict(os.environ, TMPDIR=str(tmp_path)))
    assert r.returncode == 0, r.stderr
    got = np.loadtxt(out, delimiter=",", skiprows=1, ndmin=2)
    want, st = tissuefit.Header(header).model("block48_forward").evaluate(forces)
    assert np.array_equal(got[:, 0].astype(np.int32), st)
    assert np.array_equal(got[:, 1:].astype(np.float32).view(np.uint32),
                          want.reshape(len(forces), -1).view(np.uint32))
    assert sorted(os.listdir(tmp_path)) == ["in.csv", "out.csv"]  # its build folder removed
