//! Multi-part inputs (the contract's "Multi-part input"): the medial axis and the offsets of
//! each part, one answer for all, each node, edge and loop saying its part; the tolerances of
//! every part relative to the size of all of them; and the doubt a drawing casts on answers
//! when something that could be part of an outline was not read.

use curve::{box_size, box_union, Region};
use medial::MedialAxis;
use offset::Offsets;

/// max(width, height) of the bounding box of all the parts (the contract's size).
pub(super) fn size_of(parts: &[&Region]) -> f64 {
    let boxes = parts.iter().map(|r| r.bounding_box());
    box_size(boxes.reduce(box_union).unwrap_or([0.0; 4]))
}

/// Why an answer over parts is not certified: the first part's reason that is not (named
/// when there are several parts), or the drawing's `doubt`.
fn reason(reasons: Vec<Option<String>>, doubt: Option<String>) -> Option<String> {
    let several = reasons.len() > 1;
    let first = reasons
        .into_iter()
        .enumerate()
        .find_map(|(k, r)| r.map(|r| if several { format!("part {k}: {r}") } else { r }));
    first.or(doubt)
}

/// The verdict over parts, each `(certified, complete, reason)`: certified where every part is
/// and the drawing casts no `doubt` (else the first reason), complete where every part is.
fn verdict(
    parts: Vec<(bool, bool, Option<String>)>,
    doubt: Option<String>,
) -> (bool, bool, Option<String>) {
    let certified = parts.iter().all(|p| p.0) && doubt.is_none();
    let complete = parts.iter().all(|p| p.1);
    let reasons = parts.into_iter().map(|p| p.2).collect();
    let why = if certified {
        None
    } else {
        reason(reasons, doubt)
    };
    (certified, complete, why)
}

/// The axes of the parts as one axis: nodes renumbered, each node and edge with its part
/// where there are several; certified and complete where every part's is and the drawing
/// casts no `doubt`.
pub(super) fn joined_axes(axes: Vec<MedialAxis>, doubt: Option<String>) -> MedialAxis {
    let several = axes.len() > 1;
    let (certified, complete, reason) = verdict(
        axes.iter()
            .map(|a| (a.certified, a.complete, a.reason.clone()))
            .collect(),
        doubt,
    );
    let (mut nodes, mut edges) = (Vec::new(), Vec::new());
    for (k, axis) in axes.into_iter().enumerate() {
        let part = several.then_some(k);
        let first = nodes.len();
        nodes.extend(axis.nodes.into_iter().map(|mut n| {
            n.id += first;
            n.part = part;
            n
        }));
        edges.extend(axis.edges.into_iter().map(|mut e| {
            e.from += first;
            e.to += first;
            e.part = part;
            e
        }));
    }
    MedialAxis {
        nodes,
        edges,
        certified,
        reason,
        complete,
    }
}

/// The offsets of the parts as one answer: at each distance the loops of every part in turn,
/// each with its part where there are several, and the largest error.
pub(super) fn joined_offsets(found: Vec<Offsets>, doubt: Option<String>) -> Offsets {
    let several = found.len() > 1;
    let (certified, complete, reason) = verdict(
        found
            .iter()
            .map(|o| (o.certified, o.complete, o.reason.clone()))
            .collect(),
        doubt,
    );
    let mut offsets: Vec<offset::Offset> = Vec::new();
    for (k, part) in found.into_iter().enumerate() {
        for (i, mut o) in part.offsets.into_iter().enumerate() {
            for l in &mut o.loops {
                l.part = several.then_some(k);
            }
            match offsets.get_mut(i) {
                Some(joined) => {
                    joined.loops.append(&mut o.loops);
                    joined.error = joined.error.max(o.error);
                }
                None => offsets.push(o),
            }
        }
    }
    Offsets {
        offsets,
        certified,
        reason,
        complete,
    }
}

/// The V-carvings of the parts as one: each path with its part (from 0), the flats of every
/// part in turn (with their part where there are several).
pub(super) fn joined_carves(found: Vec<offset::VCarve>, doubt: Option<String>) -> offset::VCarve {
    let several = found.len() > 1;
    let (certified, complete, reason) = verdict(
        found
            .iter()
            .map(|c| (c.certified, c.complete, c.reason.clone()))
            .collect(),
        doubt,
    );
    let (angle, max_depth) = found
        .first()
        .map_or((0.0, None), |c| (c.angle, c.max_depth));
    let (mut paths, mut flats) = (Vec::new(), Vec::new());
    for (k, carve) in found.into_iter().enumerate() {
        paths.extend(carve.paths.into_iter().map(|mut p| {
            p.part = k;
            p
        }));
        flats.extend(carve.flats.into_iter().map(|mut l| {
            l.part = several.then_some(k);
            l
        }));
    }
    offset::VCarve {
        angle,
        max_depth,
        paths,
        flats,
        certified,
        reason,
        complete,
    }
}
