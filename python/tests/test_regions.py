"""Regions in the shapely style: `Region(outer, holes)` and `.outer`, `.holes`, `.parts`;
`Profile`; every curve's document (`to_dict()`); GeoJSON (`__geo_interface__`) of curves and of
offsets, judged by shapely (GEOS); offset loops grouped into regions."""

from __future__ import annotations

import json
import math
import os
import pickle

import numpy as np
import pytest

import curvekit
from conftest import FIXTURES

try:
    import shapely
    from shapely.geometry import Polygon as ShapelyPolygon
    from shapely.geometry import shape
except ImportError as missing:
    if os.environ.get("CI"):
        raise
    pytest.skip(f"the region tests need {missing.name}", allow_module_level=True)

POCKET = FIXTURES / "region-pocket.json"
GLYPH = FIXTURES / "corpus" / "glyphs" / "roboto" / "0061-a.svg"
TOL = 1e-3  # GeoJSON's flattening, relative to the size


def test_a_region_is_made_and_taken_apart() -> None:
    pocket = curvekit.read(POCKET)
    made = curvekit.Region(pocket.outer, pocket.holes, name="made")
    assert made.kind == "region" and len(made.holes) == 1
    assert made.outer.to_dict() == pocket.outer.to_dict()
    assert [h.to_dict() for h in made.holes] == [h.to_dict() for h in pocket.holes]
    assert [p.to_dict()["outer"] for p in made.parts] == [made.outer.to_dict()]
    # The same region: the same axis, node for node.
    assert np.allclose(curvekit.medial(made).nodes, curvekit.medial(pocket).nodes)
    assert pickle.loads(pickle.dumps(made)).to_dict() == made.to_dict()
    # A closed curve is a region of one boundary; an open one has none.
    circle = curvekit.Circle(2.0)
    assert circle.outer.kind == "profile" and circle.holes == [] and len(circle.parts) == 1
    with pytest.raises(curvekit.InputError):
        curvekit.Line([0, 0], [1, 0]).outer


def test_a_profile_is_made_of_segments() -> None:
    sides = [curvekit.Line([0, 0], [4, 0]), curvekit.Arc([4, 1], 1, -math.pi / 2, math.pi / 2), {"kind": "line", "from": [4, 2], "to": [0, 2]}, curvekit.Line([0, 2], [0, 0])]
    slot = curvekit.Profile(sides)
    assert slot.kind == "profile" and slot.closed
    assert curvekit.medial(slot).certified
    with pytest.raises(TypeError, match=r"segments\[1\]"):
        curvekit.Profile([sides[0], 3])


def test_documents_read_back_as_the_same_curve() -> None:
    pocket = curvekit.read(POCKET)
    assert pocket.to_dict() == json.loads(POCKET.read_text())
    glyph = curvekit.read(GLYPH)
    doc = glyph.to_dict()
    assert doc["kind"] == "region"
    again = curvekit.from_dict(doc, "again")
    assert np.allclose(curvekit.medial(again).nodes, curvekit.medial(glyph).nodes)


def _size(geometry) -> float:
    x0, y0, x1, y1 = geometry.bounds
    return max(x1 - x0, y1 - y0)


@pytest.mark.parametrize("path", [POCKET, GLYPH, FIXTURES / "corpus" / "dxf" / "island_in_hole.dxf"])
def test_geo_interface_is_the_region_within_the_tolerance(path) -> None:
    region = curvekit.read(path)
    polygon = shape(region)
    assert polygon.is_valid and polygon.geom_type in ("Polygon", "MultiPolygon")
    # Every vertex on the boundary, every chord within the tolerance of it: judged against
    # a far finer flattening by the oracle's own means (shapely's distance to a dense ring
    # drawn from the curve's exact evaluation).
    size = _size(polygon)
    dense = []
    for part in region.parts:
        for boundary in [part.outer, *part.holes]:
            a, b = boundary.domain
            dense.append(boundary.evaluate(np.linspace(a, b, 20001)))
    exact = shapely.MultiLineString([shapely.LineString(d) for d in dense])
    rings = [polygon] if polygon.geom_type == "Polygon" else list(polygon.geoms)
    vertices = np.concatenate([np.asarray(r.coords) for p in rings for r in [p.exterior, *p.interiors]])
    # (The dense ring's own chords are far finer than the tolerance asked.)
    assert max(exact.distance(shapely.Point(v)) for v in vertices[::7]) <= 1e-4 * size
    assert shapely.hausdorff_distance(polygon.boundary, exact, densify=0.05) <= TOL * size * 1.01
    # GeoJSON's orientation: outer rings counterclockwise, holes clockwise.
    for p in rings:
        assert p.exterior.is_ccw and all(not r.is_ccw for r in p.interiors)


def test_offset_regions_and_geometry_match_shapely_buffer() -> None:
    glyph = curvekit.read(GLYPH)
    polygon = shape(glyph)
    size = _size(polygon)
    for d in (0.01 * size, 0.05 * size):
        found = curvekit.offset(glyph, distance=d)
        regions = found.regions(0)
        buffered = polygon.buffer(-d, quad_segs=64)
        parts = [buffered] if buffered.geom_type == "Polygon" else list(buffered.geoms)
        assert len(regions) == len(parts)
        assert sorted(len(r.holes) for r in regions) == sorted(len(p.interiors) for p in parts)
        ours = shape(found)
        assert ours.geom_type == "MultiPolygon" and ours.is_valid
        assert abs(ours.area - buffered.area) <= 2e-3 * buffered.area
        # Each region is a region the commands take again (its axis is not always certified:
        # the fitted pieces meet at corners of 1e-4 rad, which the axis's proofs refuse).
        assert all(len(curvekit.medial(r).edges) > 0 for r in regions)
    both = curvekit.offset(glyph, distances=[0.01 * size, 0.05 * size])
    assert shape(both).geom_type == "GeometryCollection" and len(shape(both).geoms) == 2


def test_shapely_polygons_come_and_go() -> None:
    square_with_hole = ShapelyPolygon([(0, 0), (6, 0), (6, 4), (0, 4)], [[(2, 1), (2, 3), (4, 3), (4, 1)]])
    curve = curvekit.from_shapely(square_with_hole)
    assert curve.kind == "region" and len(curve.holes) == 1
    back = curvekit.to_shapely(curve)
    assert back.symmetric_difference(square_with_hole).area <= 1e-12
    two = shapely.MultiPolygon([square_with_hole, ShapelyPolygon([(10, 0), (12, 0), (11, 2)])])
    both = curvekit.from_shapely(two)
    assert both.kind == "regions" and len(both.parts) == 2
    assert curvekit.to_shapely(both).symmetric_difference(two).area <= 1e-12
    line = curvekit.from_shapely(shapely.LineString([(0, 0), (1, 0), (1, 1)]))
    assert line.kind == "profile" and not line.closed
    assert shape(line).geom_type == "LineString"
    with pytest.raises(curvekit.InputError, match="Point"):
        curvekit.from_shapely(shapely.Point(0, 0))
