"""OpenBLAS pinned as the tissuefit tool pins it (host/base/blas_pin.c).

OpenBLAS reads OPENBLAS_CORETYPE and OPENBLAS_NUM_THREADS once, when the
process loads it; its kernel family and thread count change the last bits
of the solver's factorisation.  The tool re-executes itself with them set;
a Python process cannot, so the package sets them before it loads its
library (and before it imports numpy, which loads the same OpenBLAS), and
the library then checks the kernels OpenBLAS actually runs
(tf_api_blas_check)."""

import os


def _cpu_flags():
    try:
        with open("/proc/cpuinfo", encoding="ascii", errors="replace") as f:
            for line in f:
                if line.startswith("flags"):
                    return set(line.split(":", 1)[1].split())
    except OSError:
        pass
    return set()


def pin():
    """Sets the environment the tool pins, unless the user set it."""
    if os.uname().machine == "x86_64":
        flags = _cpu_flags()
        core = "Haswell" if {"avx2", "fma"} <= flags else "Prescott"
        os.environ.setdefault("OPENBLAS_CORETYPE", core)
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    # as the tool: OpenMP workers sleep between parallel regions (timing only)
    os.environ.setdefault("OMP_WAIT_POLICY", "passive")
