"""Shared helpers: the repository's fixtures and the `curvekit` tool the package is compared
with (``CURVEKIT_BIN``, else the workspace's build)."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
FIXTURES = ROOT / "fixtures"


def tool_path() -> Path:
    given = os.environ.get("CURVEKIT_BIN")
    if given:
        return Path(given)
    for profile in ("release", "debug"):
        candidate = ROOT / "target" / profile / "curvekit"
        if candidate.exists():
            return candidate
    pytest.skip("no curvekit tool built: run cargo build (or set CURVEKIT_BIN)")


def run_tool(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [str(tool_path()), *args], capture_output=True, text=True, check=False
    )


def tool_json(*args: str) -> dict:
    """The tool's --json document (asserting success)."""
    done = run_tool(*args, "--json")
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.fixture
def fixtures() -> Path:
    return FIXTURES
