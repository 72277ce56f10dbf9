"""The shared library libtissuefit.so (host/api/api.h) through ctypes, and
the exception its failures become."""

import ctypes
import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))


class Error(Exception):
    """A failure of tissuefit.  str(e) is the message the tissuefit tool
    prints after "tissuefit: error: " for the same input (a scene's names
    its file, line and field)."""


def _load():
    path = os.path.join(HERE, "libtissuefit.so")
    if not os.path.exists(path):
        raise ImportError(f"tissuefit: {path} is missing: install the package with `make install`")
    lib = ctypes.CDLL(path)
    c = ctypes
    sig = {
        "tf_api_ctx_new": (c.c_void_p, [c.c_int]),
        "tf_api_ctx_free": (None, [c.c_void_p]),
        "tf_api_ctx_error": (c.c_char_p, [c.c_void_p]),
        "tf_api_blas_check": (c.c_int, [c.c_void_p]),
        "tf_api_scene_load": (c.c_void_p, [c.c_void_p, c.c_char_p, c.POINTER(c.c_char_p), c.c_size_t]),
        "tf_api_scene_free": (None, [c.c_void_p]),
        "tf_api_scene_nodes": (c.c_size_t, [c.c_void_p, c.POINTER(c.POINTER(c.c_double))]),
        "tf_api_scene_outputs": (c.c_size_t, [c.c_void_p, c.c_void_p, c.c_void_p]),
        "tf_api_scene_regions": (c.c_size_t, [c.c_void_p, c.c_void_p]),
        "tf_api_scene_contacts": (c.c_size_t, [c.c_void_p]),
        "tf_api_scene_contact_name": (c.c_char_p, [c.c_void_p, c.c_size_t]),
        "tf_api_solve": (c.c_int, [c.c_void_p, c.c_void_p, c.c_char_p, c.c_void_p, c.c_double, c.c_void_p,
                                   c.c_void_p]),
        "tf_api_history_steps": (c.c_int, [c.c_void_p, c.c_void_p, c.c_void_p, c.POINTER(c.c_size_t)]),
        "tf_api_solve_history": (c.c_int, [c.c_void_p, c.c_void_p, c.c_char_p, c.c_void_p, c.c_void_p,
                                           c.c_void_p, c.c_void_p]),
        "tf_api_field": (c.c_int, [c.c_void_p, c.c_void_p, c.c_void_p, c.c_void_p, c.c_size_t, c.c_void_p]),
        "tf_api_cells": (c.c_int, [c.c_void_p, c.c_void_p, c.POINTER(c.c_size_t), c.POINTER(c.c_uint),
                                   c.c_void_p]),
        "tf_api_fit": (c.c_int, [c.c_void_p, c.POINTER(c.c_char_p), c.c_size_t, c.POINTER(c.c_int)]),
    }
    for name, (res, args) in sig.items():
        f = getattr(lib, name)
        f.restype = res
        f.argtypes = args
    return lib


lib = _load()


def ptr(a):
    """The data pointer of a C-contiguous numpy array (None for None)."""
    return None if a is None else a.ctypes.data_as(ctypes.c_void_p)


def strings(items):
    """A C array of char * for a list of str (kept alive by the caller)."""
    arr = (ctypes.c_char_p * max(1, len(items)))()
    for i, s in enumerate(items):
        arr[i] = os.fsencode(s) if isinstance(s, (str, os.PathLike)) else bytes(s)
    return arr


class Context:
    """A tf_ctx (host/base/context.h) for one object's calls: messages at
    or below log_level (0 errors, 1 warnings, 2 progress) go to standard
    error as the tool writes them; failures raise Error."""

    def __init__(self, log_level=1):
        self._p = lib.tf_api_ctx_new(int(log_level))
        if not self._p:
            raise MemoryError("tissuefit: out of memory for a context")

    @property
    def p(self):
        return self._p

    def error(self):
        return Error(lib.tf_api_ctx_error(self._p).decode("utf-8", "replace"))

    def check(self, rc):
        """Raises the context's message when rc is -1 or NULL."""
        if rc is None or rc == -1:
            raise self.error()
        return rc

    def __del__(self):
        if getattr(self, "_p", None):
            lib.tf_api_ctx_free(self._p)
            self._p = None


def blas_check():
    """None when OpenBLAS runs the kernels the tool pins, else the message."""
    ctx = Context(0)
    if lib.tf_api_blas_check(ctx.p) != 0:
        return str(ctx.error())
    return None


def as_doubles(a, shape_tail, what):
    """a as a C-contiguous float64 array of shape (..., *shape_tail)."""
    x = np.ascontiguousarray(a, dtype=np.float64)
    if x.shape[x.ndim - len(shape_tail):] != tuple(shape_tail):
        raise ValueError(f"{what}: expected shape (..., {', '.join(map(str, shape_tail))}), got {x.shape}")
    return x
