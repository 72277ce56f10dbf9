"""`tissuefit fit` from Python: the tool's own command, run in this
process, so the header is the tool's byte for byte."""

import ctypes
import os

from . import _native
from ._native import Context, lib
from .header import Header


def fit(scene, out, sets=(), family=None, contact=None, report=None, direct=False,
        budget_us=None, max_error_mm=None, mcu=None, reference=None, discretisation=True,
        log_level=1):
    """Fits the scene and writes out (NAME.h) and NAME_golden.h, as
    `tissuefit fit SCENE -o OUT [--set KEY=VALUE]... [--family F] ...` does
    (docs/fitting.md; the options are the command's; discretisation=False is
    --no-discretisation).  Returns the Header,
    whose info(model) gives the numbers the header states (held-out
    errors, operations, table bytes, cycles).  Raises tissuefit.Error with
    the tool's message; nothing is written then."""
    args = [os.fspath(scene), "-o", os.fspath(out)]
    for s in sets:
        args += ["--set", str(s)]
    for opt, val in (("--family", family), ("--contact", contact), ("--report", report),
                     ("--budget-us", budget_us), ("--max-error-mm", max_error_mm),
                     ("--mcu", mcu), ("--reference", reference)):
        if val is not None:
            args += [opt, os.fspath(val) if isinstance(val, os.PathLike) else str(val)]
    if direct:
        args.append("--direct")
    if not discretisation:
        args.append("--no-discretisation")
    ctx = Context(log_level)
    arr = _native.strings(args)
    status = ctypes.c_int()
    ctx.check(lib.tf_api_fit(ctx.p, arr, len(args), ctypes.byref(status)))
    return Header(out)
