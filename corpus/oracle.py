"""The independent oracle: runs one curvekit command on one drawing and judges its answer.

Nothing here calls curvekit's code: the drawing is read by `drawing` (svgelements, ezdxf), the
region is shapely's polygon of its densely flattened outlines, offsets are compared with GEOS's
`buffer`, distances and radii with distances to the flattened boundary, antipodal pairs and
inflections with the exact pieces' derivatives. Each (file, command) ends in one outcome:

    answered          exit 0 and every check holds (certified or not)
    refused           exit 2 on an input the oracle also finds invalid, naming the true cause
    refused-valid     exit 2 on an input the contract says must be answered
    refused-wrong-cause  exit 2 on an invalid input, naming some other cause
    wrong-certified   exit 0, certified, and a check fails (the worst)
    wrong-uncertified exit 0, not certified, and a check fails
    crash             any other exit status, a panic, or output that is not the promised JSON
    timeout           no answer within the time limit
"""

from __future__ import annotations

import json
import math
import re
import subprocess
import time
from dataclasses import dataclass, field

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon

from drawing import FLATTEN, Drawing
from geometry import Bezier, EllipticArc, Line, Nurbs, Piece, Ring, curvature_numerator

CHORD = 1e-3  # curvekit's default --chord-tol, relative to the size
TIMEOUT = 60.0
ANGLE = 1e-4  # a pair's segment must lie along both normals within this angle (radians)
ON_CURVE = 1e-6  # a reported point must lie this close to the curve (relative to the size)
CORNER = 1e-7  # joints turning more than this are corners; 1e-10 .. 1e-6 is left undecided

CAUSE_WORDS = {
    "open": ("open", "gap", "not closed", "does not close", "closed curve", "no closed outline"),
    "cross": ("cross", "intersect", "meet", "touch", "overlap", "turns back"),
    "empty": ("no usable", "empty", "no geometry", "nothing", "no profile", "no curve"),
    "degenerate": ("area", "degenerate", "zero", "back", "cusp", "cross"),
    "branch": ("branch", "meet", "more than"),
    "fit": ("fit",),
}


@dataclass
class Outcome:
    file: str
    command: str
    args: list[str]
    status: str
    certified: bool | None = None
    message: str = ""
    problems: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)  # contract details short of a wrong answer
    wall: float = 0.0
    figures: dict = field(default_factory=dict)


@dataclass
class Answer:
    code: int | None  # None: timed out
    document: dict | None
    stderr: str
    wall: float


def run_tool(binary: str, args: list[str], timeout: float = TIMEOUT) -> Answer:
    start = time.monotonic()
    try:
        done = subprocess.run([binary, *args], capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return Answer(None, None, "", time.monotonic() - start)
    wall = time.monotonic() - start
    document = None
    if done.returncode == 0:
        try:
            document = json.loads(done.stdout)
        except json.JSONDecodeError:
            document = None
    return Answer(done.returncode, document, done.stderr.strip(), wall)


def message_pattern(message: str) -> str:
    """A refusal's message without its file name and numbers, to group refusals by kind."""
    text = re.sub(r"^curvekit: [^:]*: ", "", message.splitlines()[0] if message else "")
    text = re.sub(r"-?\d+(\.\d+)?(e-?\d+)?", "N", text)
    return text[:110]


# ----------------------------------------------------------------------------------------------
# Distances to a boundary


class Boundary:
    """Nearest distances to the flattened boundary of a polygonal set, through an STRtree of its
    segments (a point-to-linestring distance is linear in the segments)."""

    def __init__(self, geometry):
        rings = []
        for polygon in getattr(geometry, "geoms", [geometry]):
            if polygon.is_empty:
                continue
            rings.append(np.asarray(polygon.exterior.coords))
            rings.extend(np.asarray(r.coords) for r in polygon.interiors)
        segments = np.concatenate([np.stack([r[:-1], r[1:]], axis=1) for r in rings]) if rings else np.zeros((0, 2, 2))
        self.segments = shapely.linestrings(segments) if len(segments) else np.array([])
        self.tree = shapely.STRtree(self.segments)
        self.empty = len(segments) == 0

    def distance(self, points: np.ndarray) -> np.ndarray:
        if self.empty:
            return np.full(len(points), np.inf)
        _, distances = self.tree.query_nearest(shapely.points(points), return_distance=True, all_matches=False)
        return distances


# ----------------------------------------------------------------------------------------------
# Medial axis


def check_medial(drawing: Drawing, document: dict, parts: list[int], size: float) -> tuple[list[str], dict]:
    """Vertices inside, radii equal to the distance to the boundary, one component per part and
    one independent cycle per hole, degrees matching the node kinds, and the disks covering the part."""
    problems: list[str] = []
    nodes = {node["id"]: node for node in document.get("nodes", [])}
    edges = document.get("edges", [])
    polygons = [drawing.part_polygons[k] for k in parts]
    region = MultiPolygon(polygons)
    boundary = Boundary(region)
    vertices = [np.asarray(n["xy"], float) for n in nodes.values()]
    radii = [float(n["radius"]) for n in nodes.values()]
    for edge in edges:
        vertices.extend(np.asarray(edge["xy"], float))
        radii.extend(float(r) for r in edge["radius"])
    vertices = np.array(vertices).reshape(-1, 2)
    radii = np.array(radii)
    figures = {"vertices": len(vertices)}
    if len(vertices) == 0:
        return ["no medial axis at all"], figures
    distance = boundary.distance(vertices)
    outside = ~shapely.contains_xy(region, vertices[:, 0], vertices[:, 1]) & (distance > CHORD * size)
    if outside.any():
        i = int(np.argmax(outside))
        problems.append(f"{int(outside.sum())} axis vertices outside the region, e.g. {fmt(vertices[i])} at {distance[i] / size:.2e} of the size")
    error = np.abs(radii - distance)
    figures["radius_error"] = float(error.max() / size)
    if error.max() > CHORD * size:
        i = int(np.argmax(error))
        problems.append(f"radius {radii[i]:.6g} at {fmt(vertices[i])} but the distance to the boundary is {distance[i]:.6g} ({error[i] / size:.2e} of the size)")
    problems += check_medial_graph(drawing, nodes, edges, parts, polygons, vertices)
    problems += check_coverage(nodes, edges, polygons, size)
    return problems, figures


def check_medial_graph(drawing, nodes, edges, parts, polygons, vertices) -> list[str]:
    problems = []
    parent = {i: i for i in nodes}

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    degree = {i: 0 for i in nodes}
    for edge in edges:
        a, b = edge["from"], edge["to"]
        if a not in nodes or b not in nodes:
            problems.append(f"an edge names a node that is not listed ({a} -> {b})")
            continue
        degree[a] += 1
        degree[b] += 1
        parent[find(a)] = find(b)
    for i, node in nodes.items():
        kind, d = node.get("kind"), degree[i]
        if (kind == "junction" and d < 3) or (kind in ("end", "corner") and d > 1) or (kind == "joint" and d != 2):
            problems.append(f"node {i} of kind {kind} has degree {d}")
    components: dict[int, list[int]] = {}
    for i in nodes:
        components.setdefault(find(i), []).append(i)
    # each component belongs to the part holding its first node
    by_part: dict[int, list[int]] = {k: [] for k in range(len(parts))}
    for root, members in components.items():
        xy = np.asarray(nodes[members[0]]["xy"], float)
        owner = int(np.argmin([p.distance(shapely.Point(xy)) for p in polygons]))
        by_part[owner].append(root)
    for k, roots in by_part.items():
        holes = len(drawing.parts[parts[k]][1])
        if len(roots) != 1:
            problems.append(f"part {parts[k]} (outer + {holes} holes) has {len(roots)} axis components, not 1")
            continue
        members = set(components[roots[0]])
        count_edges = sum(1 for e in edges if e["from"] in members)
        cycles = count_edges - len(members) + 1
        if cycles != holes:
            problems.append(f"part {parts[k]} has {holes} holes but its axis has {cycles} independent cycles")
    return problems


def check_coverage(nodes, edges, polygons, size) -> list[str]:
    """The inscribed disks along the axis cover the region (a missing branch leaves a lobe bare)."""
    centres, radii = [], []
    step = 2e-3 * size
    for node in nodes.values():
        centres.append(node["xy"])
        radii.append(node["radius"])
    for edge in edges:
        xy = np.asarray(edge["xy"], float)
        r = np.asarray(edge["radius"], float)
        for a, b, ra, rb in zip(xy[:-1], xy[1:], r[:-1], r[1:]):
            count = max(1, int(math.ceil(np.hypot(*(b - a)) / step)))
            s = np.linspace(0.0, 1.0, count + 1)[:, None]
            centres.extend(a * (1 - s) + b * s)
            radii.extend((ra * (1 - s) + rb * s)[:, 0])
    centres = np.asarray(centres, float).reshape(-1, 2)
    radii = np.asarray(radii, float)
    tests = []
    for polygon in polygons:
        for ring in [polygon.exterior, *polygon.interiors]:
            coords = np.asarray(ring.coords)
            tests.append(coords[:: max(1, len(coords) // 1500)])
        x0, y0, x1, y1 = polygon.bounds
        gx, gy = np.meshgrid(np.linspace(x0, x1, 50), np.linspace(y0, y1, 50))
        grid = np.column_stack([gx.ravel(), gy.ravel()])
        tests.append(grid[shapely.contains_xy(polygon, grid[:, 0], grid[:, 1])])
    tests = np.concatenate(tests)
    worst, where = -np.inf, None
    for chunk in range(0, len(tests), 400):
        block = tests[chunk:chunk + 400]
        gap = np.min(np.hypot(block[:, None, 0] - centres[None, :, 0], block[:, None, 1] - centres[None, :, 1]) - radii[None, :], axis=1)
        i = int(np.argmax(gap))
        if gap[i] > worst:
            worst, where = gap[i], block[i]
    if worst > 3 * CHORD * size:
        return [f"the axis's disks leave {fmt(where)} uncovered by {worst / size:.2e} of the size (a missing branch)"]
    return []


# ----------------------------------------------------------------------------------------------
# Offsets


def profile_pieces(loop: dict) -> list[Piece]:
    """A profile document's segments as exact pieces (arcs: centre + r (cos, sin) from start to end)."""
    pieces = []
    for segment in loop["segments"]:
        kind = segment["kind"]
        if kind == "line":
            pieces.append(Line(segment["from"], segment["to"]))
        elif kind == "arc":
            r = segment["r"]
            pieces.append(EllipticArc(segment["center"], (r, 0.0), (0.0, r), segment["start"], segment["end"]))
        elif kind == "bezier":
            if segment.get("weights"):
                raise ValueError("rational bezier in an offset loop")
            pieces.append(Bezier(segment["points"]))
        elif kind == "bspline":
            points = segment["points"]
            degree = segment["degree"]
            knots = segment.get("knots") or clamped_uniform(len(points), degree)
            pieces.append(Nurbs(degree, knots, points, segment.get("weights")))
        else:
            raise ValueError(f"unknown segment kind {kind!r} in an offset loop")
    return pieces


def clamped_uniform(count: int, degree: int) -> list[float]:
    inner = count - degree - 1
    return [0.0] * (degree + 1) + [(i + 1) / (inner + 1) for i in range(inner)] + [1.0] * (degree + 1)


def ring_count(geometry) -> tuple[int, int]:
    """(outer rings, holes) of a polygonal result of buffer."""
    polygons = [g for g in getattr(geometry, "geoms", [geometry]) if not g.is_empty and g.area > 0]
    return len(polygons), sum(len(p.interiors) for p in polygons)


def inward(region, distance: float):
    return region.buffer(-distance, quad_segs=64)


def check_offsets(drawing: Drawing, document: dict, parts: list[int], size: float) -> tuple[list[str], dict]:
    """Per distance: every loop point at the distance (within the chord tolerance) and inside; as
    many loops as buffer's rings; the loops and buffer's boundary within the tolerance of each
    other (both ways); outer loops counterclockwise, holes clockwise."""
    problems = []
    region = MultiPolygon([drawing.part_polygons[k] for k in parts])
    boundary = Boundary(region)
    slack = CHORD * size + 3 * FLATTEN * size
    flat = FLATTEN * size
    figures = {"distances": 0, "loops": 0, "hausdorff": 0.0}
    for offset in document.get("offsets", []):
        d = float(offset["distance"])
        loops = []
        for index, loop in enumerate(offset.get("loops", [])):
            pieces = profile_pieces(loop)
            gaps = [np.hypot(*(a.end - b.start)) for a, b in zip(pieces, pieces[1:] + pieces[:1])]
            if max(gaps) > 1e-6 * size:
                problems.append(f"d={d:g}: loop {index} is not closed (a gap of {max(gaps) / size:.2e} of the size)")
            loops.append(Ring(pieces, f"loop {index}").flatten(flat)[0])
        reference = inward(region, d)
        figures["distances"] += 1
        figures["loops"] += len(loops)
        outers, holes = ring_count(reference)
        window = [ring_count(inward(region, d + s)) for s in (-2 * CHORD * size, 2 * CHORD * size)]
        if all(w == (outers, holes) for w in window) and len(loops) != outers + holes:
            problems.append(f"d={d:g}: {len(loops)} loops, but the region offset by buffer has {outers + holes} rings ({outers} outer, {holes} holes)")
        if not loops:
            continue
        points = np.concatenate(loops)
        distance = boundary.distance(points)
        error = np.abs(distance - d)
        if error.max() > slack:
            i = int(np.argmax(error))
            problems.append(f"d={d:g}: loop point {fmt(points[i])} is {distance[i]:.6g} from the boundary ({error[i] / size:.2e} of the size off)")
        inside = shapely.contains_xy(region, points[:, 0], points[:, 1])
        if (~inside).any():
            i = int(np.argmin(inside))
            problems.append(f"d={d:g}: loop point {fmt(points[i])} lies outside the region")
        # Loops to buffer's boundary, and back from the boundary of buffer at a hair's breadth
        # more (the oracle's own error), so that a sliver whose inscribed radius reaches d only
        # within that error (a touching point, a bump that barely rises) is not required.
        margin = 3 * flat
        shrunk = inward(region, d + margin)
        if not reference.is_empty:
            to_reference = Boundary(reference).distance(points)
            ref_points = np.concatenate([np.zeros((0, 2))] + [np.asarray(r.coords) for g in getattr(shrunk, "geoms", [shrunk]) if not g.is_empty for r in [g.exterior, *g.interiors]])
            loop_boundary = Boundary(MultiPolygon([Polygon(p) for p in loops if len(p) >= 3]))
            from_reference = loop_boundary.distance(ref_points) - margin if len(ref_points) else np.zeros(1)
            hausdorff = max(float(to_reference.max()), float(from_reference.max()))
            figures["hausdorff"] = max(figures["hausdorff"], hausdorff / size)
            if hausdorff > slack + 1e-4 * d:
                where = ref_points[int(np.argmax(from_reference))] if from_reference.max() >= to_reference.max() else points[int(np.argmax(to_reference))]
                problems.append(f"d={d:g}: loops and buffer's boundary are {hausdorff / size:.2e} of the size apart near {fmt(where)}")
        problems += check_orientation(loops, d)
    return problems, figures


# ----------------------------------------------------------------------------------------------
# V-carving

VBIT_ANGLE = 60.0  # the included angle the corpus is carved with (degrees)
CUT_GRID = 240  # the swept cut is compared with the region on a grid this many points wide
DISK_SEGMENTS = 32  # quarter-circle segments of the oracle's disks (chord error 1.2e-3 of r)


def vcarve_depth(drawing: Drawing, parts: list[int]) -> float:
    """A depth limit that makes flat passes: half the widest inscribed disk (shapely's) of the
    parts, as the depth a bit of VBIT_ANGLE reaches it at."""
    widest = max(shapely.maximum_inscribed_circle(drawing.part_polygons[k], 1e-4 * drawing.size).length for k in parts)
    return float(f"{0.5 * widest / math.tan(math.radians(VBIT_ANGLE / 2)):.6g}")


def check_vcarve(drawing: Drawing, document: dict, parts: list[int], size: float) -> tuple[list[str], dict]:
    """Every path point over the medial axis (its bit's disk at the surface as wide as the
    distance to the boundary) and no deeper than the limit; every flat point at the limit's
    radius from the boundary; and the cut the bit sweeps at the surface (along each path step
    the hull of its end disks, along the flats disks of the limit's radius) equal to the points
    of the region within twice that radius of the boundary (by the distance to the boundary), on
    a grid, away from the lines between by the slack."""
    problems: list[str] = []
    region = MultiPolygon([drawing.part_polygons[k] for k in parts])
    boundary = Boundary(region)
    spread = math.tan(math.radians(float(document["angle"]) / 2))
    depth = document.get("max_depth")
    widest = float(depth) * spread if depth is not None else math.inf
    slack = 2 * CHORD * size + 3 * FLATTEN * size
    paths = [np.asarray(p["xyz"], float).reshape(-1, 3) for p in document.get("paths", [])]
    figures = {"paths": len(paths), "flats": len(document.get("flats", []))}
    if not paths and not document.get("flats"):
        return ["no tool path at all"], figures
    points = np.concatenate(paths) if paths else np.zeros((0, 3))
    radii = -points[:, 2] * spread
    if depth is not None and (points[:, 2] < -float(depth) * (1 + 1e-12)).any():
        problems.append(f"a path point deeper than the limit {depth}: {points[:, 2].min():.6g}")
    error = np.abs(radii - boundary.distance(points[:, :2])) if len(points) else np.zeros(1)
    figures["radius_error"] = float(error.max() / size)
    if error.max() > slack:
        i = int(np.argmax(error))
        problems.append(f"the bit at {fmt(points[i, :2])} cuts a disk of {radii[i]:.6g}, {error[i] / size:.2e} of the size off the distance to the boundary")
    cuts = []
    for path in paths:
        disks = shapely.buffer(shapely.points(path[:, :2]), -path[:, 2] * spread, quad_segs=DISK_SEGMENTS)
        if len(path) == 1:
            cuts.extend(disks)
        # (The step itself too: a disk of radius 0, where the path reaches a corner, is empty.)
        steps = shapely.linestrings(np.stack([path[:-1, :2], path[1:, :2]], axis=1)) if len(path) > 1 else []
        cuts.extend(shapely.convex_hull(shapely.union(shapely.union(disks[:-1], disks[1:]), steps)))
    for index, loop in enumerate(document.get("flats", [])):
        ring = Ring(profile_pieces(loop), f"flat {index}").flatten(FLATTEN * size)[0]
        distance = boundary.distance(ring)
        if np.abs(distance - widest).max() > slack:
            problems.append(f"flat {index} runs {np.abs(distance - widest).max() / size:.2e} of the size off the radius {widest:.6g}")
        cuts.append(shapely.LinearRing(ring).buffer(widest, quad_segs=DISK_SEGMENTS))
    cut = shapely.union_all(cuts)
    x0, y0, x1, y1 = region.bounds
    xs, ys = np.meshgrid(np.linspace(x0, x1, CUT_GRID), np.linspace(y0, y1, CUT_GRID))
    grid = np.stack([xs.ravel(), ys.ravel()], axis=1)
    inside = shapely.contains_xy(region, grid[:, 0], grid[:, 1])
    got = shapely.contains_xy(cut, grid[:, 0], grid[:, 1])
    # (To be cut: the points of the region within twice the limit's radius of the boundary;
    # to stay: the rest, and everything outside. Points within the slack of either line are
    # not judged. Only the points where the cut and the region disagree, or that the cut
    # may take too deep, are measured.)
    distance = np.full(len(grid), np.inf)
    asked = (inside != got) | (got & (2 * widest + slack < size))
    distance[asked] = boundary.distance(grid[asked])
    missed = inside & (distance > slack) & (distance < 2 * widest - slack) & ~got
    gouged = ((~inside & (distance > slack)) | (inside & (distance > 2 * widest + slack))) & got & asked
    figures["missed"] = int(missed.sum())
    figures["gouged"] = int(gouged.sum())
    if missed.any():
        problems.append(f"{int(missed.sum())} grid points of the region left uncut, e.g. {fmt(grid[int(np.argmax(missed))])}")
    if gouged.any():
        problems.append(f"{int(gouged.sum())} grid points cut that should stay, e.g. {fmt(grid[int(np.argmax(gouged))])}")
    return problems, figures


def check_orientation(loops: list[np.ndarray], d: float) -> list[str]:
    """A loop inside another loop of the offset is a hole: holes clockwise, outers counterclockwise."""
    problems = [f"d={d:g}: loop {i} flattens to {len(p)} points (no area)" for i, p in enumerate(loops) if len(p) < 3]
    loops = [p for p in loops if len(p) >= 3]
    polygons = [Polygon(p) for p in loops]
    for i, loop in enumerate(loops):
        depth = sum(1 for j, other in enumerate(polygons) if j != i and other.contains(shapely.Point(loop[0])))
        area = signed_area(loop)
        if depth % 2 == 0 and area < 0:
            problems.append(f"d={d:g}: outer loop {i} runs clockwise")
        if depth % 2 == 1 and area > 0:
            problems.append(f"d={d:g}: hole loop {i} runs counterclockwise")
    return problems


def signed_area(points: np.ndarray) -> float:
    x, y = points[:, 0], points[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def offset_distances(drawing: Drawing, parts: list[int]) -> list[float]:
    """2% of the size; a quarter, half and 0.8 of the largest inscribed radius; a distance where
    the region has split into the most pieces; and past the inscribed radius (nothing left)."""
    region = MultiPolygon([drawing.part_polygons[k] for k in parts])
    size = max(np.ptp(np.asarray(region.bounds).reshape(2, 2), axis=0))
    radius = max(float(shapely.maximum_inscribed_circle(p, 1e-4 * size).length) for p in region.geoms)
    chosen = [0.02 * size, 0.25 * radius, 0.5 * radius, 0.8 * radius, 1.1 * radius]
    scan = [(f, ring_count(inward(region, f * radius))[0]) for f in np.linspace(0.1, 0.95, 12)]
    most = max(scan, key=lambda item: item[1])
    if most[1] > scan[0][1]:
        chosen.append(most[0] * radius)
    return sorted({float(f"{d:.6g}") for d in chosen if d > 0})


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


def fmt(point) -> str:
    return "(" + ", ".join(f"{float(v):.6g}" for v in point) + ")"


# ----------------------------------------------------------------------------------------------
# One file, every command that applies


def judge_file(binary: str, path: str, expect: dict | None = None) -> list[Outcome]:
    """Every command that applies to the drawing, each judged; `expect` is the manifest's note
    for a DXF part (what the oracle's own reading must find, and what curvekit must report)."""
    from drawing import read

    expect = expect or {}
    try:
        drawing = read(path)
    except Exception as error:  # the oracle could not read it: said so, never blamed on curvekit
        return [Outcome(path, "read", [], "oracle-error", message=f"{type(error).__name__}: {error}")]
    outcomes = []
    if expect:
        mismatch = expectation_mismatch(drawing, expect)
        if mismatch:
            return [Outcome(path, "read", [], "oracle-error", message=mismatch)]
    part_of_pick: dict[int, int] = {}
    for command in ("medial", "offset", "vcarve", "antipodal", "inflections"):
        try:
            if command in ("medial", "offset", "vcarve"):
                outcomes += judge_region(binary, drawing, command, expect, part_of_pick)
            elif single_curve_applies(drawing):
                outcomes.append(judge_curve(binary, drawing, command, expect))
        except Exception as error:  # an oracle bug must not hide the other commands' outcomes
            outcomes.append(Outcome(path, command, [], "oracle-error", message=f"{type(error).__name__}: {error}"))
    return outcomes


def expectation_mismatch(drawing: Drawing, expect: dict) -> str:
    if not expect.get("valid", True):
        return "" if not drawing.valid or expect.get("ambiguous") else "the oracle reads as valid a part noted invalid"
    holes = sorted(len(h) for _, h in drawing.parts)
    if not drawing.valid or len(drawing.parts) != expect["parts"] or holes != sorted(expect["holes"]):
        return f"the oracle reads {len(drawing.parts)} parts with holes {holes} ({drawing.invalid[:1]}), the note says {expect['parts']} with {expect['holes']}"
    return ""


def single_curve_applies(drawing: Drawing) -> bool:
    """Antipodal pairs and inflections need profile 0 to be a simple closed curve: taken only where
    every chain is closed and none crosses itself, so that profile 0 is one of the oracle's rings."""
    closed = not any(gap > 1e-4 * drawing.size for _, gap in drawing.open_chains)
    return bool(drawing.rings) and closed and not drawing.self_crossing


def refusal_cause_named(message: str, causes: list[str]) -> bool:
    text = message.lower()
    return any(word in text for cause in causes for word in CAUSE_WORDS.get(cause, (cause,)))


def base_outcome(drawing: Drawing, command: str, args: list[str], answer: Answer) -> Outcome:
    outcome = Outcome(str(drawing.path), command, args, "", wall=answer.wall)
    if answer.code is None:
        outcome.status = "timeout"
    elif answer.code == 0 and answer.document is None:
        outcome.status, outcome.message = "crash", "exit 0 without a JSON document"
    elif answer.code not in (0, 2) or "panicked" in answer.stderr:
        outcome.status, outcome.message = "crash", f"exit {answer.code}: {answer.stderr[-400:]}"
    elif answer.code == 2:
        outcome.status, outcome.message = "refused", answer.stderr
        if len(answer.stderr.splitlines()) != 1:
            outcome.notes.append("the refusal is not one line on stderr")
    else:
        outcome.certified = bool(answer.document.get("certified"))
    return outcome


def judge_refusal(drawing: Drawing, outcome: Outcome, expect: dict) -> None:
    """A refusal is right when the input is invalid and its message names the oracle's cause (or
    the cause the manifest notes for a DXF part)."""
    causes = [entry.split(":")[0] for entry in drawing.invalid] + [expect.get("cause", "")] * bool(expect.get("cause"))
    if drawing.valid:
        near_open = [a for a in drawing.ambiguous if "near-closed" in a]
        if near_open and refusal_cause_named(outcome.message, ["open"]):
            return
        outcome.status = "refused-valid"
    elif not refusal_cause_named(outcome.message, causes):
        outcome.status = "refused-wrong-cause"
        outcome.problems.append(f"the oracle finds: {drawing.invalid[0]}")


def contract_notes(drawing: Drawing, document: dict, expect: dict, outcome: Outcome) -> None:
    """What a result read from a drawing must carry beside the geometry."""
    if "skipped" not in document:
        outcome.notes.append("no 'skipped' list in a result read from a drawing")
    else:
        listed = {item.get("type"): item.get("count") for item in document["skipped"]}
        for kind, count in (expect.get("skipped") or {}).items():
            if listed.get(kind) != count:
                outcome.notes.append(f"'skipped' lists {listed.get(kind)} {kind}, the drawing has {count}")
    accepted = {"mm": ("mm",), "in": ("in", "inch", "inches")}.get(expect.get("units"), (expect.get("units"),))
    if expect.get("units") and document.get("units") not in accepted:
        outcome.notes.append(f"units {document.get('units')!r}, the drawing says {expect['units']!r}")
    if (expect.get("uncertified") or drawing.outline_skipped) and outcome.certified:
        outcome.problems.append(f"certified although an outline was skipped: {(drawing.outline_skipped or ['?'])[0]}")


def finish(outcome: Outcome, problems: list[str], figures: dict) -> Outcome:
    outcome.problems += problems
    outcome.figures.update(figures)
    if outcome.problems:
        outcome.status = "wrong-certified" if outcome.certified else "wrong-uncertified"
    else:
        outcome.status = "answered"
    return outcome


def judge_region(binary, drawing: Drawing, command: str, expect: dict, part_of_pick: dict[int, int]) -> list[Outcome]:
    """The whole drawing as one input (multi-part as the contract says); where curvekit asks for
    --pick, each part on its own as well, so that its geometry is still judged."""
    everything = list(range(len(drawing.parts)))
    extra = []
    if command == "offset":
        distances = offset_distances(drawing, everything) if drawing.valid else [float(f"{0.05 * drawing.size:.6g}") or 1.0]
        extra = ["--distances", ",".join(f"{d:g}" for d in distances)]
    if command == "vcarve":
        extra = vcarve_args(drawing, everything)
    args = [command, str(drawing.path), "--json", *extra]
    answer = run_tool(binary, args)
    outcome = base_outcome(drawing, command, args, answer)
    outcomes = [outcome]
    if outcome.status == "refused":
        judge_refusal(drawing, outcome, expect)
        if outcome.status == "refused-valid" and "--pick" in outcome.message and len(drawing.parts) > 1:
            for pick in range(len(drawing.parts)):
                outcomes.append(judge_pick(binary, drawing, command, expect, pick, part_of_pick))
    elif outcome.status == "" and not drawing.valid:
        outcome.status = "answered-invalid"
        outcome.problems.append(f"answered although {drawing.invalid[0] if drawing.invalid else 'the input holds no region'}")
    elif outcome.status == "":
        contract_notes(drawing, answer.document, expect, outcome)
        finish(outcome, *CHECKS[command](drawing, answer.document, everything, drawing.size))
    return outcomes


def vcarve_args(drawing: Drawing, parts: list[int]) -> list[str]:
    """The bit's angle, and a depth limit where the oracle reads a region (else none)."""
    depth = ["--max-depth", f"{vcarve_depth(drawing, parts):g}"] if drawing.valid else []
    return ["--angle", f"{VBIT_ANGLE:g}", *depth]


def judge_pick(binary, drawing: Drawing, command: str, expect: dict, pick: int, part_of_pick: dict[int, int]) -> Outcome:
    """One part of a multi-part drawing through --pick; which part curvekit took is read off its
    medial axis (the part holding most of its vertices), else off the offset loops."""
    args = [command, str(drawing.path), "--json", "--pick", str(pick)]
    part = part_of_pick.get(pick, pick)
    if command == "offset":
        distances = offset_distances(drawing, [part])
        args += ["--distances", ",".join(f"{d:g}" for d in distances)]
    if command == "vcarve":
        args += vcarve_args(drawing, [part])
    answer = run_tool(binary, args)
    outcome = base_outcome(drawing, f"{command} --pick", args, answer)
    outcome.figures["pick"] = pick
    if outcome.status == "refused":
        judge_refusal(drawing, outcome, expect)
        return outcome
    if outcome.status:
        return outcome
    document = answer.document
    points = [n["xy"] for n in document.get("nodes", [])] + [e["xy"][0] for e in document.get("edges", [])]
    points += [s.get("from") or s.get("center") for o in document.get("offsets", []) for loop in o.get("loops", []) for s in loop["segments"][:1]]
    points += [p["xyz"][0][:2] for p in document.get("paths", [])]
    if points and (command == "medial" or pick not in part_of_pick):
        votes = [int(np.argmin([p.distance(shapely.Point(xy)) for p in drawing.part_polygons])) for xy in points[:200] if xy is not None]
        part = max(set(votes), key=votes.count)
        part_of_pick[pick] = part
    outcome.figures["part"] = part
    polygon = drawing.part_polygons[part]
    size = float(max(np.ptp(np.asarray(polygon.bounds).reshape(2, 2), axis=0)))
    check = CHECKS[command]
    if command in ("offset", "vcarve") and part != part_of_pick.get(pick, part):
        outcome.notes.append(f"the {command} options were chosen for another part")
    contract_notes(drawing, document, expect, outcome)
    return finish(outcome, *check(drawing, document, [part], size))


CHECKS = {"medial": check_medial, "offset": check_offsets, "vcarve": check_vcarve}


def judge_curve(binary, drawing: Drawing, command: str, expect: dict) -> Outcome:
    """Antipodal pairs or inflections of profile 0 (--pick 0 where the drawing has several)."""
    several = len(drawing.rings) > 1 or drawing.outline_skipped  # curvekit may count a skipped outline
    args = [command, str(drawing.path), "--json"] + (["--pick", "0"] if several else [])
    answer = run_tool(binary, args)
    outcome = base_outcome(drawing, command, args, answer)
    if outcome.status == "refused":
        outcome.status = "refused-valid"
        return outcome
    if outcome.status:
        return outcome
    contract_notes(drawing, answer.document, expect, outcome)
    check = check_antipodal if command == "antipodal" else check_inflections
    return finish(outcome, *check(drawing, answer.document))
