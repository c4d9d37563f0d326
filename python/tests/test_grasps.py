"""`curvekit.grasps`: the force-closure regions against what is known of simple shapes (an
ellipse's two axis pairs, a circle's one band), against an independent numpy check on a grid
(the slip angle from sampled points and tangents against membership in the region polylines,
away from their boundaries, as crates/grasp/tests/oracle.rs does in Rust), the list form
against one call at a time, and the options refused."""

from __future__ import annotations

import json
import math
import pickle

import numpy as np
import pytest

import curvekit
from conftest import FIXTURES, run_tool

# A best grasp at an antipodal pair needs no friction: zero up to the rounding of the angle
# between the normals and the chord (the library's pair is solved to the parameter tolerance).
ANTIPODAL_FRICTION = 1e-9
# The axis pairs' points, computed from parameters solved to 1e-12 of the domain.
AXIS_POINT = 1e-7
# Grid points per side of the square of pairs in the dense check.
GRID = 80
# The library's default chord tolerance (relative to the square's side), of which the dense
# check stays a few away from every reported boundary (as the Rust oracle does).
CHORD_TOL = 1e-3
MARGIN_CHORDS = 4.0
# Central differences for the tangents: the step, relative to the domain (the angle they give
# is off by about its square, far below the margin's angles).
TANGENT_STEP = 1e-6
# Random curves: the generator's seed and how many.
SEED = 20261127
MANY = 50


def star_spline(rng: np.random.Generator, name: str = "star") -> curvekit.Curve:
    """A periodic cubic B-spline on a random star-shaped polygon (as testkit's stars: angles
    jittered by 0.8 of their spacing, so in order; radii in [0.35, 1))."""
    n = int(rng.integers(6, 11))
    a, r = rng.random(n), rng.random(n)
    angle = 2 * np.pi * (np.arange(n) + 0.8 * (a - 0.5)) / n
    radius = 0.35 + 0.65 * r
    points = np.column_stack([radius * np.cos(angle), radius * np.sin(angle)])
    return curvekit.BSpline(points, periodic=True, name=name)


def pair_key(p: np.ndarray, q: np.ndarray) -> set:
    return {tuple(np.round(p, 6)), tuple(np.round(q, 6))}


def within(u: float, interval: np.ndarray, period: float) -> bool:
    """Whether `u` lies in `[lo, hi]` read modulo the period (an interval may run across the
    seam, its ends beyond the domain)."""
    lo, hi = interval
    return (u - lo) % period <= (hi - lo) + 1e-12


# ---- the dense check, in numpy only ----


def wrapped(c: curvekit.Curve, u: np.ndarray) -> np.ndarray:
    a, b = c.domain
    return a + np.mod(u - a, b - a)


def points_and_tangents(c: curvekit.Curve, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    a, b = c.domain
    h = TANGENT_STEP * (b - a)
    p = c.evaluate(wrapped(c, u))
    tangent = (c.evaluate(wrapped(c, u + h)) - c.evaluate(wrapped(c, u - h))) / (2 * h)
    return p, tangent


def orientation(c: curvekit.Curve) -> float:
    a, b = c.domain
    p = c.evaluate(np.linspace(a, b, 400, endpoint=False))
    q = np.roll(p, -1, axis=0)
    return float(np.sign(np.sum(p[:, 0] * q[:, 1] - q[:, 0] * p[:, 1])))


def slip_angles(c: curvekit.Curve, s: np.ndarray, t: np.ndarray) -> np.ndarray:
    """The larger angle between a contact's inward normal and the chord to the other contact
    (inward: the left normal of a counterclockwise curve)."""
    o = orientation(c)
    ps, ts = points_and_tangents(c, s)
    pt, tt = points_and_tangents(c, t)
    d = pt - ps

    def angle(tan: np.ndarray, chord: np.ndarray) -> np.ndarray:
        normal = np.column_stack([-o * tan[:, 1], o * tan[:, 0]])
        along = np.abs(np.sum(tan * chord, axis=1))
        return np.arctan2(along, np.sum(normal * chord, axis=1))

    return np.maximum(angle(ts, d), angle(tt, -d))


def winding(polyline: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """The winding number of a closed polyline about each point (Sunday's crossing rule)."""
    a = polyline
    b = np.roll(polyline, -1, axis=0)
    x, y = pts[:, :1], pts[:, 1:]
    ax, ay, bx, by = a[:, 0], a[:, 1], b[:, 0], b[:, 1]
    side = (bx - ax) * (y - ay) - (x - ax) * (by - ay)
    up = (ay <= y) & (by > y) & (side > 0)
    down = (ay > y) & (by <= y) & (side < 0)
    return up.sum(axis=1) - down.sum(axis=1)


def distance_to(polyline: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """The distance from each point to a closed polyline."""
    a = polyline
    b = np.roll(polyline, -1, axis=0)
    ab = b - a
    length2 = np.maximum(np.sum(ab * ab, axis=1), 1e-300)
    ap = pts[:, None, :] - a[None, :, :]
    h = np.clip(np.sum(ap * ab[None], axis=2) / length2, 0.0, 1.0)
    foot = a[None] + h[..., None] * ab[None]
    return np.min(np.linalg.norm(pts[:, None, :] - foot, axis=2), axis=1)


def held(g: curvekit.Grasps, pts: np.ndarray) -> np.ndarray:
    inside = np.zeros(len(pts), dtype=bool)
    for r in g.regions:
        ins = np.zeros(len(pts), dtype=bool)
        for part in r.parts:
            ins |= winding(part, pts) != 0
        for hole in r.holes:
            ins &= winding(hole, pts) == 0
        inside |= ins
    return inside


def polylines(g: curvekit.Grasps) -> list[np.ndarray]:
    return [p for r in g.regions for p in [*r.parts, *r.holes]]


def dense_check(c: curvekit.Curve, friction: float) -> int:
    """Asserts the regions against the slip angle on the grid; returns the pairs decided."""
    g = curvekit.grasps(c, friction)
    assert g.complete
    a, b = c.domain
    for r in g.regions:
        # A best grasp is a pair of the triangle s < t of the domain (its contact intervals
        # alone may run across the seam).
        assert a <= r.best.s <= r.best.t <= b, r.best
    i, j = np.triu_indices(GRID, k=1)
    s = a + (b - a) * (i + 0.31) / GRID
    t = a + (b - a) * (j + 0.37) / GRID
    pts = np.column_stack([s, t])
    margin = MARGIN_CHORDS * CHORD_TOL * math.sqrt(2) * (b - a)
    far = np.ones(len(pts), dtype=bool)
    for line in polylines(g):
        far &= distance_to(line, pts) > margin
    force_closure = slip_angles(c, s, t) <= math.atan(friction)
    inside = held(g, pts)
    wrong = np.flatnonzero(far & (force_closure != inside))
    assert len(wrong) == 0, (
        f"{len(wrong)} pairs disagree, the first {pts[wrong[0]]}: slip angle "
        f"{slip_angles(c, s[wrong[:1]], t[wrong[:1]])[0]} against {math.atan(friction)}"
    )
    return int(far.sum())


# ---- the tests ----


def test_an_ellipse_has_two_regions_at_its_axis_pairs() -> None:
    g = curvekit.grasps(curvekit.Ellipse(3.0, 2.0), 0.3)
    assert g.certified and g.complete and g.reason is None
    assert len(g) == len(g.regions) == 2
    found = [pair_key(r.best.p, r.best.q) for r in g.regions]
    for axis in [{(3.0, 0.0), (-3.0, 0.0)}, {(0.0, 2.0), (0.0, -2.0)}]:
        assert axis in found, found
    for r in g.regions:
        assert r.certified
        assert r.best.min_friction < ANTIPODAL_FRICTION
        assert r.best.s < r.best.t
        # The points are the curve's at the parameters.
        e = curvekit.Ellipse(3.0, 2.0)
        at = e.evaluate(np.array([r.best.s, r.best.t]))
        assert np.allclose(at, [r.best.p, r.best.q], atol=AXIS_POINT)
        assert r.boundary.ndim == 2 and r.boundary.shape[1] == 2
        assert np.array_equal(r.parts[0], r.boundary)


def test_a_circle_has_one_region() -> None:
    g = curvekit.grasps(curvekit.Circle(1.0), 0.2)
    assert g.complete and len(g.regions) == 1
    best = g.regions[0].best
    assert best.min_friction < ANTIPODAL_FRICTION
    assert np.allclose(best.p, -best.q, atol=AXIS_POINT)


def test_the_contact_stretches_are_force_closure() -> None:
    # (The contact region is the largest product of stretches in its region; it need not
    # hold the most robust grasp, which may lie near the region's edge.)
    rng = np.random.default_rng(SEED)
    curves = [curvekit.Ellipse(3.0, 2.0), curvekit.Limacon(4.0, 2.5)] + [
        star_spline(rng) for _ in range(3)
    ]
    friction = 0.4
    checked = 0
    for c in curves:
        a, b = c.domain
        period = b - a
        for r in curvekit.grasps(c, friction).regions:
            if r.contact is None:
                continue
            k = r.contact
            assert k.s.shape == k.t.shape == (2,) and k.p.shape == k.q.shape == (2, 2)
            assert np.allclose(c.evaluate(wrapped(c, k.s)), k.p, atol=AXIS_POINT)
            # Every pair of the rectangle is force closure: on a 9 × 9 grid of it.
            s, t = np.meshgrid(np.linspace(*k.s, 9), np.linspace(*k.t, 9))
            angles = slip_angles(c, s.ravel(), t.ravel())
            assert np.all(angles <= math.atan(friction) + 1e-9), angles.max()
            checked += 1
    assert checked >= len(curves)


def test_a_list_answers_as_one_at_a_time_in_order() -> None:
    rng = np.random.default_rng(SEED + 1)
    curves = [star_spline(rng, f"star {k}") for k in range(MANY)]
    many = curvekit.grasps(curves, 0.3)
    assert len(many) == MANY
    assert many == [curvekit.grasps(c, 0.3) for c in curves]
    # Tuples, prepared curves, dicts and paths, as the other commands take them.
    ellipse = FIXTURES / "ellipse.json"
    mixed = (curvekit.prepare(curves[0]), {"kind": "circle", "r": 1}, str(ellipse))
    assert curvekit.grasps(mixed, 0.3, max_width=5.0) == [
        curvekit.grasps(curves[0], 0.3, max_width=5.0),
        curvekit.grasps({"kind": "circle", "r": 1}, 0.3, max_width=5.0),
        curvekit.grasps(ellipse, 0.3, max_width=5.0),
    ]
    assert curvekit.grasps([], 0.3) == []


def test_one_bad_curve_of_a_list_is_named_by_its_place() -> None:
    pocket = curvekit.read(FIXTURES / "region-pocket.json")
    with pytest.raises(curvekit.InputError, match=r"^\[1\] .*region"):
        curvekit.grasps([curvekit.Ellipse(3.0, 2.0), pocket], 0.3)
    with pytest.raises(curvekit.InputError, match=r"^\[1\] .*open"):
        curvekit.grasps([curvekit.Ellipse(3.0, 2.0), curvekit.Line([0, 0], [1, 1])], 0.3)
    with pytest.raises(TypeError, match=r"^\[1\]: "):
        curvekit.grasps([curvekit.Ellipse(3.0, 2.0), 42], 0.3)


@pytest.mark.parametrize(
    ("options", "named"),
    [
        ({"friction": 0.0}, "friction"),
        ({"friction": -0.5}, "friction"),
        ({"friction": math.nan}, "friction"),
        ({"friction": math.inf}, "friction"),
        ({"friction": 0.3, "min_width": 0.0}, "min_width"),
        ({"friction": 0.3, "min_width": -1.0}, "min_width"),
        ({"friction": 0.3, "max_width": math.inf}, "max_width"),
        ({"friction": 0.3, "min_width": 2.0, "max_width": 2.0}, "max_width"),
        ({"friction": 0.3, "min_width": 3.0, "max_width": 2.0}, "max_width"),
    ],
)
def test_bad_options_raise_naming_the_option(options: dict, named: str) -> None:
    e = curvekit.Ellipse(3.0, 2.0)
    with pytest.raises(ValueError, match=rf"^{named}: ") as raised:
        curvekit.grasps(e, **options)
    assert not isinstance(raised.value, curvekit.InputError)
    with pytest.raises(ValueError, match=rf"^\[0\] --{named.replace('_', '-')}: "):
        curvekit.grasps([e, e], **options)


def test_widths_leave_out_pairs() -> None:
    # The ellipse's axes are 6 and 4 long: an opening of at most 5 keeps the minor one only.
    g = curvekit.grasps(curvekit.Ellipse(3.0, 2.0), 0.3, max_width=5.0)
    assert g.max_width == 5.0 and g.min_width is None
    assert [pair_key(r.best.p, r.best.q) for r in g.regions] == [{(0.0, 2.0), (0.0, -2.0)}]
    assert g.to_dict()["max_width"] == 5.0 and "min_width" not in g.to_dict()


def test_regions_match_the_dense_check_on_random_curves() -> None:
    rng = np.random.default_rng(SEED + 2)
    for friction in (0.05, 0.15, 0.5, 1.0):
        decided = dense_check(star_spline(rng), friction)
        # (Most of the grid is decided: the margin is a thin band round the boundaries.)
        assert decided > 0.8 * GRID * (GRID - 1) / 2


def test_the_document_is_the_librarys_with_the_curve() -> None:
    c = curvekit.Ellipse(3.0, 2.0)
    g = curvekit.grasps(c, 0.3)
    doc = g.to_dict()
    assert doc == json.loads(g.to_json())
    assert {"friction", "regions", "certified", "complete", "curve"} <= set(doc)
    assert doc["friction"] == 0.3 and doc["certified"] is True and "reason" not in doc
    assert len(doc["regions"]) == 2
    for r, d in zip(g.regions, doc["regions"]):
        assert np.array_equal(r.boundary, np.array(d["boundary"]))
        assert d["best"]["s"] == r.best.s and d["best"]["min_friction"] == r.best.min_friction
        assert d["contact"]["s"] == r.contact.s.tolist()
        assert d["certified"] is r.certified
    assert doc["curve"] == curvekit.antipodal(c).to_dict()["curve"]
    back = pickle.loads(pickle.dumps(g))
    assert back == g and back.to_dict() == doc


def test_the_document_is_the_tools_where_the_tool_has_the_command() -> None:
    path = str(FIXTURES / "ellipse.json")
    done = run_tool("grasps", path, "--friction", "0.3", "--json")
    if done.returncode != 0 and "grasps" in done.stderr:
        pytest.skip("the tool has no grasps command yet")
    assert done.returncode == 0, done.stderr
    assert curvekit.grasps(path, 0.3).to_dict() == json.loads(done.stdout)


def test_stretches_spared_toward_a_reflex_corner_are_the_tools() -> None:
    # Ionicons' volume icon: a region's least friction falls toward a reflex corner (which
    # takes no part); its best grasp is proven but for pairs with a finger beside it.
    path = str(FIXTURES / "corpus" / "icons" / "ionicons-filled" / "volume-high.svg")
    g = curvekit.grasps(curvekit.read(path, pick=0), 0.3)
    assert g.certified
    spared = [r.best.toward for r in g.regions if len(r.best.toward)]
    assert spared and all(t.shape[1] == 2 and np.all(t[:, 0] < t[:, 1]) for t in spared)
    assert all(r.best.toward.shape == (0, 2) for r in g.regions if not len(r.best.toward))
    done = run_tool("grasps", path, "--friction", "0.3", "--json", "--pick", "0")
    assert done.returncode == 0, done.stderr
    tool = [r["best"].get("toward", []) for r in json.loads(done.stdout)["regions"]]
    assert [r.best.toward.tolist() for r in g.regions] == tool


POLYGONS = {
    "square": [[0, 0], [2, 0], [2, 2], [0, 2]],
    "rectangle": [[0, 0], [3, 0], [3, 1], [0, 1]],
    "pentagon": [[0, 0], [2, 0], [3, 1.5], [1, 3], [-1, 1.5]],
    "triangle": [[0, 0], [4, 0], [1, 3]],
}


@pytest.mark.parametrize(
    ("name", "friction"),
    [
        ("square", 0.3),
        ("rectangle", 0.3),
        ("pentagon", 0.3),
        ("pentagon", 1.0),
        ("triangle", 0.3),
        ("triangle", 1.0),
        # Right angles at μ = 1: the pinch grasps of a corner are the line of its two sides'
        # mirror pairs, a set with no inside (the result says so and certifies nothing).
        ("square", 1.0),
        ("rectangle", 1.0),
        ("triangle", 2.0),
        ("pentagon", 3.0),
    ],
)
def test_polygons_match_the_dense_check(name: str, friction: float) -> None:
    # (The grid keeps 0.31 of a step from every corner's parameter: the tangents' differences
    # never straddle a corner.)
    c = curvekit.Polygon(POLYGONS[name])
    assert dense_check(c, friction) > 0.8 * GRID * (GRID - 1) / 2


def test_a_right_angle_at_friction_one_certifies_nothing() -> None:
    g = curvekit.grasps(curvekit.Polygon(POLYGONS["square"]), 1.0)
    assert g.regions and not any(r.certified for r in g.regions)
    assert not g.certified and g.reason


def test_profiles_with_corners_are_taken() -> None:
    square = curvekit.Polygon(POLYGONS["square"])
    g = curvekit.grasps(square, 0.3)
    assert g.complete and g.regions
    for r in g.regions:
        assert r.boundary.ndim == 2 and r.boundary.shape[1] == 2 and len(r.boundary) >= 2
        assert r.best.s < r.best.t or r.contact is None
    cam = curvekit.grasps(curvekit.read(FIXTURES / "profile-cam.json"), 0.3)
    assert cam.complete and cam.regions


def test_the_result_reads_as_it_is() -> None:
    g = curvekit.grasps(curvekit.Ellipse(3.0, 2.0), 0.3)
    assert repr(g).startswith("Grasps(2 regions")
    r = g.regions[0]
    assert repr(r).startswith("GraspRegion(") and repr(r.best).startswith("BestGrasp(")
    assert repr(r.contact).startswith("ContactRegion(")
    assert isinstance(r, curvekit.GraspRegion) and isinstance(r.best, curvekit.BestGrasp)


# ---- what the grasp crate does not do yet (strict: these fail loudly once it does) ----

# How near a reported polyline a pair on a 1-D region (a finger at a corner) must lie.
ON_STRETCH = 1e-9


def on_some_region(g: curvekit.Grasps, pair: list[float]) -> bool:
    pts = np.array([pair])
    return bool(held(g, pts)[0]) or any(
        distance_to(line, pts)[0] <= ON_STRETCH for line in polylines(g)
    )


@pytest.mark.xfail(strict=True, reason="grasp crate: a corner's stretch that ends at a corner-corner pair is lost")
def test_a_square_holds_the_stretches_of_a_finger_at_a_corner() -> None:
    # The square [0, 2]² counterclockwise from (0, 0): corner (0, 0) at parameter 0, the right
    # side (2, y) at 1 + y / 2. The chord from (0, 0) to (2, y) lies in the corner's fan of
    # inward normals ([0°, 90°]) and within atan μ of the right side's inward normal for
    # y ≤ 2μ: force closure by the contract, the stretch of pairs (0, t), t in [1, 1 + μ].
    friction = 0.3
    square = curvekit.Polygon(POLYGONS["square"])
    # The pair (0, 1.15): y = 0.3, the chord atan(0.15) from the side's normal.
    assert slip_angles(square, np.array([1.15]), np.array([0.0]))[0] < math.atan(friction)
    assert on_some_region(curvekit.grasps(square, friction), [0.0, 1.15])


@pytest.mark.xfail(strict=True, reason="grasp crate: a region bounded by corner lines gets no contact region and is not resolved")
def test_a_region_of_whole_sides_has_its_contact_region() -> None:
    # The rectangle [0, 3] × [0, 1], μ = 1: every pair of the right side (parameters [1, 2])
    # and the left side ([3, 4]) is force closure (|Δy| ≤ 1 ≤ 3μ), checked here on a grid.
    rect = curvekit.Polygon(POLYGONS["rectangle"])
    s, t = np.meshgrid(np.linspace(1.05, 1.95, 7), np.linspace(3.05, 3.95, 7))
    assert np.all(slip_angles(rect, s.ravel(), t.ravel()) < math.atan(1.0))
    g = curvekit.grasps(rect, 1.0)
    holding = [r for r in g.regions if held_by(r, [1.5, 3.5])]
    assert len(holding) == 1 and holding[0].contact is not None
    assert g.certified, g.reason


def held_by(r: curvekit.GraspRegion, pair: list[float]) -> bool:
    pts = np.array([pair])
    return any(winding(part, pts)[0] != 0 for part in r.parts)
