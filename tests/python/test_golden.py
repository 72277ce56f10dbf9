"""Every shipped header's golden inputs, evaluated from Python through
libtfit, give the golden outputs and statuses bit for bit
(docs/header-format.md §7), float and Q31 models alike."""

import glob
import os

import numpy as np
import pytest

import tissuefit
from conftest import ROOT, golden_mismatches

SHIPPED = sorted(p for p in glob.glob(os.path.join(ROOT, "coeffs/*.h")) if not p.endswith("_golden.h"))
# and the resonant family's fitted test header (tests/resonant.mk: not shipped)
HEADERS = SHIPPED + [os.path.join(ROOT, "tests/resonant/block48_dyn.h")]


def test_every_shipped_header_is_here():
    # the ten headers make coeffs writes, each beside its scene and golden file
    assert len(SHIPPED) == 10, SHIPPED
    for p in HEADERS:
        assert os.path.exists(p[:-2] + ".yaml") and os.path.exists(p[:-2] + "_golden.h"), p


@pytest.mark.parametrize("path", HEADERS, ids=[os.path.basename(p) for p in HEADERS])
def test_golden(path):
    h = tissuefit.Header(path)
    assert h.golden_path is not None
    floats, q31 = h.goldens(), h.goldens(q31=True)
    # every float model has its vectors; the Q31 sets are those the header has
    assert sorted(m.name for m, *_ in floats) == sorted(h.models)
    assert sorted(m.name for m, *_ in q31) == sorted(h.models_q31)
    for m, x, st, y in floats + q31:
        assert m.check == 0, m.name
        assert golden_mismatches(m, x, st, y) == 0, m.name
    # libtfit's own runner agrees
    assert h.golden_run() == [0] * len(floats)
    assert h.golden_run(q31=True) == [0] * len(q31)


def test_a_flipped_bit_and_a_wrong_status_are_counted():
    """The comparison can fail: one output bit and one status changed."""
    h = tissuefit.Header(os.path.join(ROOT, "coeffs/block48.h"))
    for m, x, st, y in h.goldens() + h.goldens(q31=True):
        y2 = y.copy()
        y2.reshape(-1).view(np.uint32)[7] ^= np.uint32(1)
        st2 = st.copy()
        st2[3] = 1 - st2[3]
        assert golden_mismatches(m, x, st, y2) == 1
        assert golden_mismatches(m, x, st2, y) == 1
