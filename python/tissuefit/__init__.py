"""tissuefit from Python: scenes solved into numpy arrays, headers fitted,
generated models evaluated by libtfit bit for bit, fields to VTU with
meshio (docs/python.md).

    import tissuefit                       # before numpy: see docs/python.md
    sc = tissuefit.Scene("coeffs/block48.yaml", sets=["geometry.grid=11,11,3"])
    sol = sc.solve(force=[0.9, -0.7, -0.22])   # sol.u (N, 3) mm, as `tissuefit solve`
    sol.write_vtu("block48.vtu")
    h = tissuefit.fit("scene.yaml", "build/scene.h")
    u, status = h.model("scene_forward").evaluate([[0.1, 0, -0.3]])
"""

from . import _blas

_blas.pin()  # before anything loads OpenBLAS (numpy, the library)

import warnings  # noqa: E402

from ._native import Error, blas_check  # noqa: E402
from .fit import fit  # noqa: E402
from .header import Header, Model  # noqa: E402
from .scene import History, Scene, Solution  # noqa: E402
from .vtu import write_vtu  # noqa: E402

__all__ = ["Error", "Scene", "Solution", "History", "fit", "Header", "Model", "write_vtu", "blas_pinned"]
__version__ = "0.1.0"

_blas_problem = blas_check()
blas_pinned = _blas_problem is None
if not blas_pinned:
    warnings.warn(_blas_problem, RuntimeWarning, stacklevel=2)
