"""Curves from numpy arrays of every kind, and bad input raising InputError with the tool's
message."""

from __future__ import annotations

import json
import pickle

import numpy as np
import pytest

import curvekit
from conftest import FIXTURES, run_tool

CUBIC = [[0, 0], [2, -1], [4, 0], [4, 2], [2, 1.2], [0, 2]]


def document(curve_dict: dict) -> dict:
    """The tool's antipodal document of a curve given as a dict (through the package)."""
    return curvekit.antipodal(curvekit.from_dict(curve_dict, "c")).to_dict()


@pytest.mark.parametrize(
    "points",
    [
        CUBIC,
        tuple(map(tuple, CUBIC)),
        np.array(CUBIC, dtype=np.float64),
        np.array(CUBIC, dtype=np.float32),
        np.array([[0, 0], [2, -1], [4, 0], [4, 2], [2, 1], [0, 2]], dtype=np.int64),
        np.asfortranarray(np.array(CUBIC, dtype=float)),
        np.array(CUBIC, dtype=float)[::-1][::-1],
    ],
    ids=["list", "tuple", "float64", "float32", "int64", "fortran", "strided"],
)
def test_points_of_every_kind_give_the_documents_curve(points):
    curve = curvekit.BSpline(points, degree=3, periodic=True, name="c")
    expected = {
        "kind": "bspline",
        "degree": 3,
        "periodic": True,
        "points": np.asarray(points, dtype=float).tolist(),
    }
    assert curvekit.antipodal(curve).to_dict() == document(expected)


def test_weights_and_knots_from_arrays():
    points = np.array([[0, 0], [1, 2], [3, 2], [4, 0], [5, 1]], dtype=float)
    weights = np.array([1, 2, 1, 0.5, 1])
    knots = np.array([0, 0, 0, 0, 0.3, 1, 1, 1, 1])
    curve = curvekit.BSpline(points, degree=3, weights=weights, knots=knots, name="c")
    expected = {
        "kind": "bspline",
        "degree": 3,
        "points": points.tolist(),
        "weights": weights.tolist(),
        "knots": knots.tolist(),
    }
    got = curvekit.inflections(curve).to_dict()
    assert got == curvekit.inflections(curvekit.from_dict(expected, "c")).to_dict()
    assert curve.domain == (0.0, 1.0)
    u = np.linspace(0, 1, 5)
    xy = curve.evaluate(u)
    assert xy.shape == (5, 2)
    np.testing.assert_allclose(xy[0], points[0])
    np.testing.assert_allclose(xy[-1], points[-1])


def test_the_analytic_and_segment_kinds():
    made = {
        "circle": curvekit.Circle(2.0, center=np.array([1, 1])),
        "ellipse": curvekit.Ellipse(3, 2, center=(0, 1)),
        "limacon": curvekit.Limacon(4, 2.5),
        "elliptic_lemniscate": curvekit.EllipticLemniscate(2, 1),
        "convexities": curvekit.Convexities(1.0, 0.3, 3),
        "line": curvekit.Line([0, 0], np.array([1.0, 2.0])),
        "arc": curvekit.Arc((0, 0), 1.0, 0.0, 1.5),
        "bezier": curvekit.Bezier(np.array([[0, 0], [1, 2], [2, 0]]), weights=[1, 3, 1]),
    }
    for kind, curve in made.items():
        assert curve.kind == kind
        assert curvekit.inflections(curve).certified
    p = curvekit.Circle(2.0, center=(1, 1)).evaluate(np.array([0.0, np.pi / 2]))
    np.testing.assert_allclose(p, [[3, 1], [1, 3]], atol=1e-12)


@pytest.mark.parametrize(
    "make, field",
    [
        (lambda: curvekit.BSpline([[0, 0], [1, np.nan], [2, 0], [3, 1]]), "points[1][1]"),
        (lambda: curvekit.BSpline(np.zeros((4, 3))), "points"),
        (lambda: curvekit.BSpline([[0, 0], [1, 1]], degree=3), "points"),
        (lambda: curvekit.BSpline(CUBIC, weights=[1, 1, 0, 1, 1, 1]), "weights[2]"),
        (lambda: curvekit.BSpline(CUBIC, weights=[1, np.inf, 1, 1, 1, 1]), "weights[1]"),
        (lambda: curvekit.Bezier("not points"), "points"),
        (lambda: curvekit.Circle(-1), "r"),
        (lambda: curvekit.Circle(float("nan")), "r"),
        (lambda: curvekit.Line([0, 0], [0, 0]), "to"),
        (lambda: curvekit.from_dict({"kind": "circle", "radius": 1}), "radius"),
        (lambda: curvekit.from_dict({"kind": "circle", "r": float("inf")}), "document"),
        (lambda: curvekit.Curve.from_json("{", "broken.json"), "document"),
    ],
)
def test_bad_arrays_and_documents_raise_input_error(make, field):
    with pytest.raises(curvekit.InputError) as raised:
        make()
    assert field in str(raised.value)
    assert isinstance(raised.value, ValueError)


def bad_files():
    return sorted((FIXTURES / "bad").glob("*.json"))


@pytest.mark.parametrize("file", bad_files(), ids=lambda p: p.name)
def test_bad_files_raise_input_error_with_the_tools_message(file):
    done = run_tool("antipodal", str(file))
    assert done.returncode == 2
    with pytest.raises(curvekit.InputError) as raised:
        curvekit.antipodal(curvekit.read(str(file)))
    assert f"curvekit: {raised.value}\n" == done.stderr


def test_refusals_and_options():
    region = curvekit.read(str(FIXTURES / "region-pocket.json"))
    with pytest.raises(curvekit.InputError, match="not a region"):
        curvekit.antipodal(region)
    with pytest.raises(curvekit.InputError, match="not a region"):
        curvekit.prepare(region)
    cubic = curvekit.BSpline(CUBIC, periodic=True)
    with pytest.raises(ValueError, match="^tol: 0.5 is out of range"):
        curvekit.antipodal(cubic, tol=0.5)
    with pytest.raises(ValueError, match="^chord_tol: 2 is out of range"):
        curvekit.bisector(cubic, chord_tol=2.0)
    with pytest.raises(ValueError, match="method"):
        curvekit.bisector(cubic, method="f4")
    with pytest.raises(curvekit.InputError, match="no-such-file"):
        curvekit.read("no-such-file.json")
    with pytest.raises(ValueError, match="outside the domain"):
        cubic.evaluate(np.array([7.0]))
    with pytest.raises(curvekit.InputError, match="cannot read"):
        curvekit.antipodal("no-such-file.json")
    assert json.loads(curvekit.antipodal(cubic).to_json()) == curvekit.antipodal(cubic).to_dict()


def test_the_package_docstring_example_runs():
    import doctest

    failed, tried = doctest.testmod(curvekit, verbose=False)
    assert tried > 0 and failed == 0


def test_commands_take_documents_and_paths():
    name = str(FIXTURES / "periodic_cubic.json")
    doc = json.loads((FIXTURES / "periodic_cubic.json").read_text())
    by_curve = curvekit.antipodal(curvekit.read(name)).to_dict()
    assert curvekit.antipodal(name).to_dict() == by_curve
    from pathlib import Path

    assert curvekit.antipodal(Path(name)).to_dict() == by_curve
    by_doc = curvekit.antipodal(doc).to_dict()
    assert by_doc["pairs"] == by_curve["pairs"] and by_doc["curve"]["file"] == "curve"
    with pytest.raises(TypeError):
        curvekit.antipodal(42)


def test_polygons_from_arrays_and_image_contours():
    square = np.array([[0, 0], [4, 0], [4, 3], [0, 3]], dtype=float)
    # OpenCV's contours are (n, 1, 2); a repeated point and a closing point draw nothing.
    contour = np.array([[[0, 0]], [[4, 0]], [[4, 0]], [[4, 3]], [[0, 3]], [[0, 0]]])
    a, b = curvekit.Polygon(square), curvekit.Polygon(contour)
    assert a.kind == b.kind == "profile" and a.domain == b.domain == (0.0, 4.0)
    u = np.linspace(0.0, 4.0, 17)
    assert np.array_equal(a.evaluate(u), b.evaluate(u))
    # The axis of a 4 x 3 rectangle: two junctions on its middle line, four corner leaves.
    axis = curvekit.medial(b)
    assert axis.certified
    assert sorted(axis.node_kinds).count("junction") == 2
    assert np.allclose(sorted(axis.node_radii)[-1], 1.5)
    # With a hole: a region, whose axis has one cycle.
    holed = curvekit.Polygon(square * 3, holes=[square + [4, 3]])
    axis = curvekit.medial(holed)
    assert len(axis.edges) - len(axis.nodes) + 1 == 1
    # Fewer than three distinct points is no polygon.
    with pytest.raises(curvekit.InputError, match="shell: a polygon needs 3 distinct points"):
        curvekit.Polygon([[0, 0], [1, 1], [1, 1]])
    with pytest.raises(curvekit.InputError, match=r"holes\[0\]"):
        curvekit.Polygon(square, holes=[[[0, 0]]])


def test_drawings_say_what_they_skipped_and_their_parts(tmp_path):
    drawing = tmp_path / "two.svg"
    drawing.write_text(
        '<svg xmlns="http://www.w3.org/2000/svg" width="40mm" height="10mm" viewBox="0 0 40 10">'
        '<text>label</text><path d="M0 0 H10 V10 H0 Z M20 0 H30 V10 H20 Z"/></svg>'
    )
    axis = curvekit.medial(str(drawing))
    assert axis.skipped == [{"type": "text", "count": 1}]
    assert axis.units == "mm"
    assert sorted(set(axis.node_parts.tolist())) == [0, 1]
    assert axis.to_dict()["skipped"] == axis.skipped
    passes = curvekit.offset(str(drawing), distance=1.0)
    assert passes.parts(0) == [0, 1]
    again = pickle.loads(pickle.dumps(axis))
    assert again == axis and again.skipped == axis.skipped
