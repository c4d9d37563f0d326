//! DXF text written here, group by group: whole files (a HEADER with `$INSUNITS`, BLOCKS,
//! ENTITIES), the entities the tests use, and the images of lines and circular arcs under an
//! affine map written out as entities, as a CAD program explodes a block reference. The maps
//! are computed here, independently of the reader: a block reference's transform and the
//! exploded geometry must agree.

use curve::V2;

/// One entity as written: its type and its groups, in order.
#[derive(Debug, Clone)]
pub(crate) struct Written {
    pub(crate) kind: String,
    pub(crate) groups: Vec<(i32, String)>,
}

/// A number as written: the shortest text that reads back as the same `f64`.
pub(crate) fn num(x: f64) -> String {
    format!("{x:?}")
}

pub(crate) fn entity(kind: &str, groups: Vec<(i32, String)>) -> Written {
    Written {
        kind: kind.to_string(),
        groups,
    }
}

impl Written {
    /// The entity with handle `h` (code 5, first, as writers put it).
    pub(crate) fn handle(mut self, h: &str) -> Written {
        self.groups.insert(0, (5, h.to_string()));
        self
    }

    /// The entity with more groups at its end.
    pub(crate) fn with(mut self, more: &[(i32, &str)]) -> Written {
        self.groups.extend(super::groups(more));
        self
    }
}

/// A block definition of the BLOCKS section.
#[derive(Debug, Clone)]
pub(crate) struct Block {
    pub(crate) name: String,
    pub(crate) base: V2,
    /// Code 70: 1 anonymous, 4 external reference.
    pub(crate) flags: i32,
    pub(crate) entities: Vec<Written>,
}

pub(crate) fn block(name: &str, base: V2, entities: Vec<Written>) -> Block {
    Block {
        name: name.to_string(),
        base,
        flags: 0,
        entities,
    }
}

fn push_entities(s: &mut String, entities: &[Written]) {
    for e in entities {
        *s += &format!("  0\n{}\n", e.kind);
        for (code, value) in &e.groups {
            *s += &format!("{code:>3}\n{value}\n");
        }
    }
}

/// A whole ASCII DXF file: a HEADER section with `$INSUNITS` when `units` is given, the
/// BLOCKS section when there are blocks, and the ENTITIES section.
pub(crate) fn file(units: Option<&str>, blocks: &[Block], entities: &[Written]) -> String {
    let mut s = String::new();
    if let Some(u) = units {
        s += "  0\nSECTION\n  2\nHEADER\n  9\n$ACADVER\n  1\nAC1027\n";
        s += &format!("  9\n$INSUNITS\n 70\n{u}\n  0\nENDSEC\n");
    }
    if !blocks.is_empty() {
        s += "  0\nSECTION\n  2\nBLOCKS\n";
        for b in blocks {
            s += &format!(
                "  0\nBLOCK\n  8\n0\n  2\n{}\n 70\n{}\n 10\n{}\n 20\n{}\n 30\n0.0\n  3\n{}\n",
                b.name,
                b.flags,
                num(b.base.x),
                num(b.base.y),
                b.name
            );
            push_entities(&mut s, &b.entities);
            s += "  0\nENDBLK\n  8\n0\n";
        }
        s += "  0\nENDSEC\n";
    }
    s += "  0\nSECTION\n  2\nENTITIES\n";
    push_entities(&mut s, entities);
    s + "  0\nENDSEC\n  0\nEOF\n"
}

fn xy(code: i32, p: V2) -> [(i32, String); 2] {
    [(code, num(p.x)), (code + 10, num(p.y))]
}

pub(crate) fn line(p: V2, q: V2) -> Written {
    entity("LINE", [xy(10, p), xy(11, q)].concat())
}

/// An `ARC`: angles in degrees, counterclockwise from `a0` to `a1`.
pub(crate) fn arc(c: V2, r: f64, a0: f64, a1: f64) -> Written {
    let mut g = xy(10, c).to_vec();
    g.extend([(40, num(r)), (50, num(a0)), (51, num(a1))]);
    entity("ARC", g)
}

pub(crate) fn circle(c: V2, r: f64) -> Written {
    let mut g = xy(10, c).to_vec();
    g.push((40, num(r)));
    entity("CIRCLE", g)
}

/// An `ELLIPSE`: major axis end point relative to the centre, ratio, eccentric angles.
pub(crate) fn ellipse(c: V2, major: V2, ratio: f64, t0: f64, t1: f64) -> Written {
    let mut g = [xy(10, c), xy(11, major)].concat();
    g.extend([(40, num(ratio)), (41, num(t0)), (42, num(t1))]);
    entity("ELLIPSE", g)
}

/// An `LWPOLYLINE` of vertices `(point, bulge)`.
pub(crate) fn lwpolyline(vertices: &[(V2, f64)], closed: bool) -> Written {
    let mut g = vec![
        (90, vertices.len().to_string()),
        (70, if closed { "1" } else { "0" }.to_string()),
    ];
    for &(p, b) in vertices {
        g.extend(xy(10, p));
        g.push((42, num(b)));
    }
    entity("LWPOLYLINE", g)
}

/// A closed axis-aligned rectangle as an `LWPOLYLINE`.
pub(crate) fn rectangle(lo: V2, hi: V2) -> Written {
    let v = [
        (lo, 0.0),
        (V2::new(hi.x, lo.y), 0.0),
        (hi, 0.0),
        (V2::new(lo.x, hi.y), 0.0),
    ];
    lwpolyline(&v, true)
}

/// Where a block reference puts its block: `INSERT` groups, and the map they mean.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Placement {
    pub(crate) at: V2,
    pub(crate) scale: (f64, f64),
    pub(crate) degrees: f64,
    /// Extrusion direction (0, 0, −1): the insertion's object coordinates are mirrored in x.
    pub(crate) flipped: bool,
    /// Columns and rows (MINSERT), and their spacing.
    pub(crate) grid: (i32, i32),
    pub(crate) spacing: (f64, f64),
}

impl Placement {
    pub(crate) fn at(at: V2) -> Placement {
        Placement {
            at,
            scale: (1.0, 1.0),
            degrees: 0.0,
            flipped: false,
            grid: (1, 1),
            spacing: (0.0, 0.0),
        }
    }

    /// The `INSERT` of block `name` so placed.
    pub(crate) fn insert(&self, name: &str) -> Written {
        let mut g = vec![(2, name.to_string())];
        g.extend(xy(10, self.at));
        g.extend([
            (41, num(self.scale.0)),
            (42, num(self.scale.1)),
            (43, "1.0".to_string()),
            (50, num(self.degrees)),
        ]);
        if self.grid != (1, 1) {
            g.extend([
                (70, self.grid.0.to_string()),
                (71, self.grid.1.to_string()),
                (44, num(self.spacing.0)),
                (45, num(self.spacing.1)),
            ]);
        }
        if self.flipped {
            g.extend([
                (210, "0.0".into()),
                (220, "0.0".into()),
                (230, "-1.0".into()),
            ]);
        }
        entity("INSERT", g)
    }

    /// The map of the cell (`column`, `row`) for a block whose base point is `base`:
    /// block coordinates less the base, scaled, rotated, moved to the insertion point and the
    /// cell's offset (rotated, not scaled), then the object coordinates' mirror.
    pub(crate) fn map(&self, base: V2, column: i32, row: i32) -> Map {
        let (s, c) = self.degrees.to_radians().sin_cos();
        let (sx, sy) = self.scale;
        let linear = [[c * sx, -s * sy], [s * sx, c * sy]];
        let rotate = |v: V2| V2::new(c * v.x - s * v.y, s * v.x + c * v.y);
        let offset = rotate(V2::new(
            column as f64 * self.spacing.0,
            row as f64 * self.spacing.1,
        ));
        let moved = Map {
            m: linear,
            t: self.at + offset,
        }
        .after(&Map {
            m: [[1.0, 0.0], [0.0, 1.0]],
            t: V2::new(-base.x, -base.y),
        });
        if self.flipped {
            Map {
                m: [[-1.0, 0.0], [0.0, 1.0]],
                t: V2::new(0.0, 0.0),
            }
            .after(&moved)
        } else {
            moved
        }
    }
}

/// An affine map of the plane: `p ↦ m p + t`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Map {
    pub(crate) m: [[f64; 2]; 2],
    pub(crate) t: V2,
}

impl Map {
    pub(crate) fn apply(&self, p: V2) -> V2 {
        self.linear(p) + self.t
    }

    pub(crate) fn linear(&self, v: V2) -> V2 {
        V2::new(
            self.m[0][0] * v.x + self.m[0][1] * v.y,
            self.m[1][0] * v.x + self.m[1][1] * v.y,
        )
    }

    /// `self` after `inner`.
    pub(crate) fn after(&self, inner: &Map) -> Map {
        let mut m = [[0.0; 2]; 2];
        for (i, row) in m.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate() {
                *x = self.m[i][0] * inner.m[0][j] + self.m[i][1] * inner.m[1][j];
            }
        }
        Map {
            m,
            t: self.apply(inner.t),
        }
    }
}

/// A piece of a block's outlines, in block coordinates.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Prim {
    Line(V2, V2),
    /// Centre, radius, angles (radians), counterclockwise from the first to the second.
    Arc(V2, f64, f64, f64),
}

/// How near 1 the ratio of an arc's image's axes is for it to be written as an `ARC`.
const ROUND: f64 = 1e-12;

/// The image of `prim` under `map`, written as an entity: a `LINE`, an `ARC` where the map
/// keeps circles, an `ELLIPSE` where it does not (a full turn: a `CIRCLE` or full ellipse).
pub(crate) fn exploded(prim: Prim, map: &Map) -> Written {
    match prim {
        Prim::Line(p, q) => line(map.apply(p), map.apply(q)),
        Prim::Arc(c, r, a0, a1) => {
            // The image is c' + u cos t + v sin t for t from a0 to a1.
            let (u, v) = (map.linear(V2::new(r, 0.0)), map.linear(V2::new(0.0, r)));
            let c = map.apply(c);
            // Its major axis is at t0, where |u cos t + v sin t|² = (|u|² + |v|²)/2 +
            // (|u|² − |v|²)/2 cos 2t + u·v sin 2t is largest.
            let t0 = 0.5 * (2.0 * u.dot(v)).atan2(u.dot(u) - v.dot(v));
            let major = u * t0.cos() + v * t0.sin();
            let minor = u * (-t0.sin()) + v * t0.cos();
            let ratio = minor.norm() / major.norm();
            // Counterclockwise when the minor axis is a quarter turn left of the major.
            let ccw = major.x * minor.y - major.y * minor.x > 0.0;
            let (s0, s1) = if ccw {
                (a0 - t0, a1 - t0)
            } else {
                (-(a1 - t0), -(a0 - t0))
            };
            let full = (a1 - a0 - std::f64::consts::TAU).abs() < 1e-15;
            if (ratio - 1.0).abs() < ROUND {
                let phi = major.y.atan2(major.x);
                if full {
                    circle(c, major.norm())
                } else {
                    arc(
                        c,
                        major.norm(),
                        (phi + s0).to_degrees(),
                        (phi + s1).to_degrees(),
                    )
                }
            } else {
                ellipse(c, major, ratio, s0, s1)
            }
        }
    }
}
