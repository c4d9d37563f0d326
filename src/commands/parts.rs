//! Multi-part inputs (the contract's "Multi-part input"): the medial axis and the offsets of
//! each part, one answer for all, each node, edge and loop saying its part; the tolerances of
//! every part relative to the size of all of them; and the doubt a drawing casts on answers
//! when something that could be part of an outline was not read.

use curve::{box_size, box_union, Region};
use medial::MedialAxis;
use numeric::certificate::{Doubt, Doubts};
use offset::Offsets;

/// max(width, height) of the bounding box of all the parts (the contract's size).
pub(super) fn size_of(parts: &[&Region]) -> f64 {
    let boxes = parts.iter().map(|r| r.bounding_box());
    box_size(boxes.reduce(box_union).unwrap_or([0.0; 4]))
}

/// The doubts of an answer over parts: each part's in turn (named by their part when there
/// are several), then the drawing's `doubt`. Its first is the first uncertified part's
/// reason, or the drawing's.
fn joined_doubts<'a>(
    parts: impl ExactSizeIterator<Item = &'a Doubts>,
    doubt: Option<Doubt>,
) -> Doubts {
    let several = parts.len() > 1;
    let mut out = Doubts::none();
    for (k, doubts) in parts.enumerate() {
        for d in doubts.iter() {
            out.add(if several {
                Doubt::InPart {
                    part: k,
                    doubt: Box::new(d.clone()),
                }
            } else {
                d.clone()
            });
        }
    }
    out.join(doubt.into_iter().collect());
    out
}

/// The axes of the parts as one axis: nodes renumbered, each node and edge with its part
/// where there are several; certified and complete where every part's is and the drawing
/// casts no `doubt`.
pub(super) fn joined_axes(axes: Vec<MedialAxis>, doubt: Option<Doubt>) -> MedialAxis {
    let several = axes.len() > 1;
    let doubts = joined_doubts(axes.iter().map(|a| &a.doubts), doubt);
    let complete = axes.iter().all(|a| a.complete);
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
        doubts,
        complete,
    }
}

/// The offsets of the parts as one answer: at each distance the loops of every part in turn,
/// each with its part where there are several, and the largest error.
pub(super) fn joined_offsets(found: Vec<Offsets>, doubt: Option<Doubt>) -> Offsets {
    let several = found.len() > 1;
    let doubts = joined_doubts(found.iter().map(|o| &o.doubts), doubt);
    let complete = found.iter().all(|o| o.complete);
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
        doubts,
        complete,
    }
}

/// The V-carvings of the parts as one: each path with its part (from 0), the flats of every
/// part in turn (with their part where there are several).
pub(super) fn joined_carves(found: Vec<offset::VCarve>, doubt: Option<Doubt>) -> offset::VCarve {
    let several = found.len() > 1;
    let doubts = joined_doubts(found.iter().map(|c| &c.doubts), doubt);
    let complete = found.iter().all(|c| c.complete);
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
        doubts,
        complete,
    }
}
