"""Errors cross into Python as tissuefit.Error with the tool's message:
a broken scene's names its file, line and field."""

import re

import pytest

import tissuefit
from conftest import tool, tool_error


@pytest.fixture
def broken(tmp_path, root):
    text = open(f"{root}/tests/solver/block48_seed.yaml").read()
    assert "  nu: 0.49" in text
    path = tmp_path / "broken.yaml"
    path.write_text(text.replace("  nu: 0.49", "  nu: 0.7"))
    line = text[: text.index("  nu: 0.49")].count("\n") + 1
    return str(path), line


def test_broken_scene(broken, tmp_path):
    path, line = broken
    with pytest.raises(tissuefit.Error) as e:
        tissuefit.Scene(path)
    msg = str(e.value)
    assert msg.startswith(f"{path}:{line}: material.nu: "), msg
    rc, err = tool("solve", path, "--force", "1,0,0", "-o", tmp_path / "u.csv", check=False)
    assert rc == 2 and msg == tool_error(err)


def test_broken_set():
    with pytest.raises(tissuefit.Error, match=re.escape("--set material.E=-1: material.E: ")):
        tissuefit.Scene("tests/solver/block48_seed.yaml", sets=["material.E=-1"])


def test_missing_file(tmp_path):
    with pytest.raises(tissuefit.Error, match=re.escape(str(tmp_path / "none.yaml"))):
        tissuefit.Scene(tmp_path / "none.yaml")


def test_error_is_an_exception_class():
    assert issubclass(tissuefit.Error, Exception)
