"""curvekit: certified geometry on planar freeform curves.

Curves come from the tool's JSON documents (:func:`from_dict`, :meth:`Curve.from_json`), from
files and drawings (:func:`read`: ``.json``, ``.svg``, ``.dxf``) and from numpy arrays
(:func:`BSpline`, :func:`Bezier`, :func:`Line`, :func:`Arc` and the analytic kinds). The
commands (:func:`antipodal`, :func:`grasps`, :func:`inflections`, :func:`tangents`,
:func:`bisector`, :func:`medial`, :func:`offset`, :func:`vcarve`) release the GIL while they compute, and their
results give numpy arrays and ``to_dict()``, the document ``curvekit COMMAND --json`` prints.
Given a list of curves instead of one, a command answers a list, computed in parallel (as
shapely's vectorised functions do). Curves and results pickle, so
they travel to process pools and clusters (Dask, Ray) unchanged. A curve asked many times is
prepared once (:func:`prepare`): runs on the prepared curve answer warm.

>>> import curvekit
>>> c = curvekit.BSpline([[0, 0], [2, -1], [4, 0], [4, 2], [2, 1.2], [0, 2]], periodic=True)
>>> r = curvekit.antipodal(c)
>>> r.certified, r.pairs.shape
(True, (2, 2))
"""

from __future__ import annotations

import importlib
import json
import math
import os
from typing import Any, List, Literal, Mapping, Optional, Sequence, Tuple, Union, overload

import numpy as np

from . import _curvekit
from ._curvekit import (
    Antipodal,
    BestGrasp,
    Bisector,
    ContactRegion,
    Curve,
    CurvekitError,
    GraspRegion,
    Grasps,
    Inflections,
    InputError,
    MedialAxis,
    Offsets,
    PreparedCurve,
    Tangents,
    VCarve,
    prepare,
    read,
)

__version__: str = _curvekit.__version__

__all__ = [
    "Antipodal",
    "Arc",
    "BestGrasp",
    "Bezier",
    "Bisector",
    "BSpline",
    "Circle",
    "ContactRegion",
    "Convexities",
    "Curve",
    "CurvekitError",
    "Ellipse",
    "EllipticLemniscate",
    "GraspRegion",
    "Grasps",
    "Inflections",
    "InputError",
    "Limacon",
    "Line",
    "MedialAxis",
    "Offsets",
    "Polygon",
    "PreparedCurve",
    "Profile",
    "Region",
    "Tangents",
    "VCarve",
    "__version__",
    "antipodal",
    "bisector",
    "from_dict",
    "from_shapely",
    "grasps",
    "inflections",
    "medial",
    "offset",
    "prepare",
    "read",
    "tangents",
    "to_shapely",
    "vcarve",
]


def from_dict(document: Mapping[str, Any], name: str = "curve") -> Curve:
    """A curve, profile or region from one JSON curve document given as a dict (the tool's
    format); ``name`` stands for the file name in messages and reports."""
    try:
        text = json.dumps(document, allow_nan=False)
    except (TypeError, ValueError) as e:
        raise InputError(f"{name}: document: not a JSON document: {e}") from None
    return Curve.from_json(text, name)


def _points(points: Any, field: str, name: str) -> list[list[float]]:
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
    points_list: list[list[float]] = a.tolist()
    return points_list


def _numbers(values: Any, field: str, name: str) -> list[float]:
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
    numbers: list[float] = a.tolist()
    return numbers


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
    doc: dict[str, Any] = {
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
    doc: dict[str, Any] = {"kind": "bezier", "points": _points(points, "points", name)}
    if weights is not None:
        doc["weights"] = _numbers(weights, "weights", name)
    return from_dict(doc, name)


def _center(center: Any, name: str) -> list[float]:
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


def _ring(points: Any, field: str, name: str) -> dict[str, Any]:
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


def _document(x: Any, field: str) -> dict[str, Any]:
    """A curve's document: a :class:`Curve`'s, or a dict as it is."""
    if isinstance(x, Curve):
        doc: dict[str, Any] = x.to_dict()
        return doc
    if isinstance(x, Mapping):
        return dict(x)
    raise TypeError(f"{field}: expected a curvekit.Curve or a curve document (dict), got {type(x).__name__}")


def Profile(segments: Sequence[Any], closed: Optional[bool] = None, name: str = "profile") -> Curve:
    """A profile: the curves ``segments`` (lines, arcs, Bézier curves, open B-splines, as
    :class:`Curve` or documents) joined end to end; closed when the last ends where the first
    starts, unless ``closed`` says."""
    doc: dict[str, Any] = {
        "kind": "profile",
        "segments": [_document(s, f"segments[{k}]") for k, s in enumerate(segments)],
    }
    if closed is not None:
        doc["closed"] = closed
    return from_dict(doc, name)


def Region(outer: Any, holes: Sequence[Any] = (), name: str = "region") -> Curve:
    """The region inside the closed curve or profile ``outer`` and outside each of ``holes``
    (curves or documents); ``.outer``, ``.holes`` and ``.parts`` give them back."""
    return from_dict(
        {
            "kind": "region",
            "outer": _document(outer, "outer"),
            "holes": [_document(h, f"holes[{k}]") for k, h in enumerate(holes)],
        },
        name,
    )


def to_shapely(x: Any) -> Any:
    """A curve (region, closed curve: a polygon; open curve: a line string) or an offset result
    as a shapely geometry, its curves flattened within 1e-3 of the size. Needs shapely."""
    # (Imported by name: shapely is optional and ships no type information.)
    geometry = importlib.import_module("shapely.geometry")
    return geometry.shape(x)


def from_shapely(geometry: Any, name: str = "shapely") -> Curve:
    """A shapely ``Polygon`` (a region of straight sides, with its holes), ``MultiPolygon``
    (several parts) or ``LineString`` (an open profile) as a curve. Needs shapely."""
    kind = geometry.geom_type
    if kind == "Polygon":
        return Polygon(
            np.asarray(geometry.exterior.coords)[:-1],
            [np.asarray(r.coords)[:-1] for r in geometry.interiors],
            name=name,
        )
    if kind == "MultiPolygon":
        parts = [from_shapely(g, f"{name} part {k}").to_dict() for k, g in enumerate(geometry.geoms)]
        for k, part in enumerate(parts):
            if part["kind"] != "region":
                parts[k] = {"kind": "region", "outer": part, "holes": []}
        return from_dict({"kind": "regions", "parts": parts}, name)
    if kind == "LineString":
        pts = _points(np.asarray(geometry.coords), "coords", name)
        sides = [{"kind": "line", "from": a, "to": b} for a, b in zip(pts, pts[1:]) if a != b]
        return from_dict({"kind": "profile", "segments": sides}, name)
    raise InputError(f"{name}: geometry: a {kind} is no curve (Polygon, MultiPolygon or LineString)")


CurveLike = Union[Curve, Mapping[str, Any], str, "os.PathLike[str]"]
"""What the commands take as a curve: a :class:`Curve`, a JSON curve document as a dict, or the
path of a curve file or drawing."""

OneCurve = Union[CurveLike, PreparedCurve]
"""What the one-curve commands take: a curve, or a curve prepared for many runs."""

Many = Union[List[Any], Tuple[Any, ...], "np.ndarray[Any, Any]"]
"""A list of curves: a list, a tuple or a one-dimensional object array."""


def _curve(x: Any) -> Any:
    """A curve from what a command was given (a prepared curve stays as it is)."""
    if isinstance(x, (Curve, PreparedCurve)):
        return x
    if isinstance(x, Mapping):
        return from_dict(x)
    if isinstance(x, (str, os.PathLike)):
        return read(x)
    raise TypeError(f"expected a curvekit.Curve, a curve document (dict) or a path, got {type(x).__name__}")


def _is_many(x: Any) -> bool:
    """Whether a command was given a list of curves (a list, a tuple, an object array)."""
    return isinstance(x, (list, tuple)) or (isinstance(x, np.ndarray) and x.ndim == 1)


def _curves(xs: Any) -> list[Any]:
    """Each of a list of curves as :func:`_curve` takes it, its place named on failure."""
    found = []
    for k, x in enumerate(xs):
        try:
            found.append(_curve(x))
        except TypeError as e:
            raise TypeError(f"[{k}]: {e}") from None
    return found


def _paired(first: list[Any], second: Any, command: str) -> list[Any]:
    """The second curves of a vectorised two-curve call: a list as long as the first, or one
    curve for all of them."""
    if _is_many(second):
        listed = _curves(second)
        if len(listed) != len(first):
            raise ValueError(f"{command}: {len(first)} curves against {len(listed)}: the lists pair up, so their lengths must match")
        return listed
    return [_curve(second)] * len(first)


def _one_or_many(command: str, curve: Any, **options: Any) -> Any:
    """The one-curve ``command`` on ``curve`` with ``options``, or, given a list of curves, on
    each (``command_many``, in parallel)."""
    if _is_many(curve):
        return getattr(_curvekit, f"{command}_many")(_curves(curve), **options)
    return getattr(_curvekit, command)(_curve(curve), **options)


@overload
def antipodal(curve: OneCurve, *, tol: float = ...) -> Antipodal: ...
@overload
def antipodal(curve: Many, *, tol: float = ...) -> List[Antipodal]: ...
def antipodal(curve: Any, *, tol: float = 1e-12) -> Any:
    """The antipodal point pairs of a closed curve or profile (Jia 2004): the grasps of a
    two-finger gripper, with the inflections and the families of non-isolated pairs. ``tol``
    is the parameter tolerance relative to the domain's length (``--tol``). Given a list of
    curves, a list of results, computed in parallel."""
    return _one_or_many("antipodal", curve, tol=tol)


@overload
def grasps(
    curve: OneCurve,
    friction: float,
    *,
    min_width: Optional[float] = ...,
    max_width: Optional[float] = ...,
) -> Grasps: ...
@overload
def grasps(
    curve: Many,
    friction: float,
    *,
    min_width: Optional[float] = ...,
    max_width: Optional[float] = ...,
) -> List[Grasps]: ...
def grasps(
    curve: Any,
    friction: float,
    *,
    min_width: Optional[float] = None,
    max_width: Optional[float] = None,
) -> Any:
    """Every two-finger force-closure grasp of a closed curve or profile for Coulomb friction
    ``friction`` (μ > 0; Nguyen's condition: the chord between the contacts lies inside both
    friction cones of half-angle atan μ), pairs closer than ``min_width`` or farther apart than
    ``max_width`` left out. The result's ``regions`` live in the square of contact parameters
    (s < t), each with its independent contact region (``contact``) and its most robust grasp
    (``best``); ``to_dict()`` is the document ``curvekit grasps --json`` prints. Given a list
    of curves, a list of results, computed in parallel.

    >>> import curvekit
    >>> g = curvekit.grasps(curvekit.Ellipse(3.0, 2.0), 0.3)
    >>> len(g.regions), g.certified
    (2, True)
    """
    return _one_or_many(
        "grasps", curve, friction=friction, min_width=min_width, max_width=max_width
    )


@overload
def inflections(curve: OneCurve, *, tol: float = ...) -> Inflections: ...
@overload
def inflections(curve: Many, *, tol: float = ...) -> List[Inflections]: ...
def inflections(curve: Any, *, tol: float = 1e-12) -> Any:
    """The inflections of a curve (and the corners of a profile); of each of a list of
    curves, in parallel."""
    return _one_or_many("inflections", curve, tol=tol)


@overload
def tangents(curve1: CurveLike, curve2: CurveLike, *, tol: float = ...) -> Tangents: ...
@overload
def tangents(curve1: Many, curve2: Union[CurveLike, Many], *, tol: float = ...) -> List[Tangents]: ...
def tangents(curve1: Any, curve2: Any, *, tol: float = 1e-12) -> Any:
    """Every line tangent to both curves. Given a list as ``curve1``, the tangents of each with
    ``curve2`` (one curve, or a list of as many, paired in order), in parallel."""
    if _is_many(curve1):
        first = _curves(curve1)
        return _curvekit.tangents_many(first, _paired(first, curve2, "tangents"), tol=tol)
    return _curvekit.tangents(_curve(curve1), _curve(curve2), tol=tol)


Method = Literal["f1", "f2", "f3"]
"""Elber and Kim's bisector functions: Eq. 3, the normal form, Eq. 13."""


@overload
def bisector(
    curve1: CurveLike,
    curve2: Optional[CurveLike] = ...,
    *,
    method: Method = ...,
    trimmed: bool = ...,
    chord_tol: float = ...,
    tol: float = ...,
) -> Bisector: ...
@overload
def bisector(
    curve1: Many,
    curve2: Union[CurveLike, Many, None] = ...,
    *,
    method: Method = ...,
    trimmed: bool = ...,
    chord_tol: float = ...,
    tol: float = ...,
) -> List[Bisector]: ...
def bisector(
    curve1: Any,
    curve2: Any = None,
    *,
    method: Method = "f3",
    trimmed: bool = False,
    chord_tol: float = 1e-3,
    tol: float = 1e-12,
) -> Any:
    """The bisector of two curves, or the self-bisector of one, as polylines within
    ``chord_tol`` (relative to the curves' size) of the true bisector; ``method`` is Elber and
    Kim's bisector function (``"f1"``, ``"f2"``, ``"f3"``); ``trimmed`` keeps only the points
    whose feet are the nearest points of the curves. Given a list as ``curve1``, the bisector
    of each (with ``curve2``, one curve or a list paired in order), in parallel."""
    if _is_many(curve1):
        first = _curves(curve1)
        second = None if curve2 is None else _paired(first, curve2, "bisector")
        return _curvekit.bisector_many(
            first, second, method=method, trimmed=trimmed, chord_tol=chord_tol, tol=tol
        )
    return _curvekit.bisector(
        _curve(curve1),
        None if curve2 is None else _curve(curve2),
        method=method,
        trimmed=trimmed,
        chord_tol=chord_tol,
        tol=tol,
    )


@overload
def medial(
    region: CurveLike, *, chord_tol: float = ..., fit: bool = ..., exterior: bool = ..., tol: float = ...
) -> MedialAxis: ...
@overload
def medial(
    region: Many, *, chord_tol: float = ..., fit: bool = ..., exterior: bool = ..., tol: float = ...
) -> List[MedialAxis]: ...
def medial(
    region: Any,
    *,
    chord_tol: float = 1e-3,
    fit: bool = False,
    exterior: bool = False,
    tol: float = 1e-12,
) -> Any:
    """The medial axis of a region (or of the area inside a closed curve or profile): a graph
    of edges whose points carry the radius of the largest inscribed disk; ``fit`` adds each
    edge as a B-spline; ``exterior`` gives the Voronoi diagram outside instead. Given a list
    of regions, a list of axes, computed in parallel."""
    return _one_or_many("medial", region, chord_tol=chord_tol, fit=fit, exterior=exterior, tol=tol)


@overload
def offset(
    region: CurveLike,
    *,
    distance: Optional[float] = ...,
    distances: Optional[Sequence[float]] = ...,
    step: Optional[float] = ...,
    outward: bool = ...,
    chord_tol: float = ...,
    tol: float = ...,
) -> Offsets: ...
@overload
def offset(
    region: Many,
    *,
    distance: Optional[float] = ...,
    distances: Optional[Sequence[float]] = ...,
    step: Optional[float] = ...,
    outward: bool = ...,
    chord_tol: float = ...,
    tol: float = ...,
) -> List[Offsets]: ...
def offset(
    region: Any,
    *,
    distance: Optional[float] = None,
    distances: Optional[Sequence[float]] = None,
    step: Optional[float] = None,
    outward: bool = False,
    chord_tol: float = 1e-3,
    tol: float = 1e-12,
) -> Any:
    """The inward offsets of a region (pocketing tool paths) at ``distance``, at each of
    ``distances``, or at every multiple of ``step`` while the region lasts: closed loops
    (``to_dict()``: the tool's profile documents; ``polylines(k)`` for drawing), from the
    region's medial axis, so that they never cross; ``outward`` grows the region instead (from
    its exterior axis, for distances below half its size). Given a list of regions, a list of
    results, computed in parallel."""
    listed = None if distances is None else [float(d) for d in distances]
    return _one_or_many(
        "offset",
        region,
        distance=distance,
        distances=listed,
        step=step,
        outward=outward,
        chord_tol=chord_tol,
        tol=tol,
    )


@overload
def vcarve(
    region: CurveLike, *, angle: float, max_depth: Optional[float] = ..., chord_tol: float = ..., tol: float = ...
) -> VCarve: ...
@overload
def vcarve(
    region: Many, *, angle: float, max_depth: Optional[float] = ..., chord_tol: float = ..., tol: float = ...
) -> List[VCarve]: ...
def vcarve(
    region: Any,
    *,
    angle: float,
    max_depth: Optional[float] = None,
    chord_tol: float = 1e-3,
    tol: float = 1e-12,
) -> Any:
    """The tool paths of a V-bit of included ``angle`` (degrees) over the region's medial axis,
    each point at the depth ``-radius / tan(angle / 2)`` that cuts its largest disk; with
    ``max_depth``, no deeper, and a flat pass along the offset where the axis is deeper. Given
    a list of regions, a list of results, computed in parallel."""
    return _one_or_many("vcarve", region, angle=angle, max_depth=max_depth, chord_tol=chord_tol, tol=tol)
