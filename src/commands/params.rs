//! Results in their inputs' own parameters (the contract's "Parameters, sizes and drawings"):
//! the algorithms report parameters of the exact forms they ran on (an arc's rational pieces,
//! a profile's cut segments, a curve taken as a profile); here every `s`, `t`, `u`, `feet`,
//! `bracket` and `segment` is mapped to the parameter its document gives, before the result
//! leaves the tool.

use curve::{ParamCurve, Profile, Region, Segment};

/// How one input's exact-form parameters map to its document's.
#[derive(Clone, Copy)]
pub(crate) enum DocMap<'a> {
    /// They are the document's (a spline or an analytic shape on the smooth path).
    Own,
    /// A line or an arc given on its own: the arc's angle share.
    Segment(&'a Segment),
    /// A profile (or a curve taken as one): its document spans.
    Profile(&'a Profile),
}

impl DocMap<'_> {
    /// The document parameter of `u`.
    pub(crate) fn param(&self, u: f64) -> f64 {
        match self {
            DocMap::Own => u,
            DocMap::Segment(s) => s.own_at(u),
            DocMap::Profile(p) => p.document_param(u),
        }
    }

    /// The document parameter of `u`, which on a closed profile may lie beyond its domain
    /// (a bracket or a family across the seam): whole turns are carried over.
    pub(crate) fn unwrapped(&self, u: f64) -> f64 {
        let DocMap::Profile(p) = self else {
            return self.param(u);
        };
        let n = p.domain().1;
        let turns = (u / n).floor();
        if turns == 0.0 || !p.is_closed() {
            return p.document_param(u);
        }
        let (lo, hi) = p.document_domain();
        p.document_param(u - turns * n) + turns * (hi - lo)
    }

    /// The document's segment of segment `i`.
    pub(crate) fn segment(&self, i: usize) -> usize {
        match self {
            DocMap::Profile(p) => p.document_segment(i),
            _ => i,
        }
    }
}

/// A result whose parameters are mapped to its inputs' documents.
pub(crate) trait InDocument {
    /// Maps every parameter, with `maps[k]` for input `k` (one map for a one-curve result).
    fn in_document(&mut self, maps: &[DocMap<'_>]);

    /// The result with its parameters mapped, as [`InDocument::in_document`] maps them.
    fn into_document(mut self, maps: &[DocMap<'_>]) -> Self
    where
        Self: Sized,
    {
        self.in_document(maps);
        self
    }
}

fn inflections(list: &mut [antipodal::Inflection], m: &DocMap<'_>) {
    for f in list {
        f.u = m.param(f.u);
        f.bracket = f.bracket.map(|[a, b]| [m.unwrapped(a), m.unwrapped(b)]);
        f.segment = f.segment.map(|i| m.segment(i));
    }
}

fn corners(list: &mut [antipodal::Corner], m: &DocMap<'_>) {
    for c in list {
        c.u = m.param(c.u);
    }
}

impl InDocument for antipodal::Inflections {
    fn in_document(&mut self, maps: &[DocMap<'_>]) {
        inflections(&mut self.inflections, &maps[0]);
        if let Some(list) = &mut self.corners {
            corners(list, &maps[0]);
        }
    }
}

impl InDocument for antipodal::Antipodal {
    fn in_document(&mut self, maps: &[DocMap<'_>]) {
        let m = &maps[0];
        for p in &mut self.pairs {
            (p.s, p.t) = (m.param(p.s), m.param(p.t));
            p.segment = p.segment.map(|ij| ij.map(|i| m.segment(i)));
        }
        for f in &mut self.families {
            f.s = f.s.map(|u| m.unwrapped(u));
            f.t = f.t.map(|u| m.unwrapped(u));
        }
        inflections(&mut self.inflections, m);
        if let Some(list) = &mut self.corners {
            corners(list, m);
        }
    }
}

impl InDocument for antipodal::Tangents {
    fn in_document(&mut self, maps: &[DocMap<'_>]) {
        for l in &mut self.lines {
            (l.s, l.t) = (maps[0].param(l.s), maps[1].param(l.t));
            l.segment = l
                .segment
                .map(|[i, j]| [maps[0].segment(i), maps[1].segment(j)]);
        }
    }
}

/// The maps of a bisector's `t` and `r` (a self-bisector's both on its one curve).
fn pair<'m, 'a>(maps: &'m [DocMap<'a>]) -> (&'m DocMap<'a>, &'m DocMap<'a>) {
    (&maps[0], maps.get(1).unwrap_or(&maps[0]))
}

impl InDocument for zeroset::Bisector {
    fn in_document(&mut self, maps: &[DocMap<'_>]) {
        let (mt, mr) = pair(maps);
        let map = |tr: &mut [f64; 2]| *tr = [mt.param(tr[0]), mr.param(tr[1])];
        let segments = |s: Option<[usize; 2]>| s.map(|[t, r]| [mt.segment(t), mr.segment(r)]);
        for b in &mut self.branches {
            b.tr.iter_mut().for_each(map);
            b.segment = segments(b.segment);
        }
        for p in self.singular.iter_mut().chain(&mut self.isolated) {
            map(&mut p.tr);
            p.segment = segments(p.segment);
        }
    }
}

/// The maps of a region's boundaries, in the medial axis's numbering (0 the outer one).
pub(crate) fn region_maps(region: &Region) -> Vec<DocMap<'_>> {
    std::iter::once(region.outer())
        .chain(region.holes())
        .map(DocMap::Profile)
        .collect()
}

impl InDocument for medial::MedialAxis {
    fn in_document(&mut self, maps: &[DocMap<'_>]) {
        for e in &mut self.edges {
            for (feet, on) in e.feet.iter_mut().zip(&e.boundary) {
                for k in 0..2 {
                    if let Some(m) = maps.get(on[k]) {
                        feet[k] = m.param(feet[k]);
                    }
                }
            }
        }
    }
}
