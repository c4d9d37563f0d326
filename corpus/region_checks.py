"""The oracle's checks of the region commands' answers: the medial axis (vertices inside, radii
equal to the distance to the boundary, the graph's shape, the disks covering the region), offsets
(distances, loop counts and Hausdorff distance against GEOS's `buffer`, closure, orientation) and
the v-carve's swept cut. Nothing here calls curvekit's code.
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon

from drawing import FLATTEN, Drawing
from geometry import Bezier, EllipticArc, Line, Nurbs, Piece, Ring

CHORD = 1e-3  # curvekit's default --chord-tol, relative to the size


def fmt(point) -> str:
    return "(" + ", ".join(f"{float(v):.6g}" for v in point) + ")"


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
