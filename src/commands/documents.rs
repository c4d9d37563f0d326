//! The JSON documents the tool prints with `--json`: a result's fields, the curves it is of,
//! what their drawings said, and the timing.

use crate::io::Curve;
use serde::{Deserialize, Serialize};
use serde_json::{json, Value};

/// The median time of one run, as `--time` reports it (the `stats` of a JSON document).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Stats {
    /// Median time of one warm run (on a prepared curve), in microseconds.
    pub median_us: f64,
    /// How many runs the median is taken over.
    pub runs: usize,
    /// Median time of one cold run (preparing the curve read and answering once).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cold_median_us: Option<f64>,
    /// How many cold runs.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cold_runs: Option<usize>,
}

/// One JSON document, as the tool prints it with `--json`: the result's own fields (as the
/// contract names them), then the extensions `curve` (or `curves`, for two) and, when timed,
/// `stats`; one line, ending in a newline.
pub fn json_document(result: &impl Serialize, curves: &[&Curve], stats: Option<&Stats>) -> String {
    let summaries: Vec<CurveSummary> = curves.iter().map(|c| CurveSummary::of(c)).collect();
    json_document_of(result, &summaries, stats)
}

/// [`json_document`] with the curves given by their summaries (a result kept apart from its
/// curves, as a Python result is).
pub fn json_document_of(
    result: &impl Serialize,
    curves: &[CurveSummary],
    stats: Option<&Stats>,
) -> String {
    let mut doc = serde_json::to_value(result).unwrap_or(Value::Null);
    if let Some(map) = doc.as_object_mut() {
        // (The contract's "Nothing is dropped silently": for a drawing, what was not read and
        // its units, beside the result's own fields.)
        let drawings: Vec<&DrawingSummary> =
            curves.iter().filter_map(|c| c.drawing.as_ref()).collect();
        if !drawings.is_empty() {
            let skipped: Vec<Value> = drawings
                .iter()
                .flat_map(|d| &d.skipped)
                .map(crate::io::Skipped::entry)
                .collect();
            map.insert("skipped".into(), Value::Array(skipped));
            if let Some(units) = drawings.iter().find_map(|d| d.units.as_ref()) {
                map.insert("units".into(), json!(units));
            }
        }
        match curves {
            [one] => {
                map.insert("curve".into(), json!(one));
            }
            many => {
                map.insert("curves".into(), json!(many));
            }
        }
        if let Some(s) = stats {
            map.insert("stats".into(), json!(s));
        }
    }
    format!("{doc}\n")
}

/// The `curve` object of JSON reports (an extension: which curve the numbers belong to).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CurveSummary {
    /// The file as named (or the name given to a curve made in memory).
    pub file: String,
    /// Its `kind`.
    pub kind: String,
    /// Closed or open.
    pub closed: bool,
    /// The parameter domain.
    pub domain: [f64; 2],
    /// For a drawing, what was not read and its units (written beside the result's fields,
    /// not in the curve's).
    #[serde(skip)]
    pub drawing: Option<DrawingSummary>,
}

/// What a drawing said besides its geometry, as a result carries it.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct DrawingSummary {
    /// What was not read, by type.
    pub skipped: Vec<crate::io::Skipped>,
    /// The unit of the coordinates, where the drawing says.
    pub units: Option<String>,
}

impl CurveSummary {
    /// The summary of `curve`.
    pub fn of(curve: &Curve) -> Self {
        let (a, b) = curve.domain();
        Self {
            file: curve.file.clone(),
            kind: curve.kind().into(),
            closed: curve.is_closed(),
            domain: [a, b],
            drawing: curve.drawing.as_ref().map(|d| DrawingSummary {
                skipped: d.skipped.clone(),
                units: d.units.clone(),
            }),
        }
    }
}
