"""Drawings read independently of curvekit: SVG with svgelements, DXF with ezdxf.

A drawing becomes closed rings of exact pieces (`geometry`), and the region they bound as the
renderer would fill it (shapely polygons of the densely flattened rings), together with what makes
it invalid for curvekit's contract (open chains, crossings, ...) and what it skips. SVG subpaths
are closed as the contract closes them (a gap within what the written numbers can hide is closed
by moving an end, not by a line) and degenerate Bézier ends read as it reads them: see
`close_subpath` and `as_drawn` in `svg_reader`, written from the contract's text, not from
curvekit's code. The readers are `svg_reader` and `dxf_reader`; this module holds what they make
(the `Drawing`) and the rings and filled region they build.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import shapely
from shapely.geometry import LinearRing, MultiPolygon, Polygon

from geometry import Bezier, Line, Piece, Ring

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
    from dxf_reader import read_dxf  # (here, not at the top: the readers build on this module)
    from svg_reader import read_svg

    path = Path(path)
    return read_dxf(path) if path.suffix.lower() == ".dxf" else read_svg(path)
