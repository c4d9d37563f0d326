"""The real-world corpus sample (fixtures/corpus: icons, font glyphs, DXF parts) judged by the
independent oracle in corpus/oracle.py (shapely/GEOS, svgelements, ezdxf; no curvekit code).

Fails on any wrong answer that is certified, any crash or time-out, any refusal of an input the
contract requires an answer for, and any refusal that names the wrong cause. Known current
failures are listed in XFAIL by (file, command) with what was found; the list is strict, so an
entry whose failure is fixed must be removed.
"""

from __future__ import annotations

import json
import os
import sys

import pytest

from conftest import ROOT, tool_path

SAMPLE = ROOT / "fixtures" / "corpus"
FAILING = {"wrong-certified", "crash", "timeout", "oracle-error", "refused-valid", "refused-wrong-cause"}

try:
    sys.path.insert(0, str(ROOT / "corpus"))
    from run import judge_corpus  # noqa: E402
except ImportError as missing:  # the oracle's packages: shapely, svgelements, ezdxf, scipy
    if os.environ.get("CI"):
        raise
    pytest.skip(f"the corpus oracle needs {missing.name}", allow_module_level=True)

MANIFEST = json.loads((SAMPLE / "manifest.json").read_text())["files"]

# (file, command) -> what is wrong, for outcomes known to break the rules (found with the
# binary of the day, see corpus/README.md). None are known today.
XFAIL: dict[tuple[str, str], str] = {}


def failures(outcomes: list[dict], valid: bool) -> list[str]:
    """The outcomes that break the corpus's rules; a refusal of a file the manifest marks valid is
    one even where today's oracle would accept it."""
    found = []
    for o in outcomes:
        refused_valid = valid and o["status"] == "refused"
        if o["status"] in FAILING or refused_valid or (o["status"] == "answered-invalid" and o["certified"]):
            detail = o["problems"][:2] or [o["message"][:200]]
            found.append(f"{o['command']} {' '.join(o['args'][2:])}: {o['status']}: {'; '.join(detail)}")
    return found


@pytest.fixture(scope="module")
def outcomes() -> dict[str, list[dict]]:
    """Every sample file judged once, on two workers."""
    judged = judge_corpus(str(tool_path()), SAMPLE, MANIFEST, jobs=2, progress=False)
    by_file: dict[str, list[dict]] = {}
    for outcome in judged:
        by_file.setdefault(outcome["file"], []).append(outcome)
    return by_file


@pytest.mark.parametrize("entry", MANIFEST, ids=[e["file"] for e in MANIFEST])
def test_sample_file(entry: dict, outcomes: dict[str, list[dict]]) -> None:
    mine = outcomes.get(entry["file"], [])
    assert mine, "no command was judged"
    expected = {command: reason for (file, command), reason in XFAIL.items() if file == entry["file"]}
    unexpected, known = [], set()
    for o in mine:
        for failure in failures([o], entry["valid"]):
            if o["command"] in expected:
                known.add(o["command"])
            else:
                unexpected.append(failure)
    assert not unexpected, "\n".join(unexpected)
    fixed = set(expected) - known
    assert not fixed, f"listed in XFAIL but no longer failing (remove them): {sorted(fixed)}"
    if known:
        pytest.xfail("; ".join(sorted({expected[c] for c in known})))
