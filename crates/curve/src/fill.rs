//! Regions from the closed outlines of a drawing, as a renderer fills them: each group of
//! outlines (an SVG element) fills the points its rule says are inside (`nonzero`: a nonzero
//! winding number; `evenodd`: an odd one), and the drawing is the union of the groups'
//! fills. Outlines must not cross (the union of crossing fills is not a region of these
//! outlines); nested ones split the plane into faces, each filled or not, and an outline is
//! a boundary of the union exactly where the faces either side of it differ. Each filled face
//! inside a boundary is a part: a region whose holes are the boundaries next inside it.

use crate::crossing::{first_crossing_among, Chain, Outline};
use crate::error::{Error, Result};
use crate::param::ParamCurve;
use crate::profile::Profile;
use crate::region::Region;

/// Which points a group's outlines fill.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FillRule {
    /// Points about which the outlines wind a nonzero number of times (SVG's default).
    NonZero,
    /// Points inside an odd number of the outlines (nesting: each outline inside another
    /// is a hole, and so on; DXF drawings and outlines drawn without fill).
    EvenOdd,
}

/// A closed outline of a drawing, with the group it is filled with and that group's rule.
#[derive(Debug, Clone, PartialEq)]
pub struct FilledOutline {
    /// The outline (a closed profile).
    pub profile: Profile,
    /// The group (an SVG element): the union is taken over groups.
    pub group: usize,
    /// The group's fill rule.
    pub rule: FillRule,
}

impl Region {
    /// The regions of closed profiles nested inside each other (even-odd): each profile at
    /// an even depth an outer boundary, with the profiles directly inside it as its holes;
    /// in the order of their outer boundaries. Open profiles are left out. Profiles that cross
    /// are an error ([`Region::filled`] with one group filled even-odd).
    ///
    /// ```
    /// use curve::{Profile, Region, Segment};
    /// let circle = |r: f64| {
    ///     Profile::new(vec![Segment::arc([0.0, 0.0], r, 0.0, std::f64::consts::TAU).unwrap()], None)
    ///         .unwrap()
    /// };
    /// // A washer with a disk in its hole: two regions.
    /// let regions = Region::nested(vec![circle(1.0), circle(3.0), circle(2.0)]).unwrap();
    /// assert_eq!(regions.len(), 2);
    /// assert_eq!(regions[1].holes().len(), 1); // the washer (outer r = 3) comes second
    /// ```
    pub fn nested(profiles: Vec<Profile>) -> Result<Vec<Region>> {
        let outlines = profiles
            .into_iter()
            .filter(|p| p.is_closed())
            .map(|profile| FilledOutline {
                profile,
                group: 0,
                rule: FillRule::EvenOdd,
            })
            .collect();
        Region::filled(outlines)
    }

    /// The parts a drawing's closed outlines fill (see the module documentation), in the order
    /// of their outer boundaries; outlines that bound no part (between two filled faces, or two
    /// empty ones) are left out. Outlines that cross or touch are an error naming the two
    /// (their indices) and where they meet.
    ///
    /// ```
    /// use curve::{FillRule, FilledOutline, Profile, Region, Segment};
    /// let circle = |r: f64, ccw: bool| {
    ///     let end = if ccw { std::f64::consts::TAU } else { -std::f64::consts::TAU };
    ///     Profile::new(vec![Segment::arc([0.0, 0.0], r, 0.0, end).unwrap()], None).unwrap()
    /// };
    /// let outline = |r, ccw, rule| FilledOutline { profile: circle(r, ccw), group: 0, rule };
    /// // Nonzero: an inner circle run the same way is no hole; run the other way, it is one.
    /// let same = Region::filled(vec![
    ///     outline(2.0, true, FillRule::NonZero),
    ///     outline(1.0, true, FillRule::NonZero),
    /// ]).unwrap();
    /// assert_eq!((same.len(), same[0].holes().len()), (1, 0));
    /// let opposite = Region::filled(vec![
    ///     outline(2.0, true, FillRule::NonZero),
    ///     outline(1.0, false, FillRule::NonZero),
    /// ]).unwrap();
    /// assert_eq!((opposite.len(), opposite[0].holes().len()), (1, 1));
    /// ```
    pub fn filled(outlines: Vec<FilledOutline>) -> Result<Vec<Region>> {
        let n = outlines.len();
        if n == 0 {
            return Ok(Vec::new());
        }
        if let Some(b) = outlines.iter().position(|o| !o.profile.is_closed()) {
            return Err(Error::OpenBoundary { boundary: b });
        }
        let size = outlines
            .iter()
            .map(|o| o.profile.scale())
            .fold(0.0, f64::max);
        let chains: Vec<Chain<'_>> = outlines
            .iter()
            .map(|o| (o.profile.segments(), true))
            .collect();
        if let Some(c) = first_crossing_among(&chains, true, size)? {
            return Err(Error::OutlinesCross {
                first: c.chains.0,
                second: c.chains.1,
                at: c.at,
            });
        }
        let parent = parents(&outlines)?;
        // Faces in order of depth: a parent's before its children.
        let mut order: Vec<usize> = (0..n).collect();
        let depth = |mut i: usize| {
            let mut d = 0;
            while let Some(p) = parent[i] {
                d += 1;
                i = p;
            }
            d
        };
        let depths: Vec<usize> = (0..n).map(depth).collect();
        order.sort_by_key(|&i| depths[i]);
        let groups = outlines.iter().map(|o| o.group).max().unwrap_or(0) + 1;
        let mut rules = vec![None; groups];
        for o in &outlines {
            rules[o.group] = Some(o.rule);
        }
        // The winding number of each group about the face just inside each outline.
        let mut winding: Vec<Vec<i64>> = vec![Vec::new(); n];
        let mut filled = vec![false; n];
        for &i in &order {
            let mut w = match parent[i] {
                Some(p) => winding[p].clone(),
                None => vec![0; groups],
            };
            w[outlines[i].group] += outlines[i].profile.orientation() as i64;
            filled[i] = w.iter().zip(&rules).any(|(&w, rule)| match rule {
                Some(FillRule::NonZero) => w != 0,
                Some(FillRule::EvenOdd) => w % 2 != 0,
                None => false,
            });
            winding[i] = w;
        }
        let outside_filled = |i: usize| parent[i].is_some_and(|p| filled[p]);
        let bounds = |i: usize| filled[i] != outside_filled(i);
        // The nearest boundary round each outline (itself excluded).
        let enclosing = |mut i: usize| loop {
            match parent[i] {
                Some(p) if bounds(p) => return Some(p),
                Some(p) => i = p,
                None => return None,
            }
        };
        let owner: Vec<Option<usize>> = (0..n).map(enclosing).collect();
        let mut slots: Vec<Option<Profile>> =
            outlines.into_iter().map(|o| Some(o.profile)).collect();
        let mut parts = Vec::new();
        for o in (0..n).filter(|&o| bounds(o) && filled[o]) {
            let holes: Vec<Profile> = (0..n)
                .filter(|&h| bounds(h) && !filled[h] && owner[h] == Some(o))
                .filter_map(|h| slots[h].take())
                .collect();
            if let Some(outer) = slots[o].take() {
                parts.push(Region::checked(outer, holes));
            }
        }
        Ok(parts)
    }
}

/// The outline directly round each outline (the innermost of those holding it), or none. The
/// outlines not crossing, one holds another exactly when it winds round one of the other's
/// points, which must then lie in the box of its control points (which holds it).
fn parents(outlines: &[FilledOutline]) -> Result<Vec<Option<usize>>> {
    let n = outlines.len();
    let boxes: Vec<[f64; 4]> = outlines.iter().map(|o| profile_box(&o.profile)).collect();
    let in_box =
        |b: &[f64; 4], p: crate::V2| b[0] <= p.x && b[1] <= p.y && b[2] >= p.x && b[3] >= p.y;
    let tests: Vec<Outline> = outlines
        .iter()
        .map(|o| Outline::new(o.profile.segments(), o.profile.scale()))
        .collect();
    let mut within: Vec<Vec<usize>> = vec![Vec::new(); n];
    for i in 0..n {
        let start = outlines[i].profile.jet_to(0.0, 0).p;
        for j in (0..n).filter(|&j| j != i && in_box(&boxes[j], start)) {
            if tests[j].winds_round(start)? {
                within[i].push(j);
            }
        }
    }
    // The innermost holder is the one held by all the others.
    Ok((0..n)
        .map(|i| within[i].iter().copied().max_by_key(|&j| within[j].len()))
        .collect())
}

/// The box of a profile's control points, `[lo x, lo y, hi x, hi y]` (it holds the profile).
fn profile_box(p: &Profile) -> [f64; 4] {
    (0..p.segments().len()).fold(
        [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ],
        |b, i| {
            let s = p.segment_box(i);
            [
                b[0].min(s[0]),
                b[1].min(s[1]),
                b[2].max(s[2]),
                b[3].max(s[3]),
            ]
        },
    )
}
