//! What one computation of a profile bisector shares ([`Run`]): the options, the profiles'
//! size and reach; and the trimming of its result to the nearest foot points.

use super::point_site::Reach;
use crate::bisector::{bbox_of_points, Bisector, BisectorOptions, Branch, FAR, TRIM_SLACK};
use bspline::Rational;
use curve::{ParamCurve, Profile};
use geometry::{Clearance, NearestPoint, ProfileClearance};
use numeric::tolerance::{ChordTol, Settings, Size};

/// What one computation shares: the options, the profiles' size and reach.
pub(super) struct Run<'a> {
    pub(super) profiles: [&'a Profile; 2],
    pub(super) opts: BisectorOptions,
    center: [f64; 2],
    /// The diagonal of the box of the control points: how far branches run before they are
    /// clipped.
    pub(super) diag: f64,
    /// The size the chord tolerance is relative to (the contract's).
    size: f64,
}

impl<'a> Run<'a> {
    pub(super) fn new(profiles: &[&'a Profile], opts: &BisectorOptions) -> Self {
        let pts: Vec<[f64; 2]> = profiles
            .iter()
            .flat_map(|p| p.segments())
            .flat_map(|s| s.curve().control_points())
            .collect();
        let (center, diag) = bbox_of_points(&pts);
        // (The contract's size: max(width, height) of the profiles' points together.)
        let size = opts.settings.size.map_or_else(
            || {
                profiles
                    .iter()
                    .map(|p| p.bounding_box())
                    .reduce(curve::box_union)
                    .map(curve::box_size)
                    .filter(|s| *s > 0.0 && s.is_finite())
                    .unwrap_or(diag)
            },
            Size::get,
        );
        Self {
            profiles: [profiles[0], profiles[profiles.len() - 1]],
            opts: *opts,
            center,
            diag,
            size,
        }
    }

    pub(super) fn empty(&self) -> Bisector {
        Bisector {
            branches: Vec::new(),
            singular: Vec::new(),
            isolated: Vec::new(),
            complete: true,
        }
    }

    pub(super) fn reach(&self) -> Reach {
        Reach {
            center: self.center,
            far: FAR * self.diag,
            chord: self.opts.settings.chord_tol.get() * self.size,
            tol: self.opts.settings.tol.get(),
        }
    }

    /// Options for the bisector of two segments: untrimmed (trimming is the profiles'), the
    /// chord tolerance relative to the profiles' size rather than the pair's.
    pub(super) fn pair_options(&self, curves: &[&Rational]) -> BisectorOptions {
        let pair = crate::bisector::chord_size(curves);
        let own = self.opts.settings.chord_tol;
        let chord = (own.get() * self.size / pair).clamp(own.get(), ChordTol::COARSEST);
        BisectorOptions {
            // (In range but where the pair's size is no number: then the profiles' own.)
            settings: Settings {
                chord_tol: ChordTol::new(chord).unwrap_or(own),
                size: None,
                ..self.opts.settings
            },
            trimmed: false,
            ..self.opts
        }
    }

    /// The profile parameter of segment `i`'s own parameter `v` on profile `which`.
    pub(super) fn param(&self, which: usize, i: usize, v: f64) -> f64 {
        self.profiles[which].profile_param(i, v)
    }

    /// With `trimmed`, keeps only the vertices whose foot points are nearest points of the
    /// profiles, splitting branches where others are dropped.
    pub(super) fn trim(&self, out: &mut Bisector, profiles: [&Profile; 2]) {
        if !self.opts.trimmed {
            return;
        }
        let slack = TRIM_SLACK * self.diag;
        let foot = |k: usize, u: f64| profiles[k].jet(u).p.arr();
        // No point of either profile nearer than the foot point (less the slack): proven on
        // the control hulls where rounding allows, else by the nearest point found (which
        // stops once one nearer is found).
        let keeps = |tr: [f64; 2], x: [f64; 2]| {
            let f = foot(0, tr[0]);
            let r = (x[0] - f[0]).hypot(x[1] - f[1]) - slack;
            profiles.iter().all(|p| match p.clearance(x, r) {
                Clearance::Clear => true,
                Clearance::Entered { .. } => false,
                Clearance::Unresolved => p.nearest(x, r).distance >= r,
            })
        };
        let mut branches = Vec::new();
        for b in out.branches.drain(..) {
            let mut cur: Option<Branch> = None;
            for (tr, xy) in b.tr.iter().zip(&b.xy) {
                if keeps(*tr, *xy) {
                    let c = cur.get_or_insert_with(|| Branch {
                        tr: Vec::new(),
                        xy: Vec::new(),
                        ..b.clone()
                    });
                    c.tr.push(*tr);
                    c.xy.push(*xy);
                } else if let Some(c) = cur.take() {
                    if c.xy.len() >= 2 {
                        branches.push(c);
                    }
                }
            }
            if let Some(c) = cur.filter(|c| c.xy.len() >= 2) {
                branches.push(c);
            }
        }
        out.branches = branches;
        for list in [&mut out.singular, &mut out.isolated] {
            list.retain(|p| keeps(p.tr, p.xy));
        }
    }
}
