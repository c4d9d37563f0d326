"""Drawings read independently of curvekit: SVG with svgelements, DXF with ezdxf.

A drawing becomes closed rings of exact pieces (`geometry`), and the region they bound as the
renderer would fill it (shapely polygons of the densely flattened rings), together with what makes
it invalid for curvekit's contract (open chains, crossings, ...) and what it skips. SVG subpaths
are closed as the contract closes them (a gap within what the written numbers can hide is closed
by moving an end, not by a line) and degenerate Bézier ends read as it reads them: see
`close_subpath` and `as_drawn`, written from the contract's text, not from curvekit's code.
"""

from __future__ import annotations

import io
import math
import re
import xml.etree.ElementTree as ET
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import shapely
from shapely.geometry import LinearRing, MultiPolygon, Polygon

from geometry import Bezier, EllipticArc, Line, Nurbs, Piece, Ring

FLATTEN = 1e-5  # chord error of the oracle's polygons, relative to the size
CLOSE = 1e-9  # a chain whose ends are this close (relative to the size) is closed (contract)
NEAR_CLOSE = 1e-4  # ... and one with a gap below this (a rounding slip in an editor) is ambiguous


@dataclass
class Drawing:
    """What the oracle knows about one input file."""

    path: Path
    kind: str  # "svg" or "dxf"
    rings: list[Ring] = field(default_factory=list)
    ring_rules: list[tuple[int, str]] = field(default_factory=list)  # (element, fill rule) per ring
    open_chains: list[tuple[str, float]] = field(default_factory=list)  # (label, gap)
    invalid: list[str] = field(default_factory=list)  # "open: ...", "cross: ...", ...
    self_crossing: set[int] = field(default_factory=set)  # rings that cross or touch themselves
    ambiguous: list[str] = field(default_factory=list)
    skipped: Counter = field(default_factory=Counter)  # entity types left out that are not outlines
    shapes: Counter = field(default_factory=Counter)  # SVG basic shapes read (beside <path>)
    outline_skipped: list[str] = field(default_factory=list)  # left-out curves: result uncertified
    units: int | None = None
    size: float = 0.0
    parts: list[tuple[int, list[int]]] = field(default_factory=list)  # (outer ring, hole rings)
    part_polygons: list[Polygon] = field(default_factory=list)

    @property
    def tol(self) -> float:
        return FLATTEN * self.size

    @property
    def valid(self) -> bool:
        return not self.invalid and bool(self.parts)

    @property
    def region(self) -> MultiPolygon:
        return MultiPolygon(self.part_polygons)


# ----------------------------------------------------------------------------------------------
# SVG


def read_svg(path: Path) -> Drawing:
    """Every filled shape, in user coordinates (transforms applied, the root's viewBox ignored as
    curvekit's contract reads it), one subpath per ring, closed as the contract closes it (see
    `close_subpath`)."""
    from svgelements import SVG, Arc, Close, CubicBezier, Matrix, Move, QuadraticBezier, Shape
    from svgelements import Line as SvgLine
    from svgelements import Path as SvgPath

    root = ET.parse(path).getroot()
    for attribute in ("viewBox", "width", "height", "preserveAspectRatio"):
        root.attrib.pop(attribute, None)
    # Not reified by the parser: each element's own transform is needed, since the closing
    # tolerance and the handle rule are in the units the numbers are written in.
    document = SVG.parse(io.StringIO(ET.tostring(root, encoding="unicode")), reify=False)
    drawing = Drawing(path=path, kind="svg")
    chains: list[tuple[int, str, list[Piece], bool, str]] = []
    for number, element in enumerate(e for e in document.elements() if isinstance(e, Shape)):
        element_index = number
        name = type(element).__name__
        if name != "Path":
            drawing.shapes[name] += 1
        matrix = Matrix(element.transform)
        linear = np.array([[matrix.a, matrix.c], [matrix.b, matrix.d]], float)
        element.reify()
        writing = Writing.of_element(element)
        rule = str(element.values.get("fill-rule", "nonzero")).strip().lower()
        filled = str(element.values.get("fill", "")).strip().lower() != "none"
        if not filled:
            # Outlines drawn unfilled (as CAD programs export them) nest even-odd, all together.
            element_index, rule = -1, "evenodd"
        path_data = element if isinstance(element, SvgPath) else SvgPath(element)
        segments = list(path_data)
        runs = writing.runs
        if runs is None:  # a basic shape: absolute throughout
            runs = [("M" if isinstance(s, Move) else "Z" if isinstance(s, Close) else "", 0) for s in segments]
        if len(runs) != len(segments) or any(
            isinstance(s, Move) != (kind == "M") or isinstance(s, Close) != (kind == "Z") for s, (kind, _) in zip(segments, runs)
        ):
            raise ValueError(f"{name.lower()} {number}: its path data reads as {len(runs)} commands, svgelements makes {len(segments)} segments")
        pieces: list[Piece] = []
        subpath_index = -1
        relative = 0  # relative commands since the last absolute one, at the subpath's last command

        def finish(said_close: bool):
            if pieces:
                closed, note = close_subpath(pieces, said_close, filled, writing.quantum, relative, linear)
                label = f"{name.lower()} {number} subpath {subpath_index}"
                if note:
                    drawing.ambiguous.append(f"{label} {note}")
                chains.append((element_index, rule, list(pieces), closed, label))
            pieces.clear()

        for segment, (_, count) in zip(segments, runs):
            if isinstance(segment, Move):
                finish(False)
                subpath_index += 1
                continue
            relative = count
            start = np.array([segment.start.x, segment.start.y])
            end = np.array([segment.end.x, segment.end.y])
            if isinstance(segment, Close):
                finish(True)
                continue
            if isinstance(segment, SvgLine):
                piece: Piece = Line(start, end)
            elif isinstance(segment, QuadraticBezier):
                piece = Bezier([start, [segment.control.x, segment.control.y], end])
            elif isinstance(segment, CubicBezier):
                piece = Bezier([start, [segment.control1.x, segment.control1.y], [segment.control2.x, segment.control2.y], end])
            elif isinstance(segment, Arc):
                piece = svg_arc(segment, start, end)
            else:
                raise ValueError(f"unknown SVG segment {type(segment).__name__}")
            if not is_zero_length(piece):
                pieces.append(as_drawn(piece, writing.quantum, linear))
        finish(False)
    build(drawing, chains)
    return drawing


# How curvekit's contract reads SVG path data beyond the letter of SVG (interfaces.md, "Closed
# chains in drawings", and the SVG reader's documentation), written here from that text alone:
#  - a subpath whose end comes back to its start within what the numbers as written can hide is
#    closed, with or without Z: half a unit in the last place written per coordinate, and
#    relative commands add their roundings up; the gap allowed is a unit in the last place per
#    relative command since the last absolute one, plus one, never more than 1e-3 of the
#    subpath's size nor less than a few units of floating-point rounding. Its last piece is made
#    to end exactly at the start (where the last is an arc and the first is not, the first is
#    made to start at the end instead: an arc whose end moves is no longer an arc);
#  - beyond that gap, Z draws the closing line, and so does a filled element's open subpath (SVG
#    fills it as closed); an unfilled element's open subpath stays open;
#  - a quadratic whose control point repeats an end, or a cubic with three points at one end's
#    place, is the straight line it draws; a cubic whose inner control point repeats its end has
#    it moved off, towards the next control point, by half a unit in the last place written (at
#    most 1e-2 of the way): a change the written numbers cannot tell from the drawing.
MOST_GAP = 1e-3  # the largest closing gap, relative to the subpath's size
FEW_ROUNDINGS = 16.0 * np.finfo(float).eps  # the least, relative to the largest coordinate
HANDLE_MOST = 1e-2  # the largest share of the way a handle on its end is moved off it

PATH_ARGUMENTS = {"M": 2, "L": 2, "T": 2, "H": 1, "V": 1, "C": 6, "S": 4, "Q": 4, "A": 7, "Z": 0}
NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
SEPARATORS = " \t\r\n,"


@dataclass
class Writing:
    """How an element's numbers are written: a unit in their last decimal place, and per segment
    that svgelements makes of its path data (a moveto, each coordinate set of a command, a
    closepath) its command letter and the count of relative commands since the last absolute one."""

    quantum: float
    runs: list[tuple[str, int]] | None  # None: a basic shape, absolute throughout

    @staticmethod
    def of_element(element) -> "Writing":
        d = element.values.get("d")
        if type(element).__name__ == "Path" and d is not None:
            return Writing(10.0 ** -written_places(str(d)), relative_runs(str(d)))
        attributes = ("x", "y", "width", "height", "rx", "ry", "cx", "cy", "r", "x1", "y1", "x2", "y2", "points")
        text = " ".join(str(element.values.get(a, "")) for a in attributes)
        return Writing(10.0 ** -written_places(text), None)


def written_places(text: str) -> int:
    """The most decimals written in any number of `text`, less its exponent (none below 0)."""
    places = 0
    for match in NUMBER.finditer(text):
        number = match.group(0)
        mantissa, _, exponent = number.lower().partition("e")
        decimals = len(mantissa.partition(".")[2])
        places = max(places, decimals - (int(exponent) if exponent else 0))
    return places


def relative_runs(d: str) -> list[tuple[str, int]]:
    """(command letter, relative commands since the last absolute one) per segment of path data."""
    runs: list[tuple[str, int]] = []
    i, command, count, first = 0, None, 0, True
    n = len(d)

    def skip(i):
        while i < n and d[i] in SEPARATORS:
            i += 1
        return i

    while True:
        i = skip(i)
        if i >= n:
            break
        if d[i].isalpha():
            command = d[i]
            i += 1
            if command in "Zz":
                runs.append(("Z", count))
                continue
        elif command is None or command in "Zz":
            raise ValueError(f"path data: a number without a command at {i}")
        letter = command.upper()
        if letter not in PATH_ARGUMENTS:
            raise ValueError(f"path data: unknown command {command!r}")
        for argument in range(PATH_ARGUMENTS[letter]):
            i = skip(i)
            if letter == "A" and argument in (3, 4) and i < n and d[i] in "01":
                i += 1  # a flag: one digit, which may run into the next number
                continue
            match = NUMBER.match(d, i)
            if not match:
                raise ValueError(f"path data: a number expected at {i} in {d[max(0, i - 20):i + 20]!r}")
            i = match.end()
        relative = command.islower() and not (first and letter == "M")  # a leading m is absolute
        count = count + 1 if relative else 0
        runs.append((letter, count))
        first = False
        if letter == "M":
            command = "l" if command == "m" else "L"  # further coordinate pairs are line-tos
    return runs


def closing_tolerance(pieces: list[Piece], quantum: float, relative: int, linear: np.ndarray) -> tuple[float, np.ndarray, float]:
    """The gap a subpath may leave and still be closed, in its own units; the map from the
    drawing's units back to its own; the subpath's size in its own units."""
    back = np.linalg.inv(linear)
    local = np.concatenate([p.points(np.linspace(0.0, 1.0, 17)) for p in pieces]) @ back.T
    size = float(np.max(np.ptp(local, axis=0)))
    floor = FEW_ROUNDINGS * float(np.max(np.abs(local)))
    return max(min(quantum * (relative + 1), MOST_GAP * size), floor), back, size


def close_subpath(pieces: list[Piece], said_close: bool, filled: bool, quantum: float, relative: int, linear: np.ndarray) -> tuple[bool, str]:
    """Closes the subpath in place as the contract reads it: (whether it is closed, a note where
    its gap equals the tolerance to within rounding, a limit case that binary rounding decides)."""
    start, end = pieces[0].start, pieces[-1].end
    tolerance, back, size = closing_tolerance(pieces, quantum, relative, linear)
    gap = float(np.hypot(*(back @ (end - start))))  # Euclidean, in the units written (as curvekit closes)
    # A gap of exactly the tolerance (one unit written, absolute coordinates) is decided by binary
    # rounding of the decimals, here as in curvekit: noted as ambiguous.
    note = f"ends {gap:.6g} from its start, its closing tolerance is {tolerance:.6g} (a limit case)" if abs(gap - tolerance) <= 1e-9 * tolerance else ""
    if gap <= tolerance:
        if np.array_equal(start, end):
            return True, note
        arc_last = isinstance(pieces[-1], EllipticArc)
        if arc_last and not isinstance(pieces[0], EllipticArc):
            pieces[0] = moved(pieces[0], start=end)
        elif not arc_last or gap > CLOSE * size:  # an arc's slip of floating-point rounding is left as it is
            pieces[-1] = moved(pieces[-1], end=start)
        return True, note
    if said_close or filled:
        pieces.append(Line(end, start))
        return True, note
    return False, note


def moved(piece: Piece, start=None, end=None) -> Piece:
    """The piece with its first or last point moved (for a Bézier, its end control point)."""
    if isinstance(piece, Line):
        return Line(piece.p0 if start is None else start, piece.p1 if end is None else end)
    if isinstance(piece, Bezier):
        control = piece.control.copy()
        if start is not None:
            control[0] = start
        if end is not None:
            control[-1] = end
        return Bezier(control)
    if isinstance(piece, EllipticArc):
        return MovedArcEnd(piece, end)
    raise ValueError(f"cannot move an end of a {type(piece).__name__}")


class MovedArcEnd(Piece):
    """An elliptic arc whose end is moved (a subpath that ends and starts with arcs, closed within
    its tolerance): the arc as rational quadratic Bézier pieces of at most a quarter turn each,
    the last one's end control point moved. How curvekit cuts an arc into rational pieces is its
    own affair, so near its end this piece may differ from curvekit's by a share of the gap (at
    most the gap itself: 1e-3 of the subpath's size, 4e-5 of it in this corpus's six cases)."""

    def __init__(self, arc: EllipticArc, end):
        turns = max(1, int(math.ceil(abs(arc.phi1 - arc.phi0) / (math.pi / 2) - 1e-12)))
        angles = np.linspace(arc.phi0, arc.phi1, turns + 1)
        self.spans = []
        for a, b in zip(angles[:-1], angles[1:]):
            half = 0.5 * (b - a)
            middle = 0.5 * (a + b)
            control = np.array([
                arc.center + arc.u * math.cos(a) + arc.v * math.sin(a),
                arc.center + (arc.u * math.cos(middle) + arc.v * math.sin(middle)) / math.cos(half),
                arc.center + arc.u * math.cos(b) + arc.v * math.sin(b),
            ])
            self.spans.append((control, np.array([1.0, math.cos(half), 1.0])))
        self.spans[-1][0][-1] = np.asarray(end, float)
        self.count = len(self.spans)

    def _locate(self, t):
        t = np.asarray(t, float)
        index = np.minimum((t * self.count).astype(int), self.count - 1)
        return index, t * self.count - index

    def points(self, t):
        return self.derivatives(t, points_only=True)

    def derivatives(self, t, points_only=False):
        index, s = self._locate(t)
        points, first, second = (np.zeros((len(s), 2)) for _ in range(3))
        for k, (control, w) in enumerate(self.spans):
            mask = index == k
            if not mask.any():
                continue
            u = s[mask][:, None]
            basis = np.hstack([(1 - u) ** 2, 2 * u * (1 - u), u * u])
            d1 = np.hstack([-2 * (1 - u), 2 - 4 * u, 2 * u])
            d2 = np.tile([2.0, -4.0, 2.0], (len(u), 1))
            a, a1, a2 = (basis * w) @ control, (d1 * w) @ control, (d2 * w) @ control
            h, h1, h2 = (basis @ w)[:, None], (d1 @ w)[:, None], (d2 @ w)[:, None]
            p = a / h
            f = (a1 - h1 * p) / h
            points[mask] = p
            first[mask] = f * self.count
            second[mask] = (a2 - 2 * h1 * f - h2 * p) / h * self.count**2
        return points if points_only else (first, second)

    def flatten(self, tol):
        probe = np.linspace(0.0, 1.0, 257)
        _, second = self.derivatives(probe)
        bound = 4.0 * float(np.max(np.hypot(second[:, 0], second[:, 1]))) + 1e-300
        count = max(2, int(math.ceil(math.sqrt(bound / (8.0 * tol)))) + 1)
        # every span boundary a flattening point, so that each chord lies within one span
        count = int(math.ceil((count - 1) / self.count)) * self.count + 1
        return np.linspace(0.0, 1.0, min(count, 200_000))


def as_drawn(piece: Piece, quantum: float, linear: np.ndarray) -> Piece:
    """A Bézier with a degenerate end as the contract reads it (see above)."""
    if not isinstance(piece, Bezier) or len(piece.control) not in (3, 4):
        return piece
    c = piece.control
    same = [[np.array_equal(a, b) for b in c] for a in c]
    if len(c) == 3:
        return Line(c[0], c[2]) if same[1][0] or same[1][2] else piece
    if (same[0][1] and same[1][2]) or (same[1][2] and same[2][3]):
        return Line(c[0], c[3])
    back = np.linalg.inv(linear)
    control = c.copy()
    for handle, end, towards in ((1, 0, 2), (2, 3, 1)):
        if same[handle][end]:
            way = c[towards] - c[end]
            share = min(0.5 * quantum / float(np.hypot(*(back @ way))), HANDLE_MOST)
            control[handle] = c[end] + share * way
    return Bezier(control)


def svg_arc(segment, start: np.ndarray, end: np.ndarray) -> Piece:
    """An SVG arc as centre + u cos + v sin, u and v the images of its two semi-axes.

    svgelements' sweep is the signed angle as drawn, so its sign flips with the orientation of
    (u, v) under a mirroring transform; the end point is checked against svgelements' own.
    """
    if segment.sweep is None or segment.sweep == 0 or segment.prx is None:
        return Line(start, end)
    center = np.array([segment.center.x, segment.center.y])
    u = np.array([segment.prx.x, segment.prx.y]) - center
    v = np.array([segment.pry.x, segment.pry.y]) - center
    if abs(u[0] * v[1] - u[1] * v[0]) <= 1e-14 * (u @ u + v @ v):
        return Line(start, end)
    arc = EllipticArc(center, u, v, 0.0, 0.0)
    phi0 = arc.angle_of(start)
    sweep = float(segment.sweep) * math.copysign(1.0, u[0] * v[1] - u[1] * v[0])
    arc = EllipticArc(center, u, v, phi0, phi0 + sweep)
    scale = np.hypot(*u) + np.hypot(*v)
    if np.hypot(*(arc.end - end)) > 1e-6 * scale:
        raise ValueError(f"SVG arc conversion missed its end point: {arc.end} vs {end}")
    return arc


def is_zero_length(piece: Piece) -> bool:
    if isinstance(piece, Line):
        control = np.array([piece.p0, piece.p1])
    elif isinstance(piece, Bezier):
        control = piece.control
    else:
        return False
    spread = np.max(np.abs(control - control[0]))
    return spread <= 1e-12 * (np.max(np.abs(control)) + 1.0)


# ----------------------------------------------------------------------------------------------
# DXF

OUTLINE_TYPES = {"LINE", "ARC", "CIRCLE", "ELLIPSE", "SPLINE", "LWPOLYLINE", "POLYLINE", "INSERT"}


def read_dxf(path: Path) -> Drawing:
    """LINE, ARC, CIRCLE, ELLIPSE, (LW)POLYLINE and SPLINE, with INSERTs expanded, chained by end points."""
    import ezdxf

    document = ezdxf.readfile(path)
    drawing = Drawing(path=path, kind="dxf")
    drawing.units = int(document.header.get("$INSUNITS", 0)) or None
    found: list[tuple[list[Piece], bool, str]] = []  # (pieces, closed by itself, label)
    for number, entity in enumerate(expanded(document.modelspace())):
        kind = entity.dxftype()
        label = f"{kind} #{number}"
        if kind not in OUTLINE_TYPES:
            drawing.skipped[kind] += 1
            continue
        if kind == "POLYLINE" and entity.is_3d_polyline:
            heights = [v.dxf.location.z for v in entity.vertices]
            if max(heights) - min(heights) > 0 or heights[0] != 0:
                drawing.outline_skipped.append(f"{label}: a 3D polyline off the plane")
                continue
        if kind in ("LWPOLYLINE", "POLYLINE"):
            pieces = orient([p for p in map(dxf_piece, entity.virtual_entities()) if p is not None and not is_zero_length(p)])
            if pieces:
                closed = bool(entity.closed) if kind == "LWPOLYLINE" else bool(entity.is_closed)
                found.append((pieces, closed, label))
            continue
        if kind == "SPLINE" and entity.control_point_count() == 0:
            drawing.ambiguous.append(f"{label}: a spline given by fit points only")
            drawing.outline_skipped.append(f"{label}: fit points only")
            continue
        if any(abs(z) > 0 for z in entity_heights(entity)):
            drawing.outline_skipped.append(f"{label}: off the plane z = 0")
            continue
        piece = dxf_piece(entity)
        if piece is None:
            continue
        pieces = split_c0(piece)
        found.append((pieces, kind in ("CIRCLE",) or (kind == "ELLIPSE" and is_full_ellipse(entity)), label))
    chains = chain(found, drawing)
    build(drawing, chains)
    return drawing


def expanded(layout):
    """Entities with every INSERT (and MINSERT grid) replaced by its block's entities, transformed."""
    for entity in layout:
        if entity.dxftype() == "INSERT":
            inserts = list(entity.multi_insert()) if entity.mcount > 1 else [entity]
            for insert in inserts:
                yield from expanded(insert.virtual_entities())
        else:
            yield entity


def entity_heights(entity) -> list[float]:
    kind = entity.dxftype()
    if kind == "LINE":
        return [entity.dxf.start.z, entity.dxf.end.z]
    if kind in ("ARC", "CIRCLE"):
        return [entity.ocs().to_wcs(entity.dxf.center).z]
    if kind == "ELLIPSE":
        return [entity.dxf.center.z, entity.dxf.major_axis.z]
    if kind == "SPLINE":
        return [p[2] for p in entity.control_points]
    return [0.0]


def is_full_ellipse(entity) -> bool:
    span = (entity.dxf.end_param - entity.dxf.start_param) % (2 * math.pi)
    return span < 1e-12 or abs(span - 2 * math.pi) < 1e-12


def dxf_piece(entity) -> Piece | None:
    """One exact piece for a LINE, ARC, CIRCLE, ELLIPSE or SPLINE in world coordinates."""
    kind = entity.dxftype()
    if kind == "LINE":
        start, end = entity.dxf.start, entity.dxf.end
        return Line((start.x, start.y), (end.x, end.y))
    if kind in ("ARC", "CIRCLE"):
        ocs = entity.ocs()
        center = ocs.to_wcs(entity.dxf.center)
        radius = entity.dxf.radius
        u = ocs.to_wcs((radius, 0, 0)) - ocs.to_wcs((0, 0, 0))
        v = ocs.to_wcs((0, radius, 0)) - ocs.to_wcs((0, 0, 0))
        if kind == "CIRCLE":
            start, end = 0.0, 2 * math.pi
        else:
            start = math.radians(entity.dxf.start_angle)
            end = math.radians(entity.dxf.end_angle)
            while end <= start:
                end += 2 * math.pi
        return EllipticArc((center.x, center.y), (u.x, u.y), (v.x, v.y), start, end)
    if kind == "ELLIPSE":
        center, major = entity.dxf.center, entity.dxf.major_axis
        normal = entity.dxf.extrusion.normalize()
        minor = normal.cross(major) * entity.dxf.ratio
        start, end = entity.dxf.start_param, entity.dxf.end_param
        if is_full_ellipse(entity):
            start, end = 0.0, 2 * math.pi
        while end <= start:
            end += 2 * math.pi
        return EllipticArc((center.x, center.y), (major.x, major.y), (minor.x, minor.y), start, end)
    if kind == "SPLINE":
        control = [(p[0], p[1]) for p in entity.control_points]
        weights = list(entity.weights) or None
        return Nurbs(entity.dxf.degree, list(entity.knots), control, weights)
    return None


def orient(pieces: list[Piece]) -> list[Piece]:
    """A polyline's pieces each run from the previous one's end (an ARC of a negative bulge is
    stored counterclockwise, from the polyline's later vertex)."""
    if len(pieces) < 2:
        return pieces
    first, second = pieces[0], pieces[1]
    ends = [np.hypot(*(first.end - second.start)), np.hypot(*(first.end - second.end)),
            np.hypot(*(first.start - second.start)), np.hypot(*(first.start - second.end))]
    result = [first if min(ends[:2]) <= min(ends[2:]) else Reversed(first)]
    for piece in pieces[1:]:
        end = result[-1].end
        result.append(piece if np.hypot(*(piece.start - end)) <= np.hypot(*(piece.end - end)) else Reversed(piece))
    return result


def split_c0(piece: Piece) -> list[Piece]:
    """A spline cut at its interior knots of full multiplicity, so that corners fall on joints."""
    if not isinstance(piece, Nurbs):
        return [piece]
    cuts = [0.0, *piece.c0_breaks(), 1.0]
    return [piece.restricted(a, b) for a, b in zip(cuts[:-1], cuts[1:])]


class Reversed(Piece):
    """A piece run backwards."""

    def __init__(self, piece: Piece):
        self.piece = piece

    def points(self, t):
        return self.piece.points(1.0 - np.asarray(t, float))

    def derivatives(self, t):
        first, second = self.piece.derivatives(1.0 - np.asarray(t, float))
        return -first, second

    def second_derivative_bound(self):
        return self.piece.second_derivative_bound()

    def flatten(self, tol):
        return np.sort(1.0 - self.piece.flatten(tol))


def chain(found, drawing: Drawing):
    """Entities joined end to start (either way round) into chains: (element, rule, pieces, closed, label)."""
    all_points = np.concatenate([np.array([p.start, p.end]) for pieces, _, _ in found for p in pieces]) if found else np.zeros((0, 2))
    if len(all_points) == 0:
        return []
    size = float(np.max(np.ptp(all_points, axis=0))) or 1.0
    join = NEAR_CLOSE * size
    chains = []
    loose: list[tuple[list[Piece], str]] = []
    for pieces, closed, label in found:
        if closed or np.hypot(*(pieces[0].start - pieces[-1].end)) <= join:
            chains.append((0, "evenodd", pieces, True, label))
        else:
            loose.append((pieces, label))
    used = [False] * len(loose)
    for first in range(len(loose)):
        if used[first]:
            continue
        used[first] = True
        pieces, labels = list(loose[first][0]), [loose[first][1]]
        while True:
            end = pieces[-1].end
            candidates = []
            for other, (others, label) in enumerate(loose):
                if used[other]:
                    continue
                if np.hypot(*(others[0].start - end)) <= join:
                    candidates.append((other, others))
                elif np.hypot(*(others[-1].end - end)) <= join:
                    candidates.append((other, [Reversed(p) for p in reversed(others)]))
            if len(candidates) > 1:
                drawing.invalid.append(f"branch: {len(candidates) + 1} entities meet at {tuple(np.round(end, 6))}")
            if not candidates:
                break
            other, extension = candidates[0]
            used[other] = True
            pieces.extend(extension)
            labels.append(loose[other][1])
            if np.hypot(*(pieces[-1].end - pieces[0].start)) <= join:
                break
        closed = np.hypot(*(pieces[-1].end - pieces[0].start)) <= join
        chains.append((0, "evenodd", pieces, bool(closed), "+".join(labels[:3]) + ("…" if len(labels) > 3 else "")))
    return chains


# ----------------------------------------------------------------------------------------------
# Rings and the filled region


def build(drawing: Drawing, chains) -> None:
    """Rings from the closed chains, the validity of the whole, and the filled parts."""
    every = [p for _, _, pieces, _, _ in chains for p in pieces]
    if not every:
        drawing.invalid.append("empty: no usable geometry")
        return
    probe = np.concatenate([p.points(np.linspace(0, 1, 33)) for p in every])
    drawing.size = float(np.max(np.ptp(probe, axis=0)))
    if drawing.size <= 0:
        drawing.invalid.append("empty: the geometry has no extent")
        return
    for element, rule, pieces, closed, label in chains:
        gap = float(np.hypot(*(pieces[-1].end - pieces[0].start)))
        if not closed and gap > CLOSE * drawing.size:
            drawing.open_chains.append((label, gap))
            if gap > NEAR_CLOSE * drawing.size:
                drawing.invalid.append(f"open: {label} ends {gap:.6g} from its start")
                continue
            drawing.ambiguous.append(f"{label} ends {gap:.3g} from its start (near-closed)")
            pieces = pieces + [Line(pieces[-1].end, pieces[0].start)]
        drawing.rings.append(Ring(pieces, label))
        drawing.ring_rules.append((element, rule))
    analyse_rings(drawing)


def analyse_rings(drawing: Drawing) -> None:
    """Simple rings, pairwise disjoint, nested into faces filled by each element's fill rule."""
    tol = drawing.tol
    polygons, lines = [], []
    for index, ring in enumerate(drawing.rings):
        points, _, _ = ring.flatten(tol)
        if len(points) < 3 or abs(ring.signed_area(tol)) <= (tol * tol):
            drawing.invalid.append(f"degenerate: {ring.label} encloses no area")
            polygons.append(None)
            lines.append(None)
            continue
        line = LinearRing(points)
        if not line.is_simple:
            drawing.self_crossing.add(index)
            drawing.invalid.append(f"cross: {ring.label} crosses itself near {first_self_crossing(line)}")
        polygons.append(Polygon(points))
        lines.append(line)
    live = [i for i, line in enumerate(lines) if line is not None]
    tree = shapely.STRtree([lines[i] for i in live])
    for position, i in enumerate(live):
        for other in tree.query(lines[i], predicate="intersects"):
            j = live[int(other)]
            if j > i:
                where = shapely.intersection(lines[i], lines[j]).representative_point()
                drawing.invalid.append(f"cross: {drawing.rings[i].label} meets {drawing.rings[j].label} near ({where.x:.6g}, {where.y:.6g})")
        near = tree.query(lines[i], predicate="dwithin", distance=1e-4 * drawing.size)
        for other in near:
            j = live[int(other)]
            if j > i and not lines[i].intersects(lines[j]):
                drawing.ambiguous.append(f"{drawing.rings[i].label} passes within 1e-4 of the size of {drawing.rings[j].label}")
    if drawing.invalid:
        return
    nest(drawing, polygons)


def first_self_crossing(line: LinearRing) -> str:
    """Where a ring that is not simple meets itself (for the messages)."""
    points = np.asarray(line.coords)
    merged = shapely.unary_union(shapely.linestrings(np.stack([points[:-1], points[1:]], axis=1)))
    crossings = [g for g in getattr(merged, "geoms", [merged])]
    degree = Counter()
    for piece in crossings:
        for x, y in (piece.coords[0], piece.coords[-1]):
            degree[(round(x, 9), round(y, 9))] += 1
    spot = next((p for p, d in degree.items() if d > 2), None)
    return f"({spot[0]:.6g}, {spot[1]:.6g})" if spot else "?"


def nest(drawing: Drawing, polygons: list[Polygon]) -> None:
    """Fill each face (inside a ring, outside its children) as the renderer does, then keep the
    rings that separate filled from unfilled: outers with their holes."""
    count = len(drawing.rings)
    areas = [p.area for p in polygons]
    parent = [-1] * count
    for i in range(count):
        inside_point = drawing.rings[i].flatten(drawing.tol)[0][0]
        holders = [j for j in range(count) if j != i and polygons[j].contains(shapely.Point(inside_point))]
        if holders:
            parent[i] = min(holders, key=lambda j: areas[j])
    sign = [1 if drawing.rings[i].signed_area(drawing.tol) > 0 else -1 for i in range(count)]

    def ancestors(i):
        chain_ = []
        while i >= 0:
            chain_.append(i)
            i = parent[i]
        return chain_

    def filled(i: int) -> bool:
        if i < 0:
            return False
        rings = ancestors(i)
        for element in {drawing.ring_rules[j][0] for j in rings}:
            mine = [j for j in rings if drawing.ring_rules[j][0] == element]
            rule = drawing.ring_rules[mine[0]][1]
            if (rule == "evenodd" and len(mine) % 2 == 1) or (rule != "evenodd" and sum(sign[j] for j in mine) != 0):
                return True
        return False

    boundary = [filled(i) != filled(parent[i]) for i in range(count)]
    for i in range(count):
        if not boundary[i]:
            drawing.ambiguous.append(f"{drawing.rings[i].label} is not a boundary of the fill (same fill both sides)")
    outers = [i for i in range(count) if boundary[i] and filled(i)]
    for outer in outers:
        holes = [j for j in range(count) if boundary[j] and not filled(j) and nearest_boundary_ancestor(j, parent, boundary) == outer]
        drawing.parts.append((outer, holes))
        points = drawing.rings[outer].flatten(drawing.tol)[0]
        drawing.part_polygons.append(
            Polygon(points, [drawing.rings[h].flatten(drawing.tol)[0] for h in holes])
        )


def nearest_boundary_ancestor(i: int, parent: list[int], boundary: list[bool]) -> int:
    i = parent[i]
    while i >= 0 and not boundary[i]:
        i = parent[i]
    return i


def read(path: Path) -> Drawing:
    path = Path(path)
    return read_dxf(path) if path.suffix.lower() == ".dxf" else read_svg(path)
