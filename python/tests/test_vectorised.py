"""The vectorised calls (a list of curves in, a list of results out, computed in parallel)
against the one-at-a-time calls, which they must equal result for result; failures naming the
curve's place; the V-carving results and the files the results write."""

from __future__ import annotations

import pickle
import subprocess

import numpy as np
import pytest

import curvekit
from conftest import FIXTURES, tool_path

CURVES = [
    curvekit.BSpline([[0, 0], [2, -1], [4, 0], [4, 2], [2, 1.2], [0, 2]], periodic=True),
    curvekit.Ellipse(2.0, 1.0),
    curvekit.Limacon(4.0, 2.5),
    curvekit.read(FIXTURES / "profile-cam.json"),
    curvekit.Polygon([[0, 0], [4, 0], [4, 3], [1, 3], [0, 1]]),
]
REGIONS = [
    curvekit.read(FIXTURES / "region-pocket.json"),
    curvekit.read(FIXTURES / "drawing-pocket.svg"),
    curvekit.read(FIXTURES / "corpus" / "glyphs" / "roboto" / "0061-a.svg"),
    CURVES[0],
]


def test_one_curve_commands_answer_as_one_at_a_time() -> None:
    assert curvekit.antipodal(CURVES) == [curvekit.antipodal(c) for c in CURVES]
    assert curvekit.inflections(tuple(CURVES)) == [curvekit.inflections(c) for c in CURVES]
    # An object array, and prepared curves (warm) beside plain ones.
    mixed = np.array([curvekit.prepare(CURVES[0]), CURVES[1]], dtype=object)
    assert curvekit.antipodal(mixed) == [curvekit.antipodal(CURVES[0]), curvekit.antipodal(CURVES[1])]
    # Dicts and paths are read as the single calls read them.
    assert curvekit.antipodal([{"kind": "circle", "r": 1}, str(FIXTURES / "ellipse.json")]) == [
        curvekit.antipodal({"kind": "circle", "r": 1}),
        curvekit.antipodal(FIXTURES / "ellipse.json"),
    ]


def test_two_curve_commands_pair_up_or_take_one_for_all() -> None:
    other = curvekit.Circle(1.0, center=(9, 0))
    assert curvekit.tangents(CURVES, other) == [curvekit.tangents(c, other) for c in CURVES]
    pairs = CURVES[1:]
    assert curvekit.tangents(CURVES[:-1], pairs) == [curvekit.tangents(a, b) for a, b in zip(CURVES, pairs)]
    assert curvekit.bisector(CURVES[:3]) == [curvekit.bisector(c) for c in CURVES[:3]]
    assert curvekit.bisector(CURVES[:2], other, trimmed=True) == [curvekit.bisector(c, other, trimmed=True) for c in CURVES[:2]]
    with pytest.raises(ValueError, match="lengths must match"):
        curvekit.tangents(CURVES, CURVES[:2])


def test_region_commands_answer_as_one_at_a_time() -> None:
    assert curvekit.medial(REGIONS, fit=True) == [curvekit.medial(r, fit=True) for r in REGIONS]
    assert curvekit.offset(REGIONS, distances=[0.5, 1.0]) == [curvekit.offset(r, distances=[0.5, 1.0]) for r in REGIONS]
    carved = curvekit.vcarve(REGIONS, angle=60, max_depth=2)
    assert carved == [curvekit.vcarve(r, angle=60, max_depth=2) for r in REGIONS]


def test_a_failure_names_the_curves_place() -> None:
    with pytest.raises(curvekit.InputError, match=r"^\[1\] "):
        curvekit.medial([REGIONS[0], curvekit.Line([0, 0], [1, 1])])
    with pytest.raises(ValueError, match=r"^\[0\] .*tol"):
        curvekit.antipodal(CURVES[:2], tol=-1)
    with pytest.raises(TypeError, match=r"^\[1\]: "):
        curvekit.antipodal([CURVES[0], 42])
    assert curvekit.antipodal([]) == []


def test_vcarve_paths_follow_the_axis() -> None:
    pocket = REGIONS[0]
    carve = curvekit.vcarve(pocket, angle=90)
    axis = curvekit.medial(pocket)
    depths = np.concatenate([p[:, 2] for p in carve.paths])
    radii = np.concatenate([r for _, _, _, r in axis.edges])
    # A 90° bit: the depth is the radius; every radius of the axis is cut somewhere.
    assert np.isclose(-depths.min(), radii.max()) and np.isclose(-depths.max(), radii.min())
    assert carve.certified and carve.max_depth is None and carve.flats() == []
    limited = curvekit.vcarve(pocket, angle=60, max_depth=3)
    assert min(p[:, 2].min() for p in limited.paths) >= -3 - 1e-12
    assert len(limited.flats()) > 0 and set(limited.path_parts) == {0}
    assert pickle.loads(pickle.dumps(limited)) == limited
    assert limited.to_dict()["max_depth"] == 3


def test_result_files_are_the_tools(tmp_path) -> None:
    """The files a result writes are the tool's (the DXF header's dates and ids aside)."""
    pocket = FIXTURES / "region-pocket.json"
    found = curvekit.offset(pocket, step=0.5)
    out = tmp_path / "passes.svg"
    subprocess.run([str(tool_path()), "offset", str(pocket), "--step", "0.5", "--svg-paths", str(out)], check=True, capture_output=True)
    assert found.svg_paths() == out.read_text()
    dxf = tmp_path / "passes.dxf"
    subprocess.run([str(tool_path()), "offset", str(pocket), "--step", "0.5", "--dxf", str(dxf)], check=True, capture_output=True)

    def entities(text: str) -> str:
        return text[text.index("ENTITIES") :]

    assert entities(found.dxf().decode()) == entities(dxf.read_bytes().decode())
    axis = curvekit.medial(pocket)
    assert axis.svg_paths().count("<path") == len(axis.edges)
    assert b"vcarve_paths" in curvekit.vcarve(pocket, angle=60).dxf()


def test_version() -> None:
    assert curvekit.__version__.count(".") == 2
