"""DXF parts written with ezdxf: the corpus's mechanical drawings.

Each part is a function returning (document, note, expectation). The note says what the drawing
holds and what the right answer is; the expectation is what the oracle checks its own reading
against (parts and holes, or the cause a refusal must name) and what curvekit must report beside
the geometry (skipped entities, units, an uncertified result).
"""

from __future__ import annotations

import math

import ezdxf
from ezdxf.enums import TextEntityAlignment

MM, INCH = 4, 1
FILLET = math.tan(math.radians(90) / 4)  # bulge of a quarter circle


def new(units: int = MM):
    document = ezdxf.new("R2010")
    document.units = units
    document.header["$INSUNITS"] = units
    return document, document.modelspace()


def rounded_rect(layout, x, y, w, h, r, **attribs):
    """A closed LWPOLYLINE rectangle, counterclockwise, corners rounded by bulges."""
    points = [
        (x + r, y, 0), (x + w - r, y, FILLET), (x + w, y + r, 0), (x + w, y + h - r, FILLET),
        (x + w - r, y + h, 0), (x + r, y + h, FILLET), (x, y + h - r, 0), (x, y + r, FILLET),
    ]
    return layout.add_lwpolyline(points, format="xyb", close=True, dxfattribs=attribs)


def stadium(layout, x0, x1, y, r):
    """A slot: two half circles (bulge 1) joined by straight sides."""
    return layout.add_lwpolyline([(x0, y - r, 0), (x1, y - r, 1), (x1, y + r, 0), (x0, y + r, 1)], format="xyb", close=True)


def regular_polygon(cx, cy, r, n, phase=0.0):
    return [(cx + r * math.cos(phase + 2 * math.pi * k / n), cy + r * math.sin(phase + 2 * math.pi * k / n)) for k in range(n)]


def bezier_chain_spline(layout, chain, degree=3):
    """A closed clamped spline of Bézier pieces joined with full-multiplicity knots (C0 corners).

    `chain` lists each piece's control points without its last (the next piece's first)."""
    control = [p for piece in chain for p in piece] + [chain[0][0]]
    pieces = len(chain)
    knots = [0.0] * (degree + 1)
    for k in range(1, pieces):
        knots += [float(k)] * degree
    knots += [float(pieces)] * (degree + 1)
    return layout.add_open_spline(control, degree=degree, knots=knots)


def star_chain(cx, cy, outer, inner, points):
    """Bézier pieces of a star with bulging sides: corners at the tips and the notches."""
    corners = []
    for k in range(2 * points):
        r = outer if k % 2 == 0 else inner
        a = math.pi * k / points + math.pi / 2
        corners.append((cx + r * math.cos(a), cy + r * math.sin(a)))
    chain = []
    for k, a in enumerate(corners):
        b = corners[(k + 1) % len(corners)]
        mx, my = (a[0] + b[0]) / 2 - cx, (a[1] + b[1]) / 2 - cy
        bulge = 0.25
        chain.append([a, (a[0] + (b[0] - a[0]) / 3 + bulge * mx, a[1] + (b[1] - a[1]) / 3 + bulge * my),
                      (a[0] + 2 * (b[0] - a[0]) / 3 + bulge * mx, a[1] + 2 * (b[1] - a[1]) / 3 + bulge * my)])
    return chain


def nurbs_circle(layout, cx, cy, r, sx=1.0, sy=1.0):
    """The exact rational quadratic circle (nine points), optionally stretched into an ellipse."""
    w = math.sqrt(0.5)
    square = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
    control = [(cx + r * sx * x, cy + r * sy * y) for x, y in square]
    weights = [1, w, 1, w, 1, w, 1, w, 1]
    knots = [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1]
    return layout.add_rational_spline(control, weights, degree=2, knots=knots)


def expect(parts=1, holes=None, **more):
    holes = [0] * parts if holes is None else holes
    return {"valid": True, "parts": parts, "holes": holes, **more}


def refuse(cause, **more):
    return {"valid": False, "cause": cause, **more}


# ----------------------------------------------------------------------------------------------
# The parts


def plate_holes_block():
    doc, msp = new()
    hole = doc.blocks.new("HOLE")
    hole.add_circle((0, 0), 4)
    rounded_rect(msp, 0, 0, 100, 60, 6)
    for x, y in [(12, 12), (88, 12), (88, 48), (12, 48)]:
        msp.add_blockref("HOLE", (x, y))
    return doc, "rounded plate 100x60 (bulge fillets r6), 4 holes r4 as INSERTs of one block: outer + 4 holes", expect(holes=[4], units="mm")


def plate_scaled_rotated_insert():
    doc, msp = new()
    slot = doc.blocks.new("SLOT")
    stadium(slot, -5, 5, 0, 3)
    rounded_rect(msp, 0, 0, 120, 70, 5)
    msp.add_blockref("SLOT", (35, 35), dxfattribs={"xscale": 1.5, "yscale": 1.5, "zscale": 1.5, "rotation": 30})
    msp.add_blockref("SLOT", (85, 35), dxfattribs={"rotation": -60})
    return doc, "plate with a slot block inserted scaled 1.5 + rotated 30 deg and rotated -60 deg: outer + 2 holes", expect(holes=[2], units="mm")


def plate_mirrored_insert():
    doc, msp = new()
    d_hole = doc.blocks.new("DHOLE")
    d_hole.add_line((0, -6), (0, 6))
    d_hole.add_arc((0, 0), 6, -90, 90)
    rounded_rect(msp, 0, 0, 80, 40, 4)
    msp.add_blockref("DHOLE", (25, 20))
    msp.add_blockref("DHOLE", (55, 20), dxfattribs={"xscale": -1})
    return doc, "D-shaped hole (LINE + ARC in a block) inserted as is and mirrored (xscale -1, arc extrusion flips): outer + 2 holes facing each other", expect(holes=[2], units="mm")


def plate_mirrored_rotated_keyhole():
    doc, msp = new()
    key = doc.blocks.new("KEY")
    # keyhole: circle r5 at the origin opening into a slot of half-width 2 to x = 14
    a = math.degrees(math.asin(2 / 5))
    key.add_arc((0, 0), 5, a, 360 - a)
    key.add_line((5 * math.cos(math.radians(a)), 2), (12, 2))
    key.add_line((5 * math.cos(math.radians(a)), -2), (12, -2))
    key.add_arc((12, 0), 2, -90, 90)
    rounded_rect(msp, 0, 0, 90, 60, 8)
    msp.add_blockref("KEY", (25, 30), dxfattribs={"yscale": -1, "rotation": 45})
    msp.add_blockref("KEY", (65, 30), dxfattribs={"xscale": -1, "rotation": 20})
    return doc, "keyhole block (2 arcs + 2 lines) inserted mirrored in y + rotated 45 and mirrored in x + rotated 20: outer + 2 holes", expect(holes=[2], units="mm")


def plate_nonuniform_insert():
    doc, msp = new()
    hole = doc.blocks.new("ROUND")
    hole.add_circle((0, 0), 5)
    rounded_rect(msp, 0, 0, 100, 50, 5)
    msp.add_blockref("ROUND", (30, 25), dxfattribs={"xscale": 2.0, "yscale": 1.0})
    msp.add_blockref("ROUND", (75, 25), dxfattribs={"xscale": 1.0, "yscale": 1.6, "rotation": 30})
    return doc, "a circle block inserted with non-uniform scales (2 x 1, and 1 x 1.6 rotated 30): 2 elliptic holes: outer + 2 holes", expect(holes=[2], units="mm")


def minsert_grid():
    doc, msp = new()
    hole = doc.blocks.new("H3")
    hole.add_circle((0, 0), 3)
    rounded_rect(msp, 0, 0, 120, 80, 4)
    msp.add_blockref("H3", (15, 15)).grid(size=(3, 4), spacing=(25, 30))
    return doc, "MINSERT array 3 rows x 4 columns of holes r3 (spacing 25 x 30): outer + 12 holes", expect(holes=[12], units="mm")


def minsert_rotated_squares():
    doc, msp = new()
    square = doc.blocks.new("SQ")
    square.add_lwpolyline([(-4, -4), (4, -4), (4, 4), (-4, 4)], close=True)
    rounded_rect(msp, -20, -20, 140, 100, 10)
    msp.add_blockref("SQ", (10, 10), dxfattribs={"rotation": 15}).grid(size=(2, 3), spacing=(40, 40))
    return doc, "MINSERT 2 x 3 array of square holes, the whole array rotated 15 deg: outer + 6 holes", expect(holes=[6], units="mm")


def nested_blocks():
    doc, msp = new()
    hole = doc.blocks.new("PIN")
    hole.add_circle((0, 0), 2.5)
    row = doc.blocks.new("ROW")
    for x in (0, 12, 24):
        row.add_blockref("PIN", (x, 0))
    rounded_rect(msp, 0, 0, 60, 40, 3)
    msp.add_blockref("ROW", (10, 10))
    msp.add_blockref("ROW", (50, 30), dxfattribs={"xscale": -1})
    return doc, "a block of 3 pin holes inside a block, inserted twice (once mirrored): outer + 6 holes", expect(holes=[6], units="mm")


def lwpoly_cam():
    doc, msp = new()
    points = [(0, 0, 0.3), (40, 0, 0.5), (50, 20, -0.25), (40, 40, 0.4), (10, 45, 0.2), (-5, 20, 0.3)]
    msp.add_lwpolyline(points, format="xyb", close=True)
    return doc, "a cam: one closed LWPOLYLINE of 6 bulged arcs, one concave (bulge -0.25): outer only, corners where arcs meet", expect(units="mm")


def lwpoly_slots():
    doc, msp = new()
    rounded_rect(msp, 0, 0, 100, 60, 10)
    for y in (15, 30, 45):
        stadium(msp, 20, 80 - y / 3, y, 3.5)
    return doc, "plate with 3 stadium slots (LWPOLYLINE bulge 1 ends): outer + 3 holes", expect(holes=[3], units="mm")


def polyline2d_bulges():
    doc, msp = new()
    msp.add_polyline2d([(0, 0, 0), (60, 0, 0.4), (60, 30, 0), (30, 40, -0.3), (0, 30, 0)], format="xyb", close=True)
    msp.add_polyline2d([(20, 10, 1), (30, 10, 1)], format="xyb", close=True)
    return doc, "old-style 2D POLYLINE with bulges (one concave), a round hole as a 2-vertex bulged POLYLINE: outer + 1 hole", expect(holes=[1], units="mm")


def arc_line_chain():
    doc, msp = new()
    # a gasket: lines and arcs written in scrambled order, some lines reversed
    msp.add_arc((60, 20), 20, -90, 90)
    msp.add_line((0, 40), (0, 0))
    msp.add_line((60, 40), (0, 40))
    msp.add_line((60, 0), (0, 0))  # reversed relative to the loop
    msp.add_circle((60, 20), 6)
    msp.add_circle((15, 20), 5)
    return doc, "gasket of separate LINE and ARC entities in scrambled order (one line reversed), 2 CIRCLE holes: outer + 2 holes", expect(holes=[2], units="mm")


def arc_extrusion_chain():
    doc, msp = new()
    # arcs in an OCS with extrusion (0, 0, -1): OCS x = -WCS x, drawn clockwise in WCS
    down = {"extrusion": (0, 0, -1)}
    msp.add_arc((-50, 10), 10, 90, 270, dxfattribs=down)  # WCS centre (50, 10), the right end
    msp.add_arc((-10, 10), 10, -90, 90, dxfattribs=down)  # WCS centre (10, 10), the left end
    msp.add_line((10, 0), (50, 0))
    msp.add_line((10, 20), (50, 20))
    return doc, "a stadium whose two end arcs have extrusion (0,0,-1) (OCS mirrored, clockwise in WCS): outer only, 40 x 20 with round ends", expect(units="mm")


def spline_c0_star():
    doc, msp = new()
    bezier_chain_spline(msp, star_chain(50, 50, 45, 22, 5))
    return doc, "a 5-point star as ONE closed clamped cubic SPLINE, interior knots of multiplicity 3 (C0): 10 corners, bulging sides: outer only", expect(units="mm")


def spline_c0_quadratic():
    doc, msp = new()
    corners = regular_polygon(0, 0, 40, 6)
    chain = []
    for k, a in enumerate(corners):
        b = corners[(k + 1) % 6]
        chain.append([a, ((a[0] + b[0]) * 0.6, (a[1] + b[1]) * 0.6)])
    bezier_chain_spline(msp, chain, degree=2)
    msp.add_circle((0, 0), 10)
    return doc, "hexagon with bulging sides: a closed clamped quadratic SPLINE with knots of multiplicity 2 (corners), a CIRCLE hole: outer + 1 hole", expect(holes=[1], units="mm")


def spline_closed_by_points():
    doc, msp = new()
    control = [(0, 0), (30, -10), (60, 0), (70, 30), (40, 50), (10, 45), (-10, 20), (0, 0)]
    msp.add_open_spline(control, degree=3)
    return doc, "a clamped cubic SPLINE closed by its points (first = last, no closed flag): a corner at the seam: outer only", expect(units="mm")


def spline_periodic():
    doc, msp = new()
    base = [(0, 0), (40, -10), (80, 0), (90, 40), (50, 60), (10, 50)]
    degree = 3
    control = base + base[:degree]
    knots = list(range(len(control) + degree + 1))
    spline = msp.add_open_spline(control, degree=degree, knots=knots)
    spline.closed = True
    return doc, "a periodic closed cubic SPLINE (closed flag, uniform unclamped knots, first 3 points repeated at the end: ezdxf's closed form): smooth outer only", expect(units="mm")


def spline_degree1():
    doc, msp = new()
    outer = regular_polygon(0, 0, 50, 6) + [regular_polygon(0, 0, 50, 6)[0]]
    msp.add_open_spline(outer, degree=1)
    triangle = regular_polygon(0, 0, 15, 3, math.pi / 2)
    msp.add_open_spline(triangle + [triangle[0]], degree=1)
    return doc, "degree-1 SPLINEs: a hexagon outline with a triangular hole: outer + 1 hole, all corners", expect(holes=[1], units="mm")


def nurbs_circle_hole():
    doc, msp = new()
    msp.add_lwpolyline([(0, 0), (80, 0), (80, 80), (0, 80)], close=True)
    nurbs_circle(msp, 40, 40, 25)
    return doc, "square plate with a hole that is the exact rational quadratic NURBS circle r25 (knots of multiplicity 2, smooth): outer + 1 hole", expect(holes=[1], units="mm")


def nurbs_ellipse_outer():
    doc, msp = new()
    nurbs_circle(msp, 0, 0, 30, 2.0, 1.0)
    msp.add_circle((-30, 0), 8)
    msp.add_circle((30, 0), 8)
    return doc, "an ellipse 60 x 30 (semi-axes) as a rational NURBS outline, 2 CIRCLE holes: outer + 2 holes", expect(holes=[2], units="mm")


def ellipse_holes():
    doc, msp = new()
    rounded_rect(msp, 0, 0, 120, 60, 8)
    msp.add_ellipse((35, 30), major_axis=(15, 8), ratio=0.5)
    msp.add_ellipse((85, 30), major_axis=(0, 18), ratio=0.4)
    return doc, "plate with 2 full ELLIPSE holes (one rotated, one with a vertical major axis): outer + 2 holes", expect(holes=[2], units="mm")


def ellipse_arc_chain():
    doc, msp = new()
    msp.add_ellipse((0, 0), major_axis=(0, 15), ratio=0.5, start_param=0, end_param=math.pi)
    msp.add_ellipse((50, 0), major_axis=(0, 15), ratio=0.5, start_param=math.pi, end_param=2 * math.pi)
    msp.add_line((0, -15), (50, -15))
    msp.add_line((50, 15), (0, 15))
    return doc, "an obround with half-ELLIPSE ends (elliptic arcs by parameter) and lines: outer only", expect(units="mm")


def washer():
    doc, msp = new()
    msp.add_circle((0, 0), 30)
    msp.add_circle((0, 0), 12)
    return doc, "a washer: two concentric CIRCLEs: one annulus (outer + 1 hole); its medial axis is one circle of radius 21 (a joint node)", expect(holes=[1], units="mm")


def plate_inches():
    doc, msp = new(INCH)
    rounded_rect(msp, 0, 0, 4, 2.5, 0.25)
    for x in (0.5, 3.5):
        msp.add_circle((x, 1.25), 0.2)
    return doc, "a 4 x 2.5 inch plate ($INSUNITS = 1), 2 holes: outer + 2 holes, units inch", expect(holes=[2], units="in")


def flange():
    doc, msp = new()
    bolt = doc.blocks.new("BOLT")
    bolt.add_circle((35, 0), 4)
    msp.add_circle((0, 0), 50)
    msp.add_circle((0, 0), 20)
    for k in range(6):
        msp.add_blockref("BOLT", (0, 0), dxfattribs={"rotation": 60 * k})
    return doc, "round flange r50, bore r20, 6 bolt holes as a block rotated about the centre: outer + 7 holes", expect(holes=[7], units="mm")


def text_and_notes():
    doc, msp = new()
    rounded_rect(msp, 0, 0, 80, 50, 5)
    msp.add_circle((40, 25), 8)
    msp.add_text("PART 7", height=3).set_placement((5, 5), align=TextEntityAlignment.LEFT)
    msp.add_text("R8", height=2).set_placement((50, 30), align=TextEntityAlignment.LEFT)
    msp.add_mtext("Deburr all edges", dxfattribs={"char_height": 2}).set_location((5, 45))
    return doc, "plate + hole with 2 TEXT and 1 MTEXT: outer + 1 hole; skipped TEXT x2, MTEXT x1 (not outlines: may stay certified)", expect(holes=[1], units="mm", skipped={"TEXT": 2, "MTEXT": 1})


def polyline3d_off_plane():
    doc, msp = new()
    rounded_rect(msp, 0, 0, 80, 50, 5)
    msp.add_circle((20, 25), 5)
    msp.add_polyline3d([(50, 10, 0), (70, 10, 5), (70, 40, 5), (50, 40, 0)], close=True)
    return doc, "plate + hole and a closed 3D POLYLINE off the plane (z 0..5): outer + 1 hole; the 3D polyline is skipped, so the result must be uncertified with a reason naming it", expect(holes=[1], units="mm", uncertified=True, skipped={"POLYLINE": 1})


def two_parts():
    doc, msp = new()
    rounded_rect(msp, 0, 0, 50, 30, 4)
    msp.add_circle((25, 15), 6)
    rounded_rect(msp, 70, 0, 30, 30, 3)
    return doc, "two separate plates (one with a hole): multi-part: 2 parts, holes [1, 0]", expect(parts=2, holes=[1, 0], units="mm")


def island_in_hole():
    doc, msp = new()
    rounded_rect(msp, 0, 0, 100, 100, 10)
    msp.add_circle((50, 50), 35)
    rounded_rect(msp, 35, 35, 30, 30, 5)
    return doc, "a plate with a big round hole holding a square island: 2 parts (outer with 1 hole; the island)", expect(parts=2, holes=[1, 0], units="mm")


def open_gap():
    doc, msp = new()
    msp.add_line((0, 0), (60, 0))
    msp.add_line((60, 0), (60, 40))
    msp.add_line((60, 40), (0, 40))
    msp.add_line((0, 40), (0, 0.5))
    return doc, "four LINEs that leave a 0.5 mm gap at (0, 0): no closed outline: refused, naming the gap", refuse("open")


def crossing_circles():
    doc, msp = new()
    msp.add_circle((0, 0), 20)
    msp.add_circle((25, 0), 20)
    return doc, "two overlapping CIRCLEs: the outlines cross: refused, naming the crossing", refuse("cross")


def far_from_origin():
    doc, msp = new()
    x0, y0 = 125000.0, 250000.0
    rounded_rect(msp, x0, y0, 60, 40, 5)
    msp.add_circle((x0 + 15, y0 + 20), 5)
    stadium(msp, x0 + 35, x0 + 48, y0 + 20, 4)
    return doc, "a 60 x 40 plate placed at (125000, 250000): outer + 2 holes; answers must be as accurate as at the origin", expect(holes=[2], units="mm")


def tiny_features():
    doc, msp = new()
    rounded_rect(msp, 0, 0, 100, 60, 2)
    msp.add_circle((20, 30), 0.05)
    stadium(msp, 50, 80, 30, 0.1)
    return doc, "plate 100 x 60 with a hole of r0.05 and a slot 0.2 wide (5e-4 and 2e-3 of the size): outer + 2 holes", expect(holes=[2], units="mm")


def fit_point_spline():
    doc, msp = new()
    fit = [(0, 0), (40, -5), (60, 20), (40, 45), (0, 40), (-10, 20), (0, 0)]
    msp.add_spline(fit, degree=3)
    return doc, "a closed outline given as a SPLINE with fit points only (no control points): its curve depends on the end conditions: expected refused or uncertified, never silently certified", refuse("fit", ambiguous=True)


def lwpoly_extrusion():
    doc, msp = new()
    # OCS with extrusion (0, 0, -1): vertices are mirrored in x when seen in WCS
    msp.add_lwpolyline([(-80, 0, 0), (0, 0, 0), (0, 40, 0), (-80, 40, 0)], format="xyb", close=True, dxfattribs={"extrusion": (0, 0, -1)})
    msp.add_lwpolyline([(-30, 20, 1), (-20, 20, 1)], format="xyb", close=True, dxfattribs={"extrusion": (0, 0, -1)})
    return doc, "LWPOLYLINEs with extrusion (0,0,-1): the plate lies at WCS x 0..80 (OCS x is mirrored), a round bulge hole at WCS (25, 20): outer + 1 hole", expect(holes=[1], units="mm")


def gear():
    doc, msp = new()
    teeth, root, tip = 18, 40.0, 48.0
    points = []
    for k in range(teeth):
        a = 2 * math.pi * k / teeth
        step = 2 * math.pi / teeth
        arc = math.tan(0.3 * step / 4)  # bulge of an arc of the root or tip circle over 0.3 step
        for angle, r, bulge in ((a, root, arc), (a + 0.3 * step, root, 0.0), (a + 0.4 * step, tip, arc), (a + 0.7 * step, tip, 0.0), (a + 0.8 * step, root, 0.0)):
            points.append((r * math.cos(angle), r * math.sin(angle), bulge))
    msp.add_lwpolyline(points, format="xyb", close=True)
    msp.add_circle((0, 0), 12)
    return doc, "an 18-tooth gear as one LWPOLYLINE (root and tip circle arcs as bulges, straight flanks and root chords), bore r12: outer + 1 hole", expect(holes=[1], units="mm")


def l_bracket():
    doc, msp = new()
    points = [(0, 0, 0), (80, 0, 0), (80, 12, 0), (20, 12, -FILLET), (12, 20, 0), (12, 70, 0), (0, 70, 0)]
    msp.add_lwpolyline(points, format="xyb", close=True)
    stadium(msp, 40, 65, 6, 2.5)
    msp.add_circle((6, 55), 3)
    return doc, "an L bracket with an inner fillet (concave bulge), a slot and a hole: outer + 2 holes", expect(holes=[2], units="mm")


def s_curve_arcs():
    doc, msp = new()
    # an outline whose top is an S of two tangent arcs bent opposite ways (an inflection at a G1 joint)
    msp.add_line((0, 0), (80, 0))
    msp.add_line((80, 0), (80, 20))
    msp.add_arc((60, 20), 20, 0, 90)  # from (80, 20) to (60, 40), bent left
    msp.add_arc((60, 60), 20, 180, 270)  # from (40, 60) to (60, 40): joined G1, bent the other way
    msp.add_arc((20, 60), 20, 0, 90)  # from (40, 60) to (20, 80)
    msp.add_line((20, 80), (0, 80))
    msp.add_line((0, 80), (0, 0))
    return doc, "an outline whose top is three tangent arcs bent alternately (inflections at G1 joints): outer only, 2 inflections", expect(units="mm", inflections=2)


PARTS = [
    plate_holes_block, plate_scaled_rotated_insert, plate_mirrored_insert, plate_mirrored_rotated_keyhole,
    plate_nonuniform_insert, minsert_grid, minsert_rotated_squares, nested_blocks, lwpoly_cam, lwpoly_slots,
    polyline2d_bulges, arc_line_chain, arc_extrusion_chain, spline_c0_star, spline_c0_quadratic,
    spline_closed_by_points, spline_periodic, spline_degree1, nurbs_circle_hole, nurbs_ellipse_outer,
    ellipse_holes, ellipse_arc_chain, washer, plate_inches, flange, text_and_notes, polyline3d_off_plane,
    two_parts, island_in_hole, open_gap, crossing_circles, far_from_origin, tiny_features, fit_point_spline,
    lwpoly_extrusion, gear, l_bracket, s_curve_arcs,
]
