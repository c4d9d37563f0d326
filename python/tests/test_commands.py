"""Every function against the tool's --json on the shipped fixtures: the same document."""

from __future__ import annotations

import numpy as np
import pytest

import curvekit
from conftest import FIXTURES, tool_json

CLOSED = [
    "periodic_cubic.json",
    "periodic_nurbs.json",
    "circle.json",
    "ellipse.json",
    "limacon.json",
    "antipodal-stadium.json",
    "antipodal-bspline-wavy.json",
    "clamped_closed.json",
    "profile-cam.json",
    "profile-bracket.json",
    "drawing-glyph-d.svg#1",
    "drawing-plate.dxf#0",
]
OPEN = ["bezier_s.json", "open_nurbs.json", "open_quadratic.json", "profile-s-curve.json"]


def path(name: str) -> str:
    return str(FIXTURES / name)


def read(entry: str):
    """A fixture (`name#k`: a drawing's profile k) and the tool's arguments for it."""
    name, _, pick = entry.partition("#")
    if pick:
        return curvekit.read(path(name), pick=int(pick)), [path(name), "--pick", pick]
    return curvekit.read(path(name)), [path(name)]


@pytest.mark.parametrize("entry", CLOSED)
def test_antipodal_is_the_tools_document(entry):
    curve, args = read(entry)
    result = curvekit.antipodal(curve)
    assert result.to_dict() == tool_json("antipodal", *args)
    warm = curvekit.antipodal(curvekit.prepare(curve))
    assert warm == result, "a prepared curve answers the same"


@pytest.mark.parametrize("entry", CLOSED + OPEN)
def test_inflections_is_the_tools_document(entry):
    curve, args = read(entry)
    result = curvekit.inflections(curve)
    assert result.to_dict() == tool_json("inflections", *args)
    assert curvekit.inflections(curvekit.prepare(curve)) == result
    assert result.params.shape == (len(result),)
    assert result.points.shape == (len(result), 2)


@pytest.mark.parametrize(
    "names",
    [
        ("circle.json", "ellipse.json"),
        ("bisector-fig3-quadratic1.json", "bisector-fig3-quadratic2.json"),
        ("profile-cam.json", "open_quadratic.json"),
        ("periodic_cubic.json", "limacon.json"),
    ],
)
def test_tangents_is_the_tools_document(names):
    a, b = (curvekit.read(path(n)) for n in names)
    result = curvekit.tangents(a, b)
    assert result.to_dict() == tool_json("tangents", *map(path, names))
    assert result.points.shape == (len(result), 2, 2)


@pytest.mark.parametrize(
    "names, options",
    [
        (("bisector-fig2-line.json", "bisector-fig2-quadratic.json"), {}),
        (("bisector-fig7-quadratic1.json", "bisector-fig7-quadratic2.json"), {"method": "f1"}),
        (("bisector-fig5-cubic-bspline.json",), {"chord_tol": 1e-2}),
        (("periodic_cubic.json",), {"trimmed": True, "chord_tol": 1e-2}),
        (("profile-rounded-slot.json",), {}),
    ],
)
def test_bisector_is_the_tools_document(names, options):
    curves = [curvekit.read(path(n)) for n in names]
    result = curvekit.bisector(*curves, **options)
    flags = []
    for key, value in options.items():
        flag = "--" + key.replace("_", "-")
        flags += [flag] if value is True else [flag, str(value)]
    assert result.to_dict() == tool_json("bisector", *map(path, names), *flags)
    for tr, xy in result.branches:
        assert tr.shape == xy.shape and tr.shape[1] == 2


@pytest.mark.parametrize(
    "name, options",
    [
        ("region-pocket.json", {}),
        ("drawing-pocket.svg", {"fit": True}),
        ("periodic_cubic.json", {}),
        ("profile-cam.json", {"exterior": True}),
    ],
)
def test_medial_is_the_tools_document(name, options):
    result = curvekit.medial(curvekit.read(path(name)), **options)
    flags = ["--" + k for k in options]
    assert result.to_dict() == tool_json("medial", path(name), *flags)
    doc = result.to_dict()
    assert result.nodes.shape == (len(doc["nodes"]), 2)
    assert list(result.node_radii) == [n["radius"] for n in doc["nodes"]]
    assert result.node_kinds == [n["kind"] for n in doc["nodes"]]
    for (a, b, xy, radius), edge in zip(result.edges, doc["edges"]):
        assert (a, b) == (edge["from"], edge["to"])
        assert xy.tolist() == edge["xy"] and radius.tolist() == edge["radius"]


def test_arrays_are_the_documents_numbers():
    result = curvekit.antipodal(curvekit.read(path("periodic_nurbs.json")))
    doc = result.to_dict()
    pairs = doc["pairs"]
    assert result.pairs.tolist() == [[p["s"], p["t"]] for p in pairs]
    assert result.points.tolist() == [[p["p"], p["q"]] for p in pairs]
    assert result.distances.tolist() == [p["distance"] for p in pairs]
    assert result.types == [p["type"] for p in pairs]
    assert result.inflections.tolist() == [i["u"] for i in doc["inflections"]]
    assert result.certified is doc["certified"] is True
    assert len(result) == len(pairs) > 0
    np.testing.assert_allclose(
        result.distances, np.linalg.norm(result.points[:, 1] - result.points[:, 0], axis=1)
    )


def test_a_json_text_gives_the_files_answer():
    text = (FIXTURES / "periodic_cubic.json").read_text()
    from_text = curvekit.Curve.from_json(text, path("periodic_cubic.json"))
    assert curvekit.antipodal(from_text) == curvekit.antipodal(
        curvekit.read(path("periodic_cubic.json"))
    )


@pytest.mark.parametrize(
    "name, options, flags",
    [
        ("region-pocket.json", {"step": 0.5}, ["--step", "0.5"]),
        ("drawing-pocket.svg", {"distances": [0.1, 0.3]}, ["--distances", "0.1,0.3"]),
        ("periodic_cubic.json", {"distance": 0.2}, ["--distance", "0.2"]),
        ("region-pocket.json", {"distances": [0.5, 2.0], "outward": True},
         ["--distances", "0.5,2", "--outward"]),
    ],
)
def test_offset_is_the_tools_document(name, options, flags):
    result = curvekit.offset(path(name), **options)
    assert result.to_dict() == tool_json("offset", path(name), *flags)
    for k, d in enumerate(result.distances):
        for loop in result.polylines(k):
            assert loop.shape[1] == 2 and len(loop) >= 2
    with pytest.raises(ValueError, match="one of"):
        curvekit.offset(path(name), distance=1.0, step=0.5)
