"""The type stub matches the native module, and the pure-Python modules type-check."""

import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("mypy")

ROOT = Path(__file__).resolve().parents[2]


def mypy(*args):
    return subprocess.run(
        [sys.executable, "-m", *args], capture_output=True, text=True, cwd=ROOT
    )


def test_stubtest_native_module():
    """Every public name of burmester._burmester is in the stub with a matching signature."""
    p = mypy(
        "mypy.stubtest", "burmester._burmester",
        "--allowlist", str(ROOT / "tests" / "python" / "stubtest_allowlist.txt"),
    )
    assert p.returncode == 0, p.stdout + p.stderr


def test_mypy_strict_on_the_package():
    """The package (stub included) passes ``mypy --strict`` (with matplotlib's own types)."""
    pytest.importorskip("matplotlib")
    p = mypy("mypy", "--strict", "--no-error-summary", str(ROOT / "python" / "burmester"))
    assert p.returncode == 0, p.stdout + p.stderr
