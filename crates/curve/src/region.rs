//! Regions: an outer closed profile and holes inside it (a pocket with islands), validated
//! as the interface contract asks: every boundary closed, holes inside the outer boundary and
//! outside each other, no two boundaries crossing or touching.

use crate::crossing::{first_crossing_among, Chain, Outline};
use crate::error::{Error, Result};
use crate::param::ParamCurve;
use crate::profile::Profile;

/// A region bounded by closed profiles: the outer one and its holes.
#[derive(Debug, Clone, PartialEq)]
pub struct Region {
    outer: Profile,
    holes: Vec<Profile>,
}

impl Region {
    /// The region inside `outer` and outside every hole. Boundaries are numbered 0 for the
    /// outer one and `1 + i` for hole `i` in errors.
    ///
    /// ```
    /// use curve::{Profile, Region, Segment};
    /// let circle = |c: [f64; 2], r: f64| {
    ///     Profile::new(vec![Segment::arc(c, r, 0.0, std::f64::consts::TAU).unwrap()], None).unwrap()
    /// };
    /// let washer = Region::new(circle([0.0, 0.0], 2.0), vec![circle([0.0, 0.0], 1.0)]).unwrap();
    /// assert_eq!(washer.holes().len(), 1);
    /// assert!(Region::new(circle([0.0, 0.0], 1.0), vec![circle([3.0, 0.0], 0.5)]).is_err());
    /// ```
    pub fn new(outer: Profile, holes: Vec<Profile>) -> Result<Self> {
        let boundaries: Vec<&Profile> = std::iter::once(&outer).chain(&holes).collect();
        if let Some(b) = boundaries.iter().position(|p| !p.is_closed()) {
            return Err(Error::OpenBoundary { boundary: b });
        }
        // (Each boundary is simple, proven when it was made: only pairs of boundaries are
        // tested, to the flatness of the outer boundary's size.)
        let chains: Vec<Chain<'_>> = boundaries.iter().map(|p| (p.segments(), true)).collect();
        if let Some(c) = first_crossing_among(&chains, true, outer.scale())? {
            return Err(Error::BoundariesCross {
                first: c.chains.0,
                second: c.chains.1,
                at: c.at,
            });
        }
        // No crossings: a boundary lies inside another exactly when one of its points does.
        let outlines: Vec<Outline> = boundaries
            .iter()
            .map(|p| Outline::new(p.segments(), p.scale()))
            .collect();
        let inside = |b: usize, of: usize| outlines[of].winds_round(boundaries[b].jet_to(0.0, 0).p);
        for h in 1..boundaries.len() {
            if !inside(h, 0)? {
                return Err(Error::HoleOutside { hole: h - 1 });
            }
            for o in (1..boundaries.len()).filter(|&o| o != h) {
                if inside(h, o)? {
                    return Err(Error::HoleInHole {
                        hole: h - 1,
                        other: o - 1,
                    });
                }
            }
        }
        Ok(Self { outer, holes })
    }

    /// A region of boundaries already proven closed, apart and nested as [`Region::new`]
    /// requires.
    pub(crate) fn checked(outer: Profile, holes: Vec<Profile>) -> Self {
        Self { outer, holes }
    }

    /// The outer boundary.
    pub fn outer(&self) -> &Profile {
        &self.outer
    }

    /// The holes.
    pub fn holes(&self) -> &[Profile] {
        &self.holes
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::segment::Segment;
    use proptest::prelude::*;
    use std::f64::consts::TAU;

    fn circle(c: [f64; 2], r: f64, cw: bool) -> Profile {
        let end = if cw { -TAU } else { TAU };
        Profile::new(vec![Segment::arc(c, r, 0.0, end).unwrap()], None).unwrap()
    }

    fn square(lo: [f64; 2], side: f64) -> Profile {
        let c = [
            lo,
            [lo[0] + side, lo[1]],
            [lo[0] + side, lo[1] + side],
            [lo[0], lo[1] + side],
        ];
        let sides = (0..4)
            .map(|i| Segment::line(c[i], c[(i + 1) % 4]).unwrap())
            .collect();
        Profile::new(sides, None).unwrap()
    }

    #[test]
    fn holes_must_be_inside_apart_and_uncrossed() {
        let outer = square([0.0, 0.0], 10.0);
        let ok = Region::new(
            outer.clone(),
            vec![circle([3.0, 3.0], 1.0, true), square([6.0, 6.0], 2.0)],
        );
        assert!(ok.is_ok(), "{ok:?}");
        let outside = Region::new(outer.clone(), vec![circle([13.0, 3.0], 1.0, false)]);
        assert!(
            matches!(outside, Err(Error::HoleOutside { hole: 0 })),
            "{outside:?}"
        );
        let crossing = Region::new(outer.clone(), vec![circle([10.0, 5.0], 1.0, false)]);
        assert!(
            matches!(
                crossing,
                Err(Error::BoundariesCross {
                    first: 0,
                    second: 1,
                    ..
                })
            ),
            "{crossing:?}"
        );
        let nested = Region::new(
            outer.clone(),
            vec![
                circle([5.0, 5.0], 3.0, false),
                circle([5.0, 5.0], 1.0, false),
            ],
        );
        assert!(
            matches!(nested, Err(Error::HoleInHole { hole: 1, other: 0 })),
            "{nested:?}"
        );
        let overlapping = Region::new(
            outer,
            vec![
                circle([4.0, 5.0], 1.5, false),
                circle([6.0, 5.0], 1.5, false),
            ],
        );
        assert!(
            matches!(
                overlapping,
                Err(Error::BoundariesCross {
                    first: 1,
                    second: 2,
                    ..
                })
            ),
            "{overlapping:?}"
        );
    }

    proptest! {
        /// A circular hole is accepted exactly when it lies strictly inside the outer circle
        /// (by a margin far above the flatness), and refused when it crosses or lies
        /// outside.
        #[test]
        fn circular_holes_against_their_distances(
            x in -3.0f64..3.0, y in -3.0f64..3.0, r in 0.1f64..1.5, cw in any::<bool>(),
        ) {
            let (big, d) = (2.0, x.hypot(y));
            let inside = d + r < big - 1e-4;
            let apart = d - r > big + 1e-4 || r - d > big + 1e-4;
            prop_assume!(inside || apart || (d + r > big + 1e-4 && d - r < big - 1e-4));
            let got = Region::new(circle([0.0, 0.0], big, false), vec![circle([x, y], r, cw)]);
            if inside {
                prop_assert!(got.is_ok(), "{got:?}");
            } else if apart {
                prop_assert!(matches!(got, Err(Error::HoleOutside { .. }) | Err(Error::HoleInHole { .. })), "{got:?}");
            } else {
                prop_assert!(matches!(got, Err(Error::BoundariesCross { .. })), "{got:?}");
            }
        }
    }
}
