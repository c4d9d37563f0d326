//! An independent evaluator of curve documents by the contract's parameters ("Curve files",
//! "Profiles", "Parameters, sizes and drawings"): de Boor's algorithm on the knots as written
//! (periodic ones wrapped), the analytic kinds' formulas, an arc by its angle, a profile by
//! segment. It shares no code with the tool: a parameter the tool reports must name the
//! point it reports under this reading.
#![allow(dead_code, clippy::unwrap_used)]

use serde_json::Value;
use std::f64::consts::TAU;

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap()
}

fn point(v: &Value) -> [f64; 2] {
    [num(&v[0]), num(&v[1])]
}

fn points(v: &Value) -> Vec<[f64; 2]> {
    v.as_array().unwrap().iter().map(point).collect()
}

/// The domain of a curve document's parameter.
pub(crate) fn domain(doc: &Value) -> (f64, f64) {
    match doc["kind"].as_str().unwrap() {
        "bezier" | "line" | "arc" => (0.0, 1.0),
        "bspline" => {
            let (k, _, _, _) = bspline_data(doc);
            let p = doc["degree"].as_u64().unwrap() as usize;
            let n = doc["points"].as_array().unwrap().len();
            if doc["periodic"].as_bool() == Some(true) {
                (0.0, n as f64)
            } else {
                (k[p], k[n])
            }
        }
        "profile" => (0.0, doc["segments"].as_array().unwrap().len() as f64),
        _ => (0.0, TAU),
    }
}

/// Knots, homogeneous control points `(wx, wy, w)` and degree of a `bspline` or `bezier`
/// document (a periodic one with its points wrapped and uniform knots from −p), and whether
/// it is periodic.
fn bspline_data(doc: &Value) -> (Vec<f64>, Vec<[f64; 3]>, usize, bool) {
    let pts = points(&doc["points"]);
    let n = pts.len();
    let weights: Vec<f64> = match doc.get("weights") {
        Some(w) => w.as_array().unwrap().iter().map(num).collect(),
        None => vec![1.0; n],
    };
    let hom = |i: usize| {
        let (p, w) = (pts[i % n], weights[i % n]);
        [p[0] * w, p[1] * w, w]
    };
    if doc["kind"] == "bezier" {
        let p = n - 1;
        let mut k = vec![0.0; p + 1];
        k.extend(vec![1.0; p + 1]);
        return (k, (0..n).map(hom).collect(), p, false);
    }
    let p = doc["degree"].as_u64().unwrap() as usize;
    if doc["periodic"].as_bool() == Some(true) {
        // Uniform knots from −p: the span [i, i+1] is shaped by list entries i..=i+p, the
        // points i.. wrapped.
        let k: Vec<f64> = (0..n + 2 * p + 1).map(|i| i as f64 - p as f64).collect();
        return (k, (0..n + p).map(hom).collect(), p, true);
    }
    let k = match doc.get("knots") {
        Some(k) => k.as_array().unwrap().iter().map(num).collect(),
        None => {
            let inner = n - p - 1;
            let mut k = vec![0.0; p + 1];
            k.extend((1..=inner).map(|i| i as f64 / (inner + 1) as f64));
            k.extend(vec![1.0; p + 1]);
            k
        }
    };
    (k, (0..n).map(hom).collect(), p, false)
}

/// de Boor's algorithm at `u` on homogeneous control points.
fn de_boor(k: &[f64], ctrl: &[[f64; 3]], p: usize, u: f64) -> [f64; 2] {
    let n = ctrl.len();
    let mut span = p;
    while span + 1 < n && k[span + 1] <= u {
        span += 1;
    }
    let mut d: Vec<[f64; 3]> = (0..=p).map(|j| ctrl[j + span - p]).collect();
    for r in 1..=p {
        for j in (r..=p).rev() {
            let i = j + span - p;
            let den = k[i + p + 1 - r] - k[i];
            let a = if den == 0.0 { 0.0 } else { (u - k[i]) / den };
            let (prev, cur) = (d[j - 1], d[j]);
            d[j] = [0, 1, 2].map(|c| (1.0 - a) * prev[c] + a * cur[c]);
        }
    }
    [d[p][0] / d[p][2], d[p][1] / d[p][2]]
}

/// The point of a curve document at its parameter `u` (the contract's).
pub(crate) fn eval(doc: &Value, u: f64) -> [f64; 2] {
    let center = || doc.get("center").map(point).unwrap_or([0.0, 0.0]);
    let polar = |r: f64| [r * u.cos(), r * u.sin()];
    match doc["kind"].as_str().unwrap() {
        "line" => {
            let (a, b) = (point(&doc["from"]), point(&doc["to"]));
            [a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])]
        }
        "arc" => {
            let (c, r) = (point(&doc["center"]), num(&doc["r"]));
            let (s, e) = (num(&doc["start"]), num(&doc["end"]));
            let t = s + u * (e - s);
            [c[0] + r * t.cos(), c[1] + r * t.sin()]
        }
        "circle" => {
            let (c, r) = (center(), num(&doc["r"]));
            [c[0] + r * u.cos(), c[1] + r * u.sin()]
        }
        "ellipse" => {
            let c = center();
            [
                c[0] + num(&doc["a"]) * u.cos(),
                c[1] + num(&doc["b"]) * u.sin(),
            ]
        }
        "limacon" => polar(num(&doc["a"]) + num(&doc["b"]) * u.cos()),
        "elliptic_lemniscate" => {
            let (a, b) = (num(&doc["a"]), num(&doc["b"]));
            polar((a * a * u.cos().powi(2) + b * b * u.sin().powi(2)).sqrt())
        }
        "convexities" => {
            let m = num(&doc["m"]);
            polar(num(&doc["p"]) / (1.0 + num(&doc["eps"]) * (m * u).cos()))
        }
        "bezier" | "bspline" => {
            let (k, ctrl, p, periodic) = bspline_data(doc);
            let (lo, hi) = domain(doc);
            let u = if periodic {
                u.rem_euclid(hi)
            } else {
                u.clamp(lo, hi)
            };
            de_boor(&k, &ctrl, p, u)
        }
        "profile" => {
            let segs = doc["segments"].as_array().unwrap();
            let i = (u.floor().max(0.0) as usize).min(segs.len() - 1);
            let (lo, hi) = domain(&segs[i]);
            eval(&segs[i], lo + (u - i as f64) * (hi - lo))
        }
        k => panic!("no evaluator for kind {k}"),
    }
}

/// The distance between two points.
pub(crate) fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}
