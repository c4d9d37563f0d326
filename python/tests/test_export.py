"""What the tool writes for CAD and CAM programs, read back by ezdxf and svgelements (not curvekit):
the DXF's entities are the JSON document's pieces, within 1e-9 of the size, on the contract's
layers; the SVG paths' ends are the pieces' ends."""

from __future__ import annotations

import math
import os
from collections import Counter

import numpy as np
import pytest

from conftest import FIXTURES, tool_json

try:
    import ezdxf
    import svgelements
except ImportError as missing:
    if os.environ.get("CI"):
        raise
    pytest.skip(f"the export tests need {missing.name}", allow_module_level=True)

ROUND_TRIP = 1e-9  # relative to the size (the contract's)
POCKET = str(FIXTURES / "drawing-pocket.svg")
GLYPH = str(FIXTURES / "corpus" / "glyphs" / "roboto" / "0061-a.svg")


def size_of(document: dict) -> float:
    """The size the tolerances are relative to, from the loops' and paths' own points."""
    points = []
    for o in document.get("offsets", []):
        for loop in o["loops"]:
            for s in loop["segments"]:
                points += [s[k] for k in ("from", "to", "center") if k in s] + s.get("points", [])
    points += [xy for e in document.get("edges", []) for xy in e["xy"]]
    points += [p[:2] for path in document.get("paths", []) for p in path["xyz"]]
    points = np.asarray(points, float)
    return float(np.ptp(points, axis=0).max())


def xy(v) -> tuple[float, float]:
    """An ezdxf point's plan coordinates."""
    return (v.x, v.y)


def near(a, b, tol: float) -> bool:
    return bool(np.max(np.abs(np.asarray(a, float) - np.asarray(b, float))) <= tol)


def layer_of(distance: float) -> str:
    """The contract's layer of a distance: its shortest decimal form (Rust's, no exponent)."""
    text = repr(float(distance))
    return "offset_" + (text[:-2] if text.endswith(".0") else text)


def arc_ends(center, r: float, start: float, end: float) -> list[np.ndarray]:
    return [np.asarray(center) + r * np.array([math.cos(a), math.sin(a)]) for a in (start, end)]


@pytest.mark.parametrize("drawing", [POCKET, GLYPH])
def test_offset_dxf_holds_the_pieces_on_a_layer_per_distance(drawing: str, tmp_path) -> None:
    out = tmp_path / "offsets.dxf"
    first = tool_json("offset", drawing, "--distance", "1")  # for the size only
    size = size_of(first) or 1.0
    distances = [round(0.02 * size, 6), round(0.06 * size, 6)]
    document = tool_json("offset", drawing, "--distances", ",".join(map(str, distances)), "--dxf", str(out))
    tol = ROUND_TRIP * size
    dxf = ezdxf.readfile(out)
    assert dxf.dxfversion >= "AC1024"  # R2010
    assert not dxf.audit().has_errors
    space = list(dxf.modelspace())
    for offset in document["offsets"]:
        entities = [e for e in space if e.dxf.layer == layer_of(offset["distance"])]
        # (Arcs that sweep nothing are not written: DXF would draw them as whole circles.)
        pieces = [
            s for loop in offset["loops"] for s in loop["segments"]
            if s["kind"] != "arc" or abs(s["end"] - s["start"]) > 1e-9
        ]
        assert len(entities) == len(pieces), offset["distance"]
        ends = Counter()
        for e, s in zip(entities, pieces):
            kind = e.dxftype()
            if s["kind"] == "line":
                assert kind == "LINE"
                assert near(xy(e.dxf.start), s["from"], tol) and near(xy(e.dxf.end), s["to"], tol)
                pair = [s["from"], s["to"]]
            elif s["kind"] == "arc":
                assert near(xy(e.dxf.center), s["center"], tol) and abs(e.dxf.radius - s["r"]) <= tol
                pair = arc_ends(s["center"], s["r"], s["start"], s["end"])
                if kind == "ARC":
                    # (Counterclockwise in DXF: a clockwise arc's ends are swapped.)
                    drawn = [np.asarray(xy(e.start_point)), np.asarray(xy(e.end_point))]
                    if s["end"] < s["start"]:
                        drawn.reverse()
                    assert near(drawn, pair, tol), (drawn, pair)
                else:
                    assert kind == "CIRCLE" and math.isclose(abs(s["end"] - s["start"]), 2 * math.pi)
            else:
                assert kind == "SPLINE" and e.dxf.degree == s["degree"]
                assert near(list(e.knots), s["knots"], 1e-12)
                assert near(np.asarray(e.control_points)[:, :2], s["points"], tol)
                pair = [s["points"][0], s["points"][-1]]
            for p in pair:
                ends[tuple(np.round(np.asarray(p) / (1e3 * tol)))] += 1
        # Every loop closed: each end met by the next piece's start.
        assert all(count % 2 == 0 for count in ends.values()), offset["distance"]


def test_medial_dxf_has_edges_and_a_layer_per_node_kind(tmp_path) -> None:
    out = tmp_path / "axis.dxf"
    document = tool_json("medial", POCKET, "--dxf", str(out))
    tol = ROUND_TRIP * size_of(document)
    space = list(ezdxf.readfile(out).modelspace())
    edges = [e for e in space if e.dxf.layer == "medial_edges"]
    assert [e.dxftype() for e in edges] == ["POLYLINE"] * len(document["edges"])
    for e, edge in zip(edges, document["edges"]):
        assert near([xy(v.dxf.location) for v in e.vertices], edge["xy"], tol)
    kinds = Counter(n["kind"] for n in document["nodes"])
    points = Counter(e.dxf.layer for e in space if e.dxftype() == "POINT")
    assert points == Counter({f"medial_{k}": c for k, c in kinds.items()})


def test_fitted_medial_dxf_edges_are_splines(tmp_path) -> None:
    out = tmp_path / "axis.dxf"
    document = tool_json("medial", GLYPH, "--fit", "--dxf", str(out))
    tol = ROUND_TRIP * size_of(document)
    edges = [e for e in ezdxf.readfile(out).modelspace() if e.dxf.layer == "medial_edges"]
    assert len(edges) == len(document["edges"])
    for e, edge in zip(edges, document["edges"]):
        assert e.dxftype() == "SPLINE"
        assert near(np.asarray(e.control_points)[:, :2], edge["bspline"]["points"], tol)


def test_vcarve_dxf_paths_are_3d_polylines_over_the_axis(tmp_path) -> None:
    out = tmp_path / "carve.dxf"
    document = tool_json("vcarve", GLYPH, "--angle", "60", "--max-depth", "60", "--dxf", str(out))
    tol = ROUND_TRIP * size_of(document)
    space = list(ezdxf.readfile(out).modelspace())
    paths = [e for e in space if e.dxf.layer == "vcarve_paths"]
    assert len(paths) == len(document["paths"]) > 0
    for e, path in zip(paths, document["paths"]):
        assert e.dxftype() == "POLYLINE" and e.is_3d_polyline
        assert near([v.dxf.location for v in e.vertices], path["xyz"], tol)
        assert min(p[2] for p in path["xyz"]) >= -60 - tol
    flats = [e for e in space if e.dxf.layer == "vcarve_flats"]
    assert len(flats) == sum(len(loop["segments"]) for loop in document["flats"]) > 0
    heights = {round(e.dxf.start[2] if e.dxftype() == "LINE" else (e.dxf.center[2] if e.dxftype() in ("ARC", "CIRCLE") else e.control_points[0][2]), 9) for e in flats}
    assert heights == {-60.0}


def test_svg_paths_end_where_the_pieces_end(tmp_path) -> None:
    out = tmp_path / "offsets.svg"
    document = tool_json("offset", POCKET, "--distance", "2", "--svg-paths", str(out))
    tol = ROUND_TRIP * size_of(document)
    svg = svgelements.SVG.parse(str(out), reify=False)
    paths = [e for e in svg.elements() if isinstance(e, svgelements.Path)]
    loops = document["offsets"][0]["loops"]
    assert len(paths) == len(loops)
    for path, loop in zip(paths, loops):
        drawn = [np.array([seg.end.x, seg.end.y]) for seg in path if not isinstance(seg, (svgelements.Move, svgelements.Close))]
        for s in loop["segments"]:
            end = s["to"] if s["kind"] == "line" else arc_ends(s["center"], s["r"], s["start"], s["end"])[1]
            assert min(np.abs(d - end).max() for d in drawn) <= tol, end
