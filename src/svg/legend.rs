//! What a figure says beside its drawing, in pixels: the header (title, and whether the
//! result is certified, with why not) above the panels, and the legend column to their right
//! (a key per kind of mark, the colour bar of a scale with its ticks and units).

use super::{escape, scale_color};
use std::fmt::Write as _;

/// Pixels of one line of text (14-pixel type).
pub(super) const LINE: f64 = 20.0;
/// Width of the legend column.
pub(super) const LEGEND_WIDTH: f64 = 230.0;
/// Characters of a header line before it wraps (at 14-pixel type, about 7 pixels each).
const HEADER_CHARS: usize = 110;
/// Characters of a legend label before it wraps.
const LEGEND_CHARS: usize = 26;
/// Height of the colour bar.
const BAR_HEIGHT: f64 = 180.0;
/// Ticks on the colour bar (ends included).
const TICKS: usize = 5;
/// Bands the colour bar is drawn in.
const BAR_BANDS: usize = 32;

/// How a legend entry's mark is drawn.
#[derive(Debug, Clone, PartialEq)]
pub enum Mark {
    /// A line of a colour and width (pixels).
    Line(String, f64),
    /// A dashed grey line (segments between points: antipodal pairs, tangent lines).
    Dashed,
    /// A filled dot of a colour.
    Dot(String),
    /// A hollow square (a profile's corner).
    Square,
    /// A hollow circle (a disk).
    Ring(String),
}

/// One entry of the legend.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Entry {
    pub(super) mark: Mark,
    pub(super) label: String,
}

/// A colour scale: what it measures, its range and unit.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct ColorBar {
    pub(super) quantity: String,
    pub(super) lo: f64,
    pub(super) hi: f64,
    pub(super) units: Option<String>,
}

/// Whether the result is certified, and why not.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Status {
    pub(super) certified: bool,
    pub(super) reason: Option<String>,
}

/// `text` cut into lines of at most `width` characters, at spaces where it can.
fn wrapped(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() || lines.is_empty() {
        lines.push(line);
    }
    lines
}

/// A line of text at pixel `(x, y)` (its baseline), in `color`, bold where asked.
fn text_at(s: &mut String, x: f64, y: f64, text: &str, color: &str, bold: bool) {
    let weight = if bold { r#" font-weight="bold""# } else { "" };
    let _ = writeln!(
        s,
        r#"<text x="{x:.1}" y="{y:.1}" font-size="14" font-family="sans-serif" fill="{color}"{weight}>{}</text>"#,
        escape(text)
    );
}

/// The header's lines: the title, then the status (green when certified, red with why not).
pub(super) fn header_lines(
    title: Option<&str>,
    status: Option<&Status>,
) -> Vec<(String, &'static str, bool)> {
    let mut lines = Vec::new();
    if let Some(t) = title {
        lines.extend(
            wrapped(t, HEADER_CHARS)
                .into_iter()
                .map(|l| (l, "#222222", true)),
        );
    }
    if let Some(st) = status {
        if st.certified {
            lines.push(("certified".to_string(), "#1d7a35", false));
        } else {
            let why = st.reason.as_deref().unwrap_or("no reason given");
            let text = format!("not certified: {why}");
            lines.extend(
                wrapped(&text, HEADER_CHARS)
                    .into_iter()
                    .map(|l| (l, "#b3261e", false)),
            );
        }
    }
    lines
}

/// Draws the header's lines from the top.
pub(super) fn header(s: &mut String, lines: &[(String, &'static str, bool)]) {
    for (k, (line, color, bold)) in lines.iter().enumerate() {
        text_at(s, 8.0, LINE * (k as f64 + 1.0) - 4.0, line, color, *bold);
    }
}

/// A number for a tick: three significant digits, plain where it reads so.
fn tick(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let magnitude = x.abs().log10().floor();
    if !(-3.0..6.0).contains(&magnitude) {
        return format!("{x:.2e}");
    }
    let decimals = (2.0 - magnitude).max(0.0) as usize;
    let s = format!("{x:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// Draws the legend column at pixel `x` from `top`: the colour bar (if any), then the entries;
/// its height.
pub(super) fn legend(
    s: &mut String,
    x: f64,
    top: f64,
    bar: Option<&ColorBar>,
    entries: &[Entry],
) -> f64 {
    let mut y = top;
    if let Some(bar) = bar {
        let title = match &bar.units {
            Some(u) => format!("{} ({u})", bar.quantity),
            None => bar.quantity.clone(),
        };
        text_at(s, x, y + 14.0, &title, "#222222", true);
        y += LINE + 4.0;
        let band = BAR_HEIGHT / BAR_BANDS as f64;
        // (Top is the scale's high end, as a reader expects of a vertical bar.)
        for k in 0..BAR_BANDS {
            let t = 1.0 - (k as f64 + 0.5) / BAR_BANDS as f64;
            let _ = writeln!(
                s,
                r#"<rect x="{x:.1}" y="{:.1}" width="16" height="{:.2}" fill="{}"/>"#,
                y + band * k as f64,
                band + 0.3,
                scale_color(t)
            );
        }
        let _ = writeln!(
            s,
            r##"<rect x="{x:.1}" y="{y:.1}" width="16" height="{BAR_HEIGHT}" fill="none" stroke="#444444" stroke-width="0.8"/>"##
        );
        for k in 0..TICKS {
            let f = k as f64 / (TICKS - 1) as f64;
            let ty = y + BAR_HEIGHT * (1.0 - f);
            let value = bar.lo + f * (bar.hi - bar.lo);
            let _ = writeln!(
                s,
                r##"<line x1="{:.1}" y1="{ty:.1}" x2="{:.1}" y2="{ty:.1}" stroke="#444444" stroke-width="0.8"/>"##,
                x + 16.0,
                x + 21.0
            );
            text_at(s, x + 25.0, ty + 5.0, &tick(value), "#222222", false);
        }
        y += BAR_HEIGHT + LINE;
    }
    for e in entries {
        let mid = y + 10.0;
        match &e.mark {
            Mark::Line(color, width) => {
                let _ = writeln!(
                    s,
                    r#"<line x1="{x:.1}" y1="{mid:.1}" x2="{:.1}" y2="{mid:.1}" stroke="{color}" stroke-width="{width}"/>"#,
                    x + 22.0
                );
            }
            Mark::Dashed => {
                let _ = writeln!(
                    s,
                    r##"<line x1="{x:.1}" y1="{mid:.1}" x2="{:.1}" y2="{mid:.1}" stroke="#444444" stroke-width="1" stroke-dasharray="4 3"/>"##,
                    x + 22.0
                );
            }
            Mark::Dot(color) => {
                let _ = writeln!(
                    s,
                    r#"<circle cx="{:.1}" cy="{mid:.1}" r="4" fill="{color}"/>"#,
                    x + 11.0
                );
            }
            Mark::Square => {
                let _ = writeln!(
                    s,
                    r##"<rect x="{:.1}" y="{:.1}" width="9" height="9" fill="none" stroke="#1f5fbf" stroke-width="1.5"/>"##,
                    x + 6.5,
                    mid - 4.5
                );
            }
            Mark::Ring(color) => {
                let _ = writeln!(
                    s,
                    r#"<circle cx="{:.1}" cy="{mid:.1}" r="7" fill="none" stroke="{color}" stroke-width="1"/>"#,
                    x + 11.0
                );
            }
        }
        for (k, line) in wrapped(&e.label, LEGEND_CHARS).iter().enumerate() {
            text_at(
                s,
                x + 30.0,
                mid + 5.0 + LINE * k as f64,
                line,
                "#222222",
                false,
            );
            y += LINE;
        }
        y += 4.0;
    }
    y - top
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_text_wraps_at_spaces_and_ticks_read_short() {
        assert_eq!(wrapped("a bb ccc dddd", 6), ["a bb", "ccc", "dddd"]);
        assert_eq!(wrapped("", 6), [""]);
        assert_eq!(tick(0.0), "0");
        assert_eq!(tick(2.5), "2.5");
        assert_eq!(tick(1234.5678), "1235");
        assert_eq!(tick(0.012345), "0.0123");
        assert_eq!(tick(1e-7), "1.00e-7");
    }
}
