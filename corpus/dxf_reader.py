"""DXF read independently of curvekit, with ezdxf: the outline entities, INSERTs expanded, chained
by their end points into the chains `drawing.build` makes rings of.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from drawing import NEAR_CLOSE, Drawing, build, is_zero_length
from geometry import EllipticArc, Line, Nurbs, Piece


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
