"""The stubs describe the wrapper: `mypy --strict` passes on the package and on a typed
example that uses one curve and lists of them (python/examples/typed.py)."""

from __future__ import annotations

import os

import pytest

from conftest import ROOT

try:
    from mypy import api
except ImportError:
    if os.environ.get("CI"):
        raise
    pytest.skip("the typing check needs mypy", allow_module_level=True)


def test_mypy_strict_passes_on_the_package_and_a_typed_example() -> None:
    package = ROOT / "python"
    out, err, status = api.run(
        ["--strict", "--no-incremental", str(package / "curvekit"), str(package / "examples" / "typed.py")]
    )
    assert status == 0, out + err
