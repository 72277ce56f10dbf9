"""Generated headers: their stated numbers, and their models evaluated by
libtfit bit for bit.

A Header compiles the header (and its golden file, when it is beside it)
with tfit_shim.c and the position-independent libtfit into a shared object,
with the project's bit-exact flags, and loads it with ctypes."""

import atexit
import ctypes
import os
import re
import shutil
import subprocess
import tempfile

import numpy as np

from ._native import HERE, Error, ptr

# The flags of the project's bit-exact builds (target/target.mk,
# tests/tests.mk's golden runners): strict C11, no contraction of a*b+c.
BITEXACT_FLAGS = ["-std=c11", "-O2", "-ffp-contract=off", "-Wall", "-Wextra"]

FAMILIES = {1: "nodal", 2: "modal", 3: "zhou2017", 4: "contact", 5: "prony", 6: "cut",
            7: "resonant", 8: "modal_q15", 9: "region", 10: "region_surface"}

_MODEL = re.compile(r"^extern const tfit_model (tfit_\w+);", re.M)
_MODEL_Q31 = re.compile(r"^extern const tfit_model_q31 (tfit_\w+);", re.M)
_GOLDEN = re.compile(r"^static const tfit_golden (tfit_\w+) =", re.M)
_GOLDEN_Q31 = re.compile(r"^static const tfit_golden_q31 (tfit_\w+) =", re.M)
_DEFINE = re.compile(r"^#define (TFIT_\w+) (.*?)\s*(?:/\*.*)?$", re.M)


def _value(text):
    """A macro's value: int, float, str or tuple, as the header writes it."""
    t = text.strip()
    if t.startswith('"') and t.endswith('"'):
        return t[1:-1]
    if t.startswith("{") and t.endswith("}"):
        return tuple(_value(x) for x in t[1:-1].split(","))
    m = re.fullmatch(r"(0x[0-9a-fA-F]+|\d+)u?", t)
    if m:
        return int(m.group(1), 0)
    try:
        return float(t)
    except ValueError:
        return t


def _workdir():
    d = tempfile.mkdtemp(prefix="tissuefit-")
    atexit.register(shutil.rmtree, d, True)
    return d


class Header:
    """A generated header NAME.h (docs/header-format.md).

      path, golden_path (None when NAME_golden.h is not beside it), name
      models      names of its float models, e.g. ["block48_forward", ...]
      models_q31  names of its Q31 models
      info(model) the header's numbers for a model: {"FAMILY": "nodal",
                  "N_OUT": 121, "HELDOUT_MAX_MM": 1.36e-07, ...}"""

    def __init__(self, path, cc=None):
        self.path = os.path.abspath(os.fspath(path))
        base, ext = os.path.splitext(self.path)
        if ext != ".h":
            raise Error(f"{path}: not a generated header (NAME.h)")
        self.name = os.path.basename(base)
        golden = base + "_golden.h"
        self.golden_path = golden if os.path.exists(golden) else None
        try:
            with open(self.path, encoding="ascii", errors="replace") as f:
                self._text = f.read()
            self._golden_text = ""
            if self.golden_path:
                with open(self.golden_path, encoding="ascii", errors="replace") as f:
                    self._golden_text = f.read()
        except OSError as e:
            raise Error(f"{path}: {e.strerror}") from None
        self.models = [m[len("tfit_"):] for m in _MODEL.findall(self._text)]
        self.models_q31 = [m[len("tfit_"):] for m in _MODEL_Q31.findall(self._text)]
        if not self.models:
            raise Error(f"{path}: declares no tfit_model: not a generated header")
        self._defines = {k: v for k, v in _DEFINE.findall(self._text)}
        self._cc = cc or os.environ.get("CC", "gcc")
        self._lib = None

    def info(self, model):
        """The header's #define numbers of model (a name of .models)."""
        prefix = "TFIT_" + model.upper() + "_"
        return {k[len(prefix):]: _value(v) for k, v in self._defines.items() if k.startswith(prefix)}

    # ---- the compiled evaluator --------------------------------------------

    def _compile(self):
        if self._lib is not None:
            return self._lib
        work = _workdir()
        lines = [f"TF_SHIM_MODEL(tfit_{m})" for m in self.models]
        lines += [f"TF_SHIM_MODEL_Q31(tfit_{m})" for m in self.models_q31]
        lines += [f"TF_SHIM_GOLDEN({g})" for g in _GOLDEN.findall(self._golden_text)]
        lines += [f"TF_SHIM_GOLDEN_Q31({g})" for g in _GOLDEN_Q31.findall(self._golden_text)]
        with open(os.path.join(work, "shim_list.h"), "w") as f:
            f.write("\n".join(lines) + "\n")
        so = os.path.join(work, self.name + ".so")
        cmd = [self._cc, *BITEXACT_FLAGS, "-fPIC", "-shared",
               "-I" + os.path.dirname(self.path), "-I" + os.path.join(HERE, "include"), "-I" + work,
               f'-DTF_SHIM_HEADER_FILE="{self.name}.h"', '-DTF_SHIM_LIST_FILE="shim_list.h"',
               f"-DTFIT_{self.name.upper()}_IMPLEMENTATION"]
        if self.golden_path:
            cmd.append(f'-DTF_SHIM_GOLDEN_FILE="{self.name}_golden.h"')
        cmd += [os.path.join(HERE, "tfit_shim.c"), os.path.join(HERE, "libtfit_pic.a"), "-o", so]
        try:
            r = subprocess.run(cmd, capture_output=True, text=True)
        except OSError as e:
            raise Error(f"{self.path}: cannot run the C compiler {self._cc}: {e.strerror}") from None
        if r.returncode != 0:
            raise Error(f"{self.path}: does not compile with libtfit ({' '.join(cmd)}):\n{r.stderr}")
        lib = ctypes.CDLL(so)
        c = ctypes
        u32, i32, P = c.c_uint32, c.c_int32, c.c_void_p
        for name, res, args in [
            ("tf_shim_models", u32, []), ("tf_shim_model_name", c.c_char_p, [u32]),
            ("tf_shim_model_info", i32, [u32, P]), ("tf_shim_eval", i32, [u32, u32, P, P, P, P]),
            ("tf_shim_cut_golden_s", c.c_float, [u32]), ("tf_shim_goldens", u32, []),
            ("tf_shim_golden", i32, [u32, P, P, P, P, P]), ("tf_shim_golden_run", u32, [u32]),
            ("tf_shim_models_q31", u32, []), ("tf_shim_model_q31_name", c.c_char_p, [u32]),
            ("tf_shim_model_q31_info", i32, [u32, P]), ("tf_shim_eval_q31", i32, [u32, u32, P, P, P]),
            ("tf_shim_goldens_q31", u32, []), ("tf_shim_golden_q31", i32, [u32, P, P, P, P, P]),
            ("tf_shim_golden_run_q31", u32, [u32]),
        ]:
            f = getattr(lib, name)
            f.restype, f.argtypes = res, args
        self._lib = lib
        return lib

    def model(self, name):
        """The compiled model `name` (of .models or .models_q31)."""
        lib = self._compile()
        q31 = name in self.models_q31
        names = self.models_q31 if q31 else self.models
        if name not in names:
            raise Error(f"{self.path}: no model {name} (it has {', '.join(self.models + self.models_q31)})")
        return Model(self, lib, names.index(name), name, q31)

    def goldens(self, q31=False):
        """The golden sets of NAME_golden.h: a list of (model, inputs,
        statuses, outputs), inputs (V, 3) and outputs (V, n_out, 3) as the
        header's float32 (int32 for Q31) values, statuses (V,) int32."""
        lib = self._compile()
        count = lib.tf_shim_goldens_q31() if q31 else lib.tf_shim_goldens()
        get = lib.tf_shim_golden_q31 if q31 else lib.tf_shim_golden
        sets = []
        for j in range(count):
            mi, nv = ctypes.c_uint32(), ctypes.c_uint32()
            pin, pst, pout = ctypes.c_void_p(), ctypes.c_void_p(), ctypes.c_void_p()
            if get(j, ctypes.byref(mi), ctypes.byref(nv), ctypes.byref(pin), ctypes.byref(pst),
                   ctypes.byref(pout)) != 0:
                raise Error(f"{self.golden_path}: golden set {j} names a model the header does not declare")
            m = self.model((self.models_q31 if q31 else self.models)[mi.value])
            v, n = nv.value, m.n_out
            word = ctypes.c_int32 if q31 else ctypes.c_uint32
            dtype = np.int32 if q31 else np.float32

            def arr(p, count, t=word):
                return np.ctypeslib.as_array(ctypes.cast(p, ctypes.POINTER(t)), shape=(count,)).copy()

            inputs = arr(pin, 3 * v).view(dtype).reshape(v, 3)
            statuses = arr(pst, v, ctypes.c_int32)
            outputs = arr(pout, 3 * n * v).view(dtype).reshape(v, n, 3)
            sets.append((m, inputs, statuses, outputs))
        return sets

    def golden_run(self, q31=False):
        """libtfit's own count of mismatching words per golden set
        (tfit_golden_run): 0 when bit-exact."""
        lib = self._compile()
        if q31:
            return [lib.tf_shim_golden_run_q31(j) for j in range(lib.tf_shim_goldens_q31())]
        return [lib.tf_shim_golden_run(j) for j in range(lib.tf_shim_goldens())]


class Model:
    """One model of a header, evaluated by libtfit.

      name, family (e.g. "nodal", "contact"), n_out (output points), q31
      check   tfit_model_check's status (0: TFIT_OK)"""

    def __init__(self, header, lib, index, name, q31):
        self.header, self.name, self.q31 = header, name, q31
        self._lib, self._i = lib, index
        info = (ctypes.c_uint32 * 3)()
        fn = lib.tf_shim_model_q31_info if q31 else lib.tf_shim_model_info
        self.check = fn(index, info)
        self.family = FAMILIES.get(info[0], str(info[0]))
        self.n_out = info[1]

    def __repr__(self):
        return f"<tissuefit.Model {self.name} ({self.family}, {self.n_out} outputs)>"

    def evaluate(self, inputs, s=None):
        """inputs (K, 3) or (3,): forces in N (forward models) or contact
        displacements in mm (the contact family); as float32, the words
        libtfit evaluates (int32 in the header's Q31 scaling for a Q31
        model).  s (K,): the cut progress of a cut model.  A prony or
        resonant model steps the K inputs as one tick sequence from rest.

        Returns (outputs, status): outputs (K, n_out, 3) displacements in mm
        (forces in N for the contact family) as float32 (int32 for Q31),
        status (K,) int32 (tfit.h: 0 TFIT_OK, 1 TFIT_CLAMPED, -1
        TFIT_ERR_INPUT, ...).  A single input gives (n_out, 3) and a scalar
        status."""
        dtype = np.int32 if self.q31 else np.float32
        x = np.asarray(inputs)
        single = x.ndim == 1
        x = np.ascontiguousarray(x.reshape(-1, 3), dtype=dtype)
        k = len(x)
        out = np.empty((k, self.n_out, 3), dtype=dtype)
        st = np.empty(k, dtype=np.int32)
        if self.q31:
            rc = self._lib.tf_shim_eval_q31(self._i, k, ptr(x), ptr(out), ptr(st))
        else:
            sv = None
            if s is not None:
                sv = np.ascontiguousarray(np.broadcast_to(np.asarray(s, dtype=np.float32), (k,)))
            elif self.family == "cut":
                raise Error(f"{self.name}: a cut model needs its cut progress s")
            rc = self._lib.tf_shim_eval(self._i, k, ptr(x), ptr(sv), ptr(out), ptr(st))
        if rc != 0:
            raise Error(f"{self.name}: evaluation refused")
        return (out[0], int(st[0])) if single else (out, st)

    def cut_golden_s(self, count):
        """The cut progress of golden vectors 0..count-1 (tfit.h's
        TFIT_CUT_GOLDEN_S_BITS[v mod 16]), float32."""
        return np.array([self._lib.tf_shim_cut_golden_s(v) for v in range(count)], dtype=np.float32)
