"""curvekit: certified geometry on planar freeform curves.

Curves come from the tool's JSON documents (:func:`from_dict`, :meth:`Curve.from_json`), from
files and drawings (:func:`read`: ``.json``, ``.svg``, ``.dxf``) and from numpy arrays
(:func:`BSpline`, :func:`Bezier`, :func:`Line`, :func:`Arc` and the analytic kinds). The
commands (:func:`antipodal`, :func:`inflections`, :func:`tangents`, :func:`bisector`,
:func:`medial`) release the GIL while they compute, and their results give numpy arrays and
``to_dict()``, the document ``curvekit COMMAND --json`` prints. Curves and results pickle, so
they travel to process pools and clusters (Dask, Ray) unchanged. A curve asked many times is
prepared once (:func:`prepare`): runs on the prepared curve answer warm.

>>> import curvekit
>>> c = curvekit.BSpline([[0, 0], [2, -1], [4, 0], [4, 2], [2, 1.2], [0, 2]], periodic=True)
>>> r = curvekit.antipodal(c)
>>> r.certified, r.pairs.shape
(True, (2, 2))
"""

from __future__ import annotations

import json
import math
import os
from typing import Any, Mapping, Optional, Sequence, Union

import numpy as np

from . import _curvekit
from ._curvekit import (
    Antipodal,
    Bisector,
    Curve,
    CurvekitError,
    Inflections,
    InputError,
    MedialAxis,
    Offsets,
    PreparedCurve,
    Tangents,
    prepare,
    read,
)

__all__ = [
    "Antipodal",
    "Arc",
    "Bezier",
    "Bisector",
    "BSpline",
    "Circle",
    "Convexities",
    "Curve",
    "CurvekitError",
    "Ellipse",
    "EllipticLemniscate",
    "Inflections",
    "InputError",
    "Limacon",
    "Line",
    "MedialAxis",
    "Offsets",
    "Polygon",
    "PreparedCurve",
    "Tangents",
    "antipodal",
    "bisector",
    "from_dict",
    "inflections",
    "medial",
    "offset",
    "prepare",
    "read",
    "tangents",
]


def from_dict(document: Mapping[str, Any], name: str = "curve") -> Curve:
    """A curve, profile or region from one JSON curve document given as a dict (the tool's
    format); ``name`` stands for the file name in messages and reports."""
    try:
        text = json.dumps(document, allow_nan=False)
    except (TypeError, ValueError) as e:
        raise InputError(f"{name}: document: not a JSON document: {e}") from None
    return Curve.from_json(text, name)


def _points(points: Any, field: str, name: str) -> list:
    """An (n, 2) array of finite coordinates as nested lists, or InputError naming the field."""
    try:
        a = np.asarray(points, dtype=float)
    except (TypeError, ValueError) as e:
        raise InputError(f"{name}: {field}: not an array of numbers: {e}") from None
    if a.ndim != 2 or a.shape[1] != 2:
        raise InputError(f"{name}: {field}: expected an (n, 2) array, got shape {a.shape}")
    bad = np.argwhere(~np.isfinite(a))
    if len(bad):
        i, j = bad[0]
        raise InputError(f"{name}: {field}[{i}][{j}]: {a[i, j]} is not a finite number")
    return a.tolist()


def _numbers(values: Any, field: str, name: str) -> list:
    """A 1-D array of finite numbers as a list, or InputError naming the field."""
    try:
        a = np.asarray(values, dtype=float)
    except (TypeError, ValueError) as e:
        raise InputError(f"{name}: {field}: not an array of numbers: {e}") from None
    if a.ndim != 1:
        raise InputError(f"{name}: {field}: expected a 1-D array, got shape {a.shape}")
    bad = np.flatnonzero(~np.isfinite(a))
    if len(bad):
        raise InputError(f"{name}: {field}[{bad[0]}]: {a[bad[0]]} is not a finite number")
    return a.tolist()


def _number(value: Any, field: str, name: str) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{name}: {field}: {value!r} is not a number") from None
    if not math.isfinite(x):
        raise InputError(f"{name}: {field}: {x} is not a finite number")
    return x


def BSpline(
    points: Any,
    degree: int = 3,
    periodic: bool = False,
    weights: Optional[Any] = None,
    knots: Optional[Any] = None,
    name: str = "bspline",
) -> Curve:
    """A B-spline (NURBS with ``weights``) of ``degree`` on ``points`` (an (n, 2) array):
    periodic (closed, uniform), or open, clamped on [0, 1] unless ``knots`` are given."""
    doc: dict = {
        "kind": "bspline",
        "degree": degree,
        "points": _points(points, "points", name),
    }
    if periodic:
        doc["periodic"] = True
    if weights is not None:
        doc["weights"] = _numbers(weights, "weights", name)
    if knots is not None:
        doc["knots"] = _numbers(knots, "knots", name)
    return from_dict(doc, name)


def Bezier(points: Any, weights: Optional[Any] = None, name: str = "bezier") -> Curve:
    """A Bézier curve (rational with ``weights``) on ``points`` (an (n, 2) array), on [0, 1]."""
    doc: dict = {"kind": "bezier", "points": _points(points, "points", name)}
    if weights is not None:
        doc["weights"] = _numbers(weights, "weights", name)
    return from_dict(doc, name)


def _center(center: Any, name: str) -> list:
    return _points([center], "center", name)[0]


def Circle(r: float, center: Sequence[float] = (0.0, 0.0), name: str = "circle") -> Curve:
    """The circle of radius ``r`` about ``center``, counterclockwise from angle 0."""
    return from_dict(
        {"kind": "circle", "r": _number(r, "r", name), "center": _center(center, name)}, name
    )


def Ellipse(
    a: float, b: float, center: Sequence[float] = (0.0, 0.0), name: str = "ellipse"
) -> Curve:
    """The ellipse (cx + a cos φ, cy + b sin φ)."""
    return from_dict(
        {
            "kind": "ellipse",
            "a": _number(a, "a", name),
            "b": _number(b, "b", name),
            "center": _center(center, name),
        },
        name,
    )


def Limacon(a: float, b: float, name: str = "limacon") -> Curve:
    """The limaçon r(φ) = a + b cos φ (a > b ≥ 0)."""
    return from_dict(
        {"kind": "limacon", "a": _number(a, "a", name), "b": _number(b, "b", name)}, name
    )


def EllipticLemniscate(a: float, b: float, name: str = "elliptic_lemniscate") -> Curve:
    """The elliptic lemniscate r(φ) = sqrt(a² cos² φ + b² sin² φ)."""
    return from_dict(
        {"kind": "elliptic_lemniscate", "a": _number(a, "a", name), "b": _number(b, "b", name)},
        name,
    )


def Convexities(p: float, eps: float, m: int, name: str = "convexities") -> Curve:
    """The curve r(φ) = p / (1 + eps cos(m φ)) with m convexities."""
    return from_dict(
        {
            "kind": "convexities",
            "p": _number(p, "p", name),
            "eps": _number(eps, "eps", name),
            "m": m,
        },
        name,
    )


def Line(start: Sequence[float], end: Sequence[float], name: str = "line") -> Curve:
    """The line segment from ``start`` to ``end``, on [0, 1]."""
    pts = _points([start, end], "from/to", name)
    return from_dict({"kind": "line", "from": pts[0], "to": pts[1]}, name)


def Arc(
    center: Sequence[float], r: float, start: float, end: float, name: str = "arc"
) -> Curve:
    """The circular arc about ``center`` of radius ``r`` from angle ``start`` to ``end``
    (radians; counterclockwise when end > start), on [0, 1]."""
    return from_dict(
        {
            "kind": "arc",
            "center": _center(center, name),
            "r": _number(r, "r", name),
            "start": _number(start, "start", name),
            "end": _number(end, "end", name),
        },
        name,
    )


def _ring(points: Any, field: str, name: str) -> dict:
    """A closed profile document of the straight sides through ``points``: an (n, 2) array, or
    OpenCV's (n, 1, 2) contour; repeated points (and a last point that repeats the first) are
    dropped, as they draw nothing."""
    try:
        a = np.asarray(points, dtype=float)
    except (TypeError, ValueError) as e:
        raise InputError(f"{name}: {field}: not an array of numbers: {e}") from None
    if a.ndim == 3 and a.shape[1:] == (1, 2):
        a = a[:, 0, :]
    pts = _points(a, field, name)
    ring = [p for i, p in enumerate(pts) if i == 0 or p != pts[i - 1]]
    while len(ring) > 1 and ring[-1] == ring[0]:
        ring.pop()
    if len(ring) < 3:
        raise InputError(
            f"{name}: {field}: a polygon needs 3 distinct points at least, got {len(ring)}"
        )
    sides = [
        {"kind": "line", "from": ring[i], "to": ring[(i + 1) % len(ring)]} for i in range(len(ring))
    ]
    return {"kind": "profile", "segments": sides, "closed": True}


def Polygon(shell: Any, holes: Sequence[Any] = (), name: str = "polygon") -> Curve:
    """The polygon through ``shell`` (an (n, 2) array, or an image contour's (n, 1, 2) array as
    OpenCV gives it), with the polygons ``holes`` inside it: a closed profile of straight
    sides, or a region with holes, either way round. Repeated points are dropped.

    >>> import numpy as np, curvekit
    >>> contour = np.array([[[0, 0]], [[4, 0]], [[4, 3]], [[0, 3]]])
    >>> curvekit.medial(curvekit.Polygon(contour)).certified
    True
    """
    outer = _ring(shell, "shell", name)
    if not holes:
        return from_dict(outer, name)
    inner = [_ring(h, f"holes[{k}]", name) for k, h in enumerate(holes)]
    return from_dict({"kind": "region", "outer": outer, "holes": inner}, name)


CurveLike = Union[Curve, Mapping[str, Any], str, "os.PathLike[str]"]
"""What the commands take as a curve: a :class:`Curve`, a JSON curve document as a dict, or the
path of a curve file or drawing."""


def _curve(x: Any) -> Any:
    """A curve from what a command was given (a prepared curve stays as it is)."""
    if isinstance(x, (Curve, PreparedCurve)):
        return x
    if isinstance(x, Mapping):
        return from_dict(x)
    if isinstance(x, (str, os.PathLike)):
        return read(x)
    raise TypeError(f"expected a curvekit.Curve, a curve document (dict) or a path, got {type(x).__name__}")


def antipodal(curve: Union[CurveLike, PreparedCurve], *, tol: float = 1e-12) -> Antipodal:
    """The antipodal point pairs of a closed curve or profile (Jia 2004): the grasps of a
    two-finger gripper, with the inflections and the families of non-isolated pairs. ``tol``
    is the parameter tolerance relative to the domain's length (``--tol``)."""
    return _curvekit.antipodal(_curve(curve), tol=tol)


def inflections(curve: Union[CurveLike, PreparedCurve], *, tol: float = 1e-12) -> Inflections:
    """The inflections of a curve (and the corners of a profile)."""
    return _curvekit.inflections(_curve(curve), tol=tol)


def tangents(curve1: CurveLike, curve2: CurveLike, *, tol: float = 1e-12) -> Tangents:
    """Every line tangent to both curves."""
    return _curvekit.tangents(_curve(curve1), _curve(curve2), tol=tol)


def bisector(
    curve1: CurveLike,
    curve2: Optional[CurveLike] = None,
    *,
    method: str = "f3",
    trimmed: bool = False,
    chord_tol: float = 1e-3,
    tol: float = 1e-12,
) -> Bisector:
    """The bisector of two curves, or the self-bisector of one, as polylines within
    ``chord_tol`` (relative to the curves' size) of the true bisector; ``method`` is Elber and
    Kim's bisector function (``"f1"``, ``"f2"``, ``"f3"``); ``trimmed`` keeps only the points
    whose feet are the nearest points of the curves."""
    return _curvekit.bisector(
        _curve(curve1),
        None if curve2 is None else _curve(curve2),
        method=method,
        trimmed=trimmed,
        chord_tol=chord_tol,
        tol=tol,
    )


def medial(
    region: CurveLike,
    *,
    chord_tol: float = 1e-3,
    fit: bool = False,
    exterior: bool = False,
    tol: float = 1e-12,
) -> MedialAxis:
    """The medial axis of a region (or of the area inside a closed curve or profile): a graph
    of edges whose points carry the radius of the largest inscribed disk; ``fit`` adds each
    edge as a B-spline; ``exterior`` gives the Voronoi diagram outside instead."""
    return _curvekit.medial(
        _curve(region), chord_tol=chord_tol, fit=fit, exterior=exterior, tol=tol
    )


def offset(
    region: CurveLike,
    *,
    distance: Optional[float] = None,
    distances: Optional[Sequence[float]] = None,
    step: Optional[float] = None,
    outward: bool = False,
    chord_tol: float = 1e-3,
    tol: float = 1e-12,
) -> Offsets:
    """The inward offsets of a region (pocketing tool paths) at ``distance``, at each of
    ``distances``, or at every multiple of ``step`` while the region lasts: closed loops
    (``to_dict()``: the tool's profile documents; ``polylines(k)`` for drawing), from the
    region's medial axis, so that they never cross; ``outward`` grows the region instead (from
    its exterior axis, for distances below half its size)."""
    if distances is not None:
        distances = [float(d) for d in distances]
    return _curvekit.offset(
        _curve(region),
        distance=distance,
        distances=distances,
        step=step,
        outward=outward,
        chord_tol=chord_tol,
        tol=tol,
    )
