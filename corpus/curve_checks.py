"""The oracle's checks of the single-curve commands' answers: antipodal pairs (normals at both
ends, the diameter pair present) and inflections (sign changes of the curvature, corners), with
the exact pieces' derivatives. Nothing here calls curvekit's code.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely

from drawing import FLATTEN, Drawing
from geometry import Line, Piece, Ring, curvature_numerator
from region_checks import fmt

ANGLE = 1e-4  # a pair's segment must lie along both normals within this angle (radians)
ON_CURVE = 1e-6  # a reported point must lie this close to the curve (relative to the size)
CORNER = 1e-7  # joints turning more than this are corners; 1e-10 .. 1e-6 is left undecided


# ----------------------------------------------------------------------------------------------
# Antipodal pairs and inflections


@dataclass
class Foot:
    piece: int
    t: float
    distance: float
    corner: bool
    joint: int | None  # the piece index that starts at this corner


def foot(ring: Ring, point, size: float) -> Foot:
    piece, t, distance = ring.project(point, FLATTEN * size)
    joint = piece if t <= 1e-9 else (piece + 1) % len(ring.pieces) if t >= 1 - 1e-9 else None
    if joint is None:
        # a corner reported a rounding step away from the joint
        for candidate in (piece, (piece + 1) % len(ring.pieces)):
            if np.hypot(*(ring.pieces[candidate].start - np.asarray(point))) <= 1e-9 * size:
                joint = candidate
    corner = joint is not None and abs(ring.joint_turn(joint)) > CORNER
    return Foot(piece, t, distance, corner, joint)


def inward_directions(ring: Ring, at: Foot, counterclockwise: bool) -> list[np.ndarray]:
    """The inward normal at a smooth point, or the two bounding the cone at a corner."""
    turn = 1.0 if counterclockwise else -1.0

    def normal(tangent):
        return turn * np.array([-tangent[1], tangent[0]])

    if at.corner:
        return [normal(ring.pieces[at.joint - 1].tangent(1.0)), normal(ring.pieces[at.joint].tangent(0.0))]
    return [normal(ring.pieces[at.piece].tangent(at.t))]


def along_normal(direction: np.ndarray, normals: list[np.ndarray], convex: bool) -> bool:
    """The unit direction lies along the (single) inward normal, or inside the convex corner's cone."""
    if len(normals) == 1 or not convex:
        return any(float(direction @ n) > 0 and abs(float(n[0] * direction[1] - n[1] * direction[0])) <= ANGLE for n in normals)
    a, b = normals
    span = math.atan2(a[0] * b[1] - a[1] * b[0], float(a @ b))
    angle = math.atan2(a[0] * direction[1] - a[1] * direction[0], float(a @ direction))
    low, high = min(0.0, span), max(0.0, span)
    return low - ANGLE <= angle <= high + ANGLE


def identify_ring(drawing: Drawing, points: list[np.ndarray]) -> int:
    """The ring all the reported points lie on (ring 0 when nothing was reported)."""
    if not points:
        return 0
    scores = [max(float(ring.chord_distances(p, drawing.tol).min()) for p in points[:20]) for ring in drawing.rings]
    return int(np.argmin(scores))


def check_antipodal(drawing: Drawing, document: dict) -> tuple[list[str], dict]:
    pairs = document.get("pairs", [])
    families = document.get("families", [])
    reported = [np.asarray(p[key], float) for p in pairs for key in ("p", "q")]
    ring_index = identify_ring(drawing, reported)
    ring = drawing.rings[ring_index]
    size = drawing.size
    counterclockwise = ring.signed_area(drawing.tol) > 0
    problems = []
    longest = 0.0
    for number, pair in enumerate(pairs):
        p, q = np.asarray(pair["p"], float), np.asarray(pair["q"], float)
        span = float(np.hypot(*(q - p)))
        longest = max(longest, span)
        if abs(span - float(pair.get("distance", span))) > 1e-9 * size:
            problems.append(f"pair {number}: distance {pair['distance']} but |q - p| = {span:.12g}")
        if span <= ON_CURVE * size:
            problems.append(f"pair {number}: p and q coincide at {fmt(p)}")
            continue
        direction = (q - p) / span
        for name, point, towards in (("p", p, direction), ("q", q, -direction)):
            at = foot(ring, point, size)
            if at.distance > ON_CURVE * size:
                problems.append(f"pair {number}: {name} = {fmt(point)} is {at.distance / size:.2e} of the size off the curve")
                continue
            normals = inward_directions(ring, at, counterclockwise)
            convex = at.corner and (ring.joint_turn(at.joint) > 0) == counterclockwise
            if at.corner and not convex and not along_normal(towards, normals, False):
                problems.append(f"pair {number}: {name} = {fmt(point)} is a reflex corner (reflex corners take no part)")
            elif not along_normal(towards, normals, convex):
                angle = min(abs(math.asin(max(-1.0, min(1.0, float(n[0] * towards[1] - n[1] * towards[0]))))) for n in normals)
                problems.append(f"pair {number}: pq is {angle:.2e} rad off the inward normal at {name} = {fmt(point)}")
    for family in families:
        for p, q in zip(family.get("p", []), family.get("q", [])):
            longest = max(longest, float(np.hypot(*(np.asarray(q) - np.asarray(p)))))
    diameter, ends = ring_diameter(ring.flatten(drawing.tol)[0])
    if longest < diameter - 1e-7 * size and not on_cone_edge(ring, ends, counterclockwise, size):
        problems.append(f"the diameter pair (length {diameter:.8g}, {fmt(ends[0])} to {fmt(ends[1])}) is missing: the longest pair reported is {longest:.8g}")
    return problems, {"ring": ring_index, "pairs": len(pairs), "families": len(families)}


def ring_diameter(points: np.ndarray) -> tuple[float, tuple[np.ndarray, np.ndarray]]:
    """The longest chord of the sampled ring (always an antipodal pair) and its ends."""
    hull = np.asarray(shapely.convex_hull(shapely.multipoints(points)).exterior.coords)
    lengths = np.hypot(hull[:, None, 0] - hull[None, :, 0], hull[:, None, 1] - hull[None, :, 1])
    i, j = np.unravel_index(int(np.argmax(lengths)), lengths.shape)
    return float(lengths[i, j]), (hull[i], hull[j])


def on_cone_edge(ring: Ring, ends, counterclockwise: bool, size: float) -> bool:
    """The diameter pair is the contract's limit case: its direction lies on the edge of a
    corner's cone of normals (then it may be reported or not)."""
    p, q = ends
    direction = (q - p) / np.hypot(*(q - p))
    for point, towards in ((p, direction), (q, -direction)):
        at = foot(ring, point, size)
        if at.corner:
            for normal in inward_directions(ring, at, counterclockwise):
                if abs(float(normal[0] * towards[1] - normal[1] * towards[0])) <= ANGLE and float(normal @ towards) > 0:
                    return True
    return False


def curvature_signs(piece: Piece, samples: int = 2001) -> tuple[np.ndarray, float] | None:
    """The signs of the curvature along a piece, None for a straight one."""
    if isinstance(piece, Line):
        return None
    t = np.linspace(0.0, 1.0, samples)
    values = curvature_numerator(piece, t)
    first, second = piece.derivatives(t)
    speed = float(np.max(np.hypot(first[:, 0], first[:, 1])))
    scale = speed * max(speed, float(np.max(np.hypot(second[:, 0], second[:, 1])))) + 1e-300
    values = np.where(np.abs(values) <= 1e-9 * scale, 0.0, values)  # rounding noise of a straight stretch
    if not values.any():
        return None
    return values, scale


def expected_inflections(ring: Ring) -> tuple[int, int, int]:
    """(required, optional, undecided): sign changes of the curvature inside pieces and across
    smooth joints; across a straight run between opposite bends one is optional; a near double
    root inside a piece makes up to two undecided."""
    required = optional = undecided = 0
    ends = []  # per piece: (sign at start, sign at end) or None when straight
    for piece in ring.pieces:
        found = curvature_signs(piece)
        if found is None:
            ends.append(None)
            continue
        values, scale = found
        signs = np.sign(values)
        nonzero = signs[signs != 0]
        required += int(np.sum(nonzero[1:] != nonzero[:-1]))
        tiny = np.abs(values) <= 1e-9 * np.max(np.abs(values))
        interior_minima = (np.abs(values[1:-1]) < np.abs(values[:-2])) & (np.abs(values[1:-1]) < np.abs(values[2:])) & tiny[1:-1]
        undecided += int(np.sum(interior_minima & (np.sign(values[:-2]) == np.sign(values[2:]))))
        ends.append((nonzero[0], nonzero[-1]))
    count = len(ring.pieces)
    corners = [abs(ring.joint_turn(i)) > CORNER for i in range(count)]
    # walk the joints: the last bend seen, whether a straight run lies between
    for i in range(count):
        if ends[i] is None or corners[(i + 1) % count]:
            continue
        j, straight = (i + 1) % count, False
        while ends[j] is None and not corners[(j + 1) % count] and j != i:
            j, straight = (j + 1) % count, True
        if ends[j] is None or j == i or (straight and corners[j]):
            continue
        if ends[i][1] != ends[j][0]:
            if straight:
                optional += 1
            else:
                required += 1
    return required, optional, undecided


def check_inflections(drawing: Drawing, document: dict) -> tuple[list[str], dict]:
    inflections = document.get("inflections", [])
    points = [np.asarray(i["p"], float) for i in inflections] + [np.asarray(c["p"], float) for c in document.get("corners", [])]
    ring_index = identify_ring(drawing, points)
    ring = drawing.rings[ring_index]
    size = drawing.size
    problems = []
    for number, inflection in enumerate(inflections):
        at = foot(ring, inflection["p"], size)
        if at.distance > ON_CURVE * size:
            problems.append(f"inflection {number} at {fmt(inflection['p'])} is {at.distance / size:.2e} of the size off the curve")
    required, optional, undecided = expected_inflections(ring)
    if not required <= len(inflections) <= required + optional + 2 * undecided:
        problems.append(f"{len(inflections)} inflections reported, the curvature changes sign {required} times" + (f" (+ up to {optional} on straight runs)" if optional else "") + (f" (+ {undecided} undecided touches)" if undecided else ""))
    turns = [ring.joint_turn(i) for i in range(len(ring.pieces))]
    corners = sum(abs(t) > CORNER for t in turns)
    undecided_corners = sum(1e-10 < abs(t) <= 1e-6 for t in turns)
    # (The rings are closed as the contract closes drawn subpaths, `drawing.close_subpath`: a
    # closing gap within the written precision leaves no short piece, and no extra corner.)
    reported_corners = len(document.get("corners", []))
    if "corners" in document and not corners - undecided_corners <= reported_corners <= corners + undecided_corners:
        problems.append(f"{reported_corners} corners reported, the outline has {corners}")
    return problems, {"ring": ring_index, "inflections": len(inflections), "expected": [required, required + optional + 2 * undecided]}
