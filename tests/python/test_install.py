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
