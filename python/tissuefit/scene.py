"""Scenes and their solves (`tissuefit solve`), as numpy arrays."""

import ctypes
import os

import numpy as np

from . import _native
from ._native import Context, lib, ptr


class Scene:
    """A scene file read as `tissuefit` reads it, with `key=value`
    overrides as --set takes them (docs/scene-format.md).

    Attributes (arrays are copies, mm):
      path      the scene file
      nodes     (N, 3) node coordinates; node number = row + 1
      outputs   (M, 3) positions of the scene's outputs
      output_ids (M,) their ids: node numbers, or point numbers 1.. for
                outputs at points (the `output` column of solve --outputs)
      contacts  the contact sites' names, in the scene's order
    Raises tissuefit.Error with the tool's message (file:line: field: ...)."""

    def __init__(self, path, sets=(), log_level=1):
        self.path = os.fspath(path)
        self._ctx = Context(log_level)
        sets = [str(s) for s in sets]
        arr = _native.strings(sets)
        self._p = self._ctx.check(lib.tf_api_scene_load(self._ctx.p, os.fsencode(self.path), arr,
                                                        len(sets)))
        xyz = ctypes.POINTER(ctypes.c_double)()
        n = lib.tf_api_scene_nodes(self._p, ctypes.byref(xyz))
        self.nodes = np.ctypeslib.as_array(xyz, shape=(n, 3)).copy()
        m = lib.tf_api_scene_outputs(self._p, None, None)
        self.outputs = np.empty((m, 3))
        self.output_ids = np.empty(m, dtype=np.uint64)
        lib.tf_api_scene_outputs(self._p, ptr(self.outputs), ptr(self.output_ids))
        self.contacts = [lib.tf_api_scene_contact_name(self._p, k).decode()
                         for k in range(lib.tf_api_scene_contacts(self._p))]

    def close(self):
        """Frees the scene and its solver (also done when it is collected)."""
        if getattr(self, "_p", None):
            lib.tf_api_scene_free(self._p)
            self._p = None

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _handle(self):
        if not self._p:
            raise _native.Error(f"{self.path}: the scene was closed")
        return self._p

    def solve(self, force=None, contact=None, points=None, cut_progress=None):
        """`tissuefit solve SCENE [--force FX,FY,FZ] [--contact NAME]
        [--cut-progress S]`: one load case from rest, the same bits as the
        tool's CSV files.

        force: (3,) N at the contact site (None: only the scene's loads);
        contact: a site's name (None: the first); points: (P, 3) mm where
        the displacement field is also wanted; cut_progress: S in [0, 1],
        every cut of the scene to that fraction of its path (None: whole).
        Returns a Solution.  The solver is built at the first solve and kept
        for the next ones at the same cut progress."""
        f = None if force is None else _native.as_doubles(force, (3,), "force").reshape(3)
        u = np.empty((len(self.nodes), 3))
        v = np.empty((len(self.outputs), 3))
        self._ctx.check(lib.tf_api_solve(self._ctx.p, self._handle(),
                                         None if contact is None else contact.encode(), ptr(f),
                                         float("nan") if cut_progress is None else float(cut_progress),
                                         ptr(u), ptr(v)))
        sol = Solution(self, None if f is None else f.copy(), contact, u, v)
        sol.cut_progress = cut_progress
        if points is not None:
            sol.points = _native.as_doubles(points, (3,), "points").reshape(-1, 3).copy()
            sol.at_points = sol.at(sol.points)
        return sol

    def solve_many(self, forces, contact=None, cut_progress=None):
        """One solve per force of forces (K, 3): the nodes' displacements
        (K, N, 3) and the outputs' (K, M, 3)."""
        fs = _native.as_doubles(forces, (3,), "forces").reshape(-1, 3)
        u = np.empty((len(fs), len(self.nodes), 3))
        v = np.empty((len(fs), len(self.outputs), 3))
        for k, f in enumerate(fs):
            s = self.solve(f, contact, cut_progress=cut_progress)
            u[k], v[k] = s.u, s.outputs
        return u, v

    def solve_history(self, force=None, contact=None):
        """`tissuefit solve SCENE [--force FX,FY,FZ] [--contact NAME]` of a
        scene with a history: section: its time series from rest, the same
        bits as the tool's CSV (step k is row k).

        force: (3,) N replacing history.force (refused for a table of
        forces); contact: a site's name (None: history.contact).  Returns a
        History."""
        f = None if force is None else _native.as_doubles(force, (3,), "force").reshape(3)
        n = ctypes.c_size_t()
        self._ctx.check(lib.tf_api_history_steps(self._ctx.p, self._handle(), ptr(f), ctypes.byref(n)))
        t = np.empty(n.value)
        u = np.empty((n.value, len(self.nodes), 3))
        v = np.empty((n.value, len(self.outputs), 3))
        self._ctx.check(lib.tf_api_solve_history(self._ctx.p, self._handle(),
                                                 None if contact is None else contact.encode(),
                                                 ptr(f), ptr(t), ptr(u), ptr(v)))
        return History(self, None if f is None else f.copy(), contact, t, u, v)

    def regions(self):
        """The material region of every node, (N,) uint32: 0 the body, k the
        k-th of the scene's inclusions (the first holding the node), as the
        tool's VTU files give it ("material"); None without inclusions."""
        if lib.tf_api_scene_regions(self._handle(), None) == 0:
            return None
        r = np.empty(len(self.nodes), dtype=np.uint32)
        lib.tf_api_scene_regions(self._handle(), ptr(r))
        return r

    def cells(self):
        """The cells of the VTU file `tissuefit solve --vtk` writes:
        ("hexahedron", (C, 8)) for a box's grid (without the cells a cut
        passes through, at the cut progress of the last solve) or
        ("tetra", (C, 4)) for an organ; node indices from 0."""
        n, k = ctypes.c_size_t(), ctypes.c_uint()
        self._ctx.check(lib.tf_api_cells(self._ctx.p, self._handle(), ctypes.byref(n), ctypes.byref(k),
                                         None))
        conn = np.empty((n.value, k.value), dtype=np.uint64)
        self._ctx.check(lib.tf_api_cells(self._ctx.p, self._handle(), ctypes.byref(n), ctypes.byref(k),
                                         ptr(conn)))
        return ("hexahedron" if k.value == 8 else "tetra"), conn.astype(np.int64)


class Solution:
    """One solve of a scene.

      force     (3,) N, or None
      contact   the site's name as given (None: the first)
      cut_progress  as given to solve (None: the cuts whole)
      u         (N, 3) displacement of every node, mm
      outputs   (M, 3) displacement at the scene's outputs, mm
      points, at_points  (P, 3) the points asked for and the field there"""

    def __init__(self, scene, force, contact, u, outputs):
        self.scene = scene
        self.force = force
        self.contact = contact
        self.u = u
        self.outputs = outputs
        self.points = None
        self.at_points = None
        self.cut_progress = None

    def at(self, points):
        """The displacement field (mm) at points (P, 3) mm, as an output at
        those points gives it: (P, 3)."""
        x = _native.as_doubles(points, (3,), "points").reshape(-1, 3)
        out = np.empty_like(x)
        sc = self.scene
        sc._ctx.check(lib.tf_api_field(sc._ctx.p, sc._handle(), ptr(np.ascontiguousarray(self.u)),
                                       ptr(x), len(x), ptr(out)))
        return out

    def write_vtu(self, path):
        """The solve as a VTU file for ParaView (tissuefit.write_vtu)."""
        from .vtu import write_vtu
        return write_vtu(path, self)


class History:
    """A scene's history solved (Scene.solve_history).

      force, contact  as given (None: the history's own)
      t         (S,) the steps' times, s
      u         (S, N, 3) displacement of every node at each step, mm
      outputs   (S, M, 3) displacement at the scene's outputs, mm"""

    def __init__(self, scene, force, contact, t, u, outputs):
        self.scene = scene
        self.force = force
        self.contact = contact
        self.t = t
        self.u = u
        self.outputs = outputs
