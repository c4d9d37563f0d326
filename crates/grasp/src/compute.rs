//! The computation of every force-closure grasp of a prepared curve or profile.

use crate::assemble::{regions, RawRegion};
use crate::best::{descend, most_robust, ANTIPODAL_ANGLE};
use crate::cells::{cells, trace};
use crate::contact::{around, square_at_most, Positivity};
use crate::corners::corner_lines;
use crate::error::Result;
use crate::model::Model;
use crate::near::NearContacts;
use crate::options::GraspOptions;
use crate::polyline::{bounds, signed_area};
use crate::proof::{none_below, Below, LowerSets};
use crate::quality::{force_closure, min_friction};
use crate::region_set::{deepest, depth, holds_or_touches, in_triangle};
use crate::spared::Spared;
use crate::types::{BestGrasp, ContactRegion, GraspRegion, Grasps};
use curve::follow_image;
use numeric::certificate::{Doubt, Doubts};

/// [`crate::grasps`] of a prepared model, whose antipodal pairs and families' middles (in the
/// profile's parameter) are `seeds`, for options already checked.
pub(crate) fn grasps_of(
    model: &Model<'_>,
    seeds: &[[f64; 2]],
    opts: &GraspOptions,
) -> Result<Grasps> {
    let widths =
        [opts.min_width, opts.max_width].map(|w| w.map(|w| model.frame.length_to_local(w)));
    let cells = cells(model, opts, widths)?;
    let near = NearContacts::new(model, opts.friction);
    let mut doubts = Doubts::none();
    let mut complete = true;
    let mut traced = Vec::with_capacity(cells.len());
    for cell in &cells {
        let t = trace(model, cell, opts, &near)?;
        complete &= t.complete;
        traced.push(((cell.i, cell.j), t));
    }
    if !complete {
        doubts.add(Doubt::SearchLimit);
    }
    let mut line_doubts = Doubts::none();
    let lines = corner_lines(model, opts.friction, widths, None, &mut line_doubts)?;
    // A corner line's end left unproven may join two regions or part one: as with an
    // unresolved boundary, no region's identity is proven then.
    let lines_unproven = !line_doubts.is_empty();
    doubts.join(line_doubts);
    // (The chord tolerance of the cells, in the profile's parameter where a cell is a unit.)
    let chord = opts.settings.chord_tol.get() * std::f64::consts::SQRT_2;
    let alpha = opts.friction.atan();
    let holds = |p: [f64; 2]| force_closure(model, alpha, widths, p);
    let raw = regions(model, &traced, &lines, chord, &holds);
    let proof = Positivity::new(model, &cells);
    // (A cell's unresolved point is said even where no region came of it.)
    let cell_unresolved = traced.iter().any(|(_, t)| t.unresolved);
    if cell_unresolved {
        doubts.add(Doubt::GraspBoundaryUnresolved);
    }
    // Every antipodal pair within the width limits is force closure at any friction: one
    // that no region holds was lost (regions narrower than the subdivision resolves).
    let lost = seeds.iter().any(|&p| {
        force_closure(model, alpha.max(ANTIPODAL_ANGLE), widths, p)
            && !raw.iter().any(|r| holds_or_touches(r, model.n(), p, chord))
    });
    if lost {
        doubts.add(Doubt::GraspPairLost);
    }
    let unresolved = lines_unproven
        || lost
        || cell_unresolved
        || raw.iter().any(|r| {
            r.doubts
                .iter()
                .any(|d| *d == Doubt::GraspBoundaryUnresolved)
        });
    let mut found = Vec::with_capacity(raw.len());
    for r in &raw {
        let (mut center, mut proven) = most_robust(model, r, seeds, alpha, chord);
        // A best grasp found by search is proven the most robust (to a share of its friction)
        // where the set at a friction just below holds no pair of the region; a pair of it
        // that does starts the search again.
        let mut traced: Option<LowerSets> = None;
        for _ in 0..PROOF_ROUNDS {
            let least = min_friction(model, center[0], center[1]);
            if proven || !(least > 0.0 && least.is_finite()) {
                break;
            }
            let lower = traced.insert(LowerSets::new(least, r));
            match none_below(model, opts, widths, r, lower, chord, &Spared::default())? {
                Below::None => proven = true,
                Below::Unknown => break,
                Below::Beaten(p) => {
                    let (x, _) = descend(model, r, p, chord);
                    center = in_triangle(model.n(), x[0], x[1]);
                }
            }
        }
        // Where the least friction falls toward a joint's line the region does not hold (a
        // reflex corner, or two joints at one point), no pair attains it: what is proven is
        // that only pairs with a finger beside that joint need less than the best found.
        let mut toward = Spared::default();
        if !proven {
            let least = min_friction(model, center[0], center[1]);
            let spared = Spared::toward(model, r, center, chord);
            // (The plain proof's traces, where it was tried at this friction.)
            let mut lower = match traced {
                Some(t) if t.least == least => t,
                _ => LowerSets::new(least, r),
            };
            if !spared.is_empty()
                && least > 0.0
                && least.is_finite()
                && none_below(model, opts, widths, r, &mut lower, chord, &spared)? == Below::None
            {
                proven = true;
                toward = spared;
            }
        }
        let mut region_doubts = r.doubts.clone();
        if !proven {
            region_doubts.add(Doubt::GraspBestUnproven);
        }
        // (The parts' polylines are within a chord of the region's edge.)
        let reach = r
            .parts
            .iter()
            .map(|p| bounds(p))
            .fold([0.0f64; 2], |m, (lo, hi)| {
                [m[0].max(hi[0] - lo[0]), m[1].max(hi[1] - lo[1])]
            })
            .map(|x| x + 2.0 * chord);
        // The largest square is sought round the best grasp, and round the points of the
        // region deepest inside it where that one is clearly smaller (the best grasp may lie
        // on a width limit, or off the region's middle).
        let at_best = around(model, &proof, center, reach);
        // (Only where the best grasp lies clearly nearer the region's edge than its deepest
        // points: elsewhere its square is the one to find.)
        let candidates = deepest(r, CONTACT_CENTERS);
        let best_depth = depth(r, center);
        // (A centre whose square cannot come clearly larger is not searched: its region's
        // edge lies within a chord of the polylines.)
        let beaten = |c: [f64; 2], d: f64| {
            at_best
                .is_some_and(|b| square_at_most(model, c, d + 2.0 * chord) <= b.2 * CLEARLY_LARGER)
        };
        let deeper = candidates
            .into_iter()
            .filter(|&(_, d)| at_best.is_none() || d > DEEPER * best_depth)
            .filter(|&(c, d)| !beaten(c, d))
            .filter_map(|(c, _)| around(model, &proof, c, reach))
            .max_by(|a, b| a.2.total_cmp(&b.2));
        let contact = match (at_best, deeper) {
            (Some(b), Some(d)) if d.2 > b.2 * CLEARLY_LARGER => Some(d),
            (None, d) => d,
            (b, _) => b,
        }
        .map(|(s, t, _)| (s, t));
        // A boundary or corner line left unresolved anywhere may have cut a region in two or
        // joined two: no region's identity is proven then.
        let certified = r.doubts.is_empty() && !unresolved;
        doubts.join(region_doubts);
        found.push(output(model, chord, r, center, &toward, contact, certified));
    }
    Ok(Grasps {
        friction: opts.friction,
        min_width: opts.min_width,
        max_width: opts.max_width,
        regions: found,
        doubts,
        complete,
    })
}

/// A contact region round another centre replaces the one round the best grasp when its
/// square is this much larger.
const CLEARLY_LARGER: f64 = 1.1;

/// Halvings of a chord whose image in the document's parameter bends.
const IMAGE_DEPTH: usize = 8;

/// A deeper point is tried as a contact region's centre when it lies this many times deeper
/// than the best grasp.
const DEEPER: f64 = 2.0;

/// Times a best grasp found by search is beaten by the set at a friction just below and
/// searched again from the pair that beat it, before it is left unproven.
const PROOF_ROUNDS: usize = 3;

/// Centres tried for a region's contact region besides its best grasp.
const CONTACT_CENTERS: usize = 4;

/// A region in the curve's own parameter and coordinates.
fn output(
    model: &Model<'_>,
    chord: f64,
    r: &RawRegion,
    center: [f64; 2],
    toward: &Spared,
    contact: Option<([f64; 2], [f64; 2])>,
    certified: bool,
) -> GraspRegion {
    let doc = |p: [f64; 2]| [model.document_param(p[0]), model.document_param(p[1])];
    // The polylines are straight in the forms' parameters (their distance from the boundary
    // was measured in the document's, [`crate::cells::trace`]); where the document's parameter
    // is not linear in them (an analytic shape's angle against its rational circle's), a chord
    // is followed by its image, halved until its middle lies on the mapped chord.
    let tol = chord * model.document_cell();
    let polyline = |pts: &[[f64; 2]]| -> Vec<[f64; 2]> {
        let mut out: Vec<[f64; 2]> = Vec::with_capacity(pts.len());
        let mut mids = Vec::new();
        for w in pts.windows(2) {
            out.push(doc(w[0]));
            mids.clear();
            follow_image(&|p| Some(doc(p)), w[0], w[1], tol, IMAGE_DEPTH, &mut mids);
            out.extend(mids.iter().map(|&m| doc(m)));
        }
        if let Some(&last) = pts.last() {
            out.push(doc(last));
        }
        // (Pieces meet end to end: their shared vertices once. A single pair stays two.)
        out.dedup();
        if out.len() == 1 {
            out.push(out[0]);
        }
        out
    };
    let mut parts: Vec<Vec<[f64; 2]>> = r.parts.iter().map(|p| polyline(p)).collect();
    parts.sort_by(|x, y| signed_area(y).total_cmp(&signed_area(x)));
    // Pairs with a finger at a corner, as stretches there and back (the longest first), and
    // single pairs: parts without area, after those with (nothing is left out).
    let mut lines: Vec<&[[f64; 2]; 2]> = r.lines.iter().collect();
    let len = |l: &[[f64; 2]; 2]| (l[1][0] - l[0][0]).hypot(l[1][1] - l[0][1]);
    lines.sort_by(|a, b| len(b).total_cmp(&len(a)));
    parts.extend(lines.iter().map(|l| polyline(&[l[0], l[1], l[0]])));
    parts.extend(r.points.iter().map(|&p| polyline(&[p, p])));
    let boundary = parts.first().cloned().unwrap_or_default();
    if parts.len() == 1 {
        parts.clear();
    }
    GraspRegion {
        boundary,
        parts,
        holes: r.holes.iter().map(|h| polyline(h)).collect(),
        contact: contact.map(|(s, t)| ContactRegion {
            s: s.map(|u| model.document_param(u)),
            t: t.map(|u| model.document_param(u)),
            p: s.map(|u| model.global_point(u)),
            q: t.map(|u| model.global_point(u)),
        }),
        best: BestGrasp {
            s: model.document_param(center[0]),
            t: model.document_param(center[1]),
            p: model.global_point(center[0]),
            q: model.global_point(center[1]),
            min_friction: min_friction(model, center[0], center[1]),
            toward: toward
                .joints
                .iter()
                .map(|&k| [k - toward.by, k + toward.by].map(|u| model.document_param(u)))
                .collect(),
        },
        certified,
    }
}
