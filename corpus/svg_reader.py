"""SVG read independently of curvekit, with svgelements: every filled shape in user coordinates,
its subpaths closed as the contract closes them and degenerate Bézier ends read as it reads them
(`close_subpath`, `as_drawn`), into the chains `drawing.build` makes rings of.
"""

from __future__ import annotations

import io
import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from geometry import Bezier, EllipticArc, Line, Piece
from drawing import CLOSE, Drawing, build, is_zero_length


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
