//! A small SVG writer for result figures: polylines, dots, numbered segments and labels,
//! with the view box fitted to the content and y pointing up; above the drawing a header (the
//! title, whether the result is certified and why not), beside it a legend (a key per mark, a
//! colour bar with ticks and units). Numbers on the drawing never overlap: one that would is
//! left out, and the legend says how many were.

mod legend;

pub use legend::Mark;

use legend::{ColorBar, Entry, Status, LEGEND_WIDTH, LINE};
use std::borrow::Cow;
use std::fmt::Write as _;

/// Colors of the figure elements (curves cycle through the first ones).
const PALETTE: [&str; 4] = ["#1f4e9c", "#2a8c4a", "#8c2a7a", "#b05a00"];

/// The colour of a region's boundaries: neutral, so that it never reads as a value of a scale.
pub const BOUNDARY: &str = "#3a3a3a";

/// The colour of a marked point (inflections, nodes that are not told apart).
pub const DOT: &str = "#d62020";

/// Pixels a number on the drawing takes per character, and its height: the box two numbers
/// must not share.
const LABEL_CHAR: f64 = 8.0;
const LABEL_HEIGHT: f64 = 15.0;

/// More dots of one kind than this are drawn small (a dense axis's hundreds of nodes would
/// cover its edges).
const MANY_DOTS: usize = 48;

/// Pixels of a stretch picked out on a curve: thick enough to read over the curve's 2.
const STRETCH_WIDTH: f64 = 5.0;

/// Opacity of a filled area: what it covers shows through.
const AREA_OPACITY: f64 = 0.45;

/// Least size of a panel's content (user units): a panel of one point, of size 0, still gets
/// a view box of nonzero width and height (else its pixel size is 0 / 0).
const MIN_SIZE: f64 = 1e-9;

enum Item {
    Polyline {
        points: Vec<[f64; 2]>,
        color: Cow<'static, str>,
        width: f64,
        closed: bool,
    },
    /// A closed polygon filled with a colour, see-through, outlined in it.
    Area {
        points: Vec<[f64; 2]>,
        color: Cow<'static, str>,
    },
    Dot {
        at: [f64; 2],
        color: Cow<'static, str>,
        /// A share of the usual radius (one of many drawn small).
        scale: f64,
    },
    Segment {
        from: [f64; 2],
        to: [f64; 2],
        label: Option<String>,
    },
    Text {
        at: [f64; 2],
        text: String,
    },
    Corner {
        at: [f64; 2],
    },
}

/// The color at fraction `t` (clamped to `[0, 1]`) of a scale of distances, dark blue through
/// teal to yellow: an axis's radii, offsets' distances, each figure its own range.
pub fn scale_color(t: f64) -> String {
    const STOPS: [[f64; 3]; 3] = [
        [40.0, 30.0, 140.0],
        [30.0, 150.0, 140.0],
        [240.0, 210.0, 20.0],
    ];
    let t = t.clamp(0.0, 1.0) * (STOPS.len() - 1) as f64;
    let i = (t.floor() as usize).min(STOPS.len() - 2);
    let f = t - i as f64;
    let c = |k: usize| (STOPS[i][k] + f * (STOPS[i + 1][k] - STOPS[i][k])).round() as u8;
    format!("#{:02x}{:02x}{:02x}", c(0), c(1), c(2))
}

/// A figure under construction.
#[derive(Default)]
pub struct Figure {
    items: Vec<Item>,
    curves: usize,
    title: Option<String>,
    frame: Option<([f64; 2], [f64; 2])>,
    status: Option<Status>,
    legend: Vec<Entry>,
    bar: Option<ColorBar>,
}

impl Figure {
    /// An empty figure.
    pub fn new() -> Self {
        Self::default()
    }

    /// A curve as a dense polyline (a new color per curve).
    pub fn curve(&mut self, points: Vec<[f64; 2]>, closed: bool) {
        let color = PALETTE[self.curves % PALETTE.len()];
        self.curves += 1;
        self.items.push(Item::Polyline {
            points,
            color: color.into(),
            width: 2.0,
            closed,
        });
    }

    /// A region's boundary, in the neutral colour.
    pub fn boundary(&mut self, points: Vec<[f64; 2]>, closed: bool) {
        self.items.push(Item::Polyline {
            points,
            color: BOUNDARY.into(),
            width: 1.6,
            closed,
        });
    }

    /// A thin polyline (bisector branches, foot-point lines).
    pub fn thin(&mut self, points: Vec<[f64; 2]>, color: &'static str) {
        self.items.push(Item::Polyline {
            points,
            color: color.into(),
            width: 0.6,
            closed: false,
        });
    }

    /// A polyline of a computed color (`#rrggbb`), drawn between the thin and the curve
    /// widths (a medial axis coloured by radius).
    pub fn colored(&mut self, points: Vec<[f64; 2]>, color: String) {
        self.items.push(Item::Polyline {
            points,
            color: color.into(),
            width: 1.4,
            closed: false,
        });
    }

    /// A stretch of a curve picked out in a colour (`#rrggbb`), thicker than the curve under
    /// it (a grasp's contact stretch).
    pub fn stretch(&mut self, points: Vec<[f64; 2]>, color: &'static str) {
        self.items.push(Item::Polyline {
            points,
            color: color.into(),
            width: STRETCH_WIDTH,
            closed: false,
        });
    }

    /// A closed polygon filled with a colour (`#rrggbb`), see-through so that what it covers
    /// shows (a region of a parameter square).
    pub fn area(&mut self, points: Vec<[f64; 2]>, color: &'static str) {
        self.items.push(Item::Area {
            points,
            color: color.into(),
        });
    }

    /// A marked point (inflections).
    pub fn dot(&mut self, at: [f64; 2]) {
        self.items.push(Item::Dot {
            at,
            color: DOT.into(),
            scale: 1.0,
        });
    }

    /// Marked points of a colour (`#rrggbb`): the nodes of a kind. Many are drawn small, so
    /// that they do not hide what lies between them.
    pub fn dots(&mut self, points: &[[f64; 2]], color: &'static str) {
        let scale = if points.len() > MANY_DOTS { 0.3 } else { 1.0 };
        for &at in points {
            self.items.push(Item::Dot {
                at,
                color: color.into(),
                scale,
            });
        }
    }

    /// Whether the result drawn is certified, and why not: the header's second line.
    pub fn status(&mut self, certified: bool, reason: Option<&str>) {
        self.status = Some(Status {
            certified,
            reason: reason.map(str::to_string),
        });
    }

    /// A legend entry: a mark and what it stands for (an entry given twice is kept once).
    pub fn legend(&mut self, mark: Mark, label: impl Into<String>) {
        let entry = Entry {
            mark,
            label: label.into(),
        };
        if !self.legend.contains(&entry) {
            self.legend.push(entry);
        }
    }

    /// The colour bar of the scale [`scale_color`] spans: what it measures (`radius`), from
    /// `lo` to `hi`, in `units` where the drawing says.
    pub fn color_bar(&mut self, quantity: &str, lo: f64, hi: f64, units: Option<&str>) {
        self.bar = Some(ColorBar {
            quantity: quantity.to_string(),
            lo,
            hi,
            units: units.map(str::to_string),
        });
    }

    /// A marked corner of a profile (a hollow square, set apart from the inflections' dots).
    pub fn corner(&mut self, at: [f64; 2]) {
        self.items.push(Item::Corner { at });
    }

    /// A segment between two points, optionally numbered at its middle (antipodal pairs).
    pub fn segment(&mut self, from: [f64; 2], to: [f64; 2], label: Option<String>) {
        self.items.push(Item::Segment { from, to, label });
    }

    /// A caption in the top-left corner.
    pub fn title(&mut self, text: impl Into<String>) {
        self.title = Some(text.into());
    }

    /// Fixes the drawn region to the box `lo`–`hi` (plot coordinates) instead of fitting it to
    /// the content; what lies outside is clipped. Bisectors reach far from their curves, and a
    /// figure fitted to them would show the curves as a dot.
    pub fn frame(&mut self, lo: [f64; 2], hi: [f64; 2]) {
        self.frame = Some((lo, hi));
    }

    /// A label at a point.
    pub fn text(&mut self, at: [f64; 2], text: impl Into<String>) {
        self.items.push(Item::Text {
            at,
            text: text.into(),
        });
    }

    /// The SVG document.
    pub fn render(&self) -> String {
        side_by_side(&[self])
    }

    /// One panel as a nested `<svg>` element at pixel offset `(x, y)`, with its width and
    /// height in pixels and the numbers left out where they would overlap; its title drawn in
    /// it where `titled` (a panel beside the main one: the main one's is the header). A nested
    /// `<svg>` clips what lies outside its view box.
    fn panel(&self, x: f64, y: f64, titled: bool) -> (String, f64, f64, usize) {
        let (lo, hi) = self.frame.unwrap_or_else(|| self.bounds());
        let size = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(MIN_SIZE);
        let pad = 0.06 * size;
        let (x0, y0) = (lo[0] - pad, -hi[1] - pad);
        let (w, h) = (hi[0] - lo[0] + 2.0 * pad, hi[1] - lo[1] + 2.0 * pad);
        let px = 640.0;
        let (pw, ph) = if w >= h {
            (px, px * h / w)
        } else {
            (px * w / h, px)
        };
        // Stroke widths are given in pixels and converted to user units, so every renderer
        // draws them alike (`vector-effect` is not supported everywhere).
        let upx = w / pw;
        let r = 0.008 * size;
        // Numbers drawn so far, as pixel boxes: one that would overlap them is left out.
        let mut placed: Vec<[f64; 4]> = Vec::new();
        let mut left_out = 0;
        let mut place = |at: [f64; 2], label: &str| {
            let (px, py) = ((at[0] - x0) / upx, (-at[1] - y0) / upx);
            let b = [
                px,
                py - LABEL_HEIGHT,
                px + LABEL_CHAR * label.chars().count() as f64,
                py,
            ];
            let clear = placed
                .iter()
                .all(|q| b[2] <= q[0] || q[2] <= b[0] || b[3] <= q[1] || q[3] <= b[1]);
            if clear {
                placed.push(b);
            } else {
                left_out += 1;
            }
            clear
        };
        let mut s = String::new();
        let _ = writeln!(
            s,
            r#"<svg x="{x:.0}" y="{y:.0}" width="{pw:.0}" height="{ph:.0}" viewBox="{} {} {} {}">"#,
            num(x0),
            num(y0),
            num(w),
            num(h)
        );
        let _ = writeln!(
            s,
            r##"<rect x="{}" y="{}" width="{}" height="{}" fill="#ffffff"/>"##,
            num(x0),
            num(y0),
            num(w),
            num(h)
        );
        for item in &self.items {
            match item {
                Item::Polyline {
                    points,
                    color,
                    width,
                    closed,
                } => {
                    let tag = if *closed { "polygon" } else { "polyline" };
                    let pts: Vec<String> = points.iter().map(|p| pair(*p)).collect();
                    let _ = writeln!(
                        s,
                        r#"<{tag} points="{}" fill="none" stroke="{color}" stroke-width="{}" stroke-linejoin="round"/>"#,
                        pts.join(" "),
                        num(width * upx)
                    );
                }
                Item::Area { points, color } => {
                    let pts: Vec<String> = points.iter().map(|p| pair(*p)).collect();
                    let _ = writeln!(
                        s,
                        r#"<polygon points="{}" fill="{color}" fill-opacity="{AREA_OPACITY}" stroke="{color}" stroke-width="{}" stroke-linejoin="round"/>"#,
                        pts.join(" "),
                        num(0.6 * upx)
                    );
                }
                Item::Dot { at, color, scale } => {
                    let _ = writeln!(
                        s,
                        r#"<circle cx="{}" cy="{}" r="{}" fill="{color}"/>"#,
                        num(at[0]),
                        num(-at[1]),
                        num(r * scale)
                    );
                }
                Item::Corner { at } => {
                    let _ = writeln!(
                        s,
                        r##"<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#1f5fbf" stroke-width="{}"/>"##,
                        num(at[0] - 1.5 * r),
                        num(-at[1] - 1.5 * r),
                        num(3.0 * r),
                        num(3.0 * r),
                        num(0.5 * r)
                    );
                }
                Item::Segment { from, to, label } => {
                    let _ = writeln!(
                        s,
                        r##"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="#444444" stroke-width="{}" stroke-dasharray="{} {}"/>"##,
                        num(from[0]),
                        num(-from[1]),
                        num(to[0]),
                        num(-to[1]),
                        num(upx),
                        num(4.0 * upx),
                        num(3.0 * upx)
                    );
                    if let Some(label) = label {
                        // Near the first end: segments often share their midpoint.
                        let at = [
                            from[0] + 0.1 * (to[0] - from[0]),
                            from[1] + 0.1 * (to[1] - from[1]),
                        ];
                        if place(at, label) {
                            text(&mut s, at, label, upx);
                        }
                    }
                }
                Item::Text { at, text: t } => {
                    if place(*at, t) {
                        text(&mut s, *at, t, upx);
                    }
                }
            }
        }
        if let (true, Some(t)) = (titled, &self.title) {
            // In the top padding, in plot coordinates (y up).
            text(&mut s, [x0 + 0.5 * pad, hi[1] + 0.2 * pad], t, upx);
        }
        s.push_str("</svg>\n");
        (s, pw, ph, left_out)
    }

    fn bounds(&self) -> ([f64; 2], [f64; 2]) {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        let mut add = |p: &[f64; 2]| {
            if p[0].is_finite() && p[1].is_finite() {
                for c in 0..2 {
                    lo[c] = lo[c].min(p[c]);
                    hi[c] = hi[c].max(p[c]);
                }
            }
        };
        for item in &self.items {
            match item {
                Item::Polyline { points, .. } | Item::Area { points, .. } => {
                    points.iter().for_each(&mut add)
                }
                Item::Dot { at, .. } | Item::Text { at, .. } | Item::Corner { at } => add(at),
                Item::Segment { from, to, .. } => {
                    add(from);
                    add(to);
                }
            }
        }
        if lo[0] > hi[0] {
            return ([-1.0, -1.0], [1.0, 1.0]);
        }
        (lo, hi)
    }
}

/// Text made safe for SVG.
fn escape(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Text of 14 pixels whatever the figure's scale: set in pixels and scaled to user units by a
/// transform (tiny user-unit font sizes render badly in some viewers).
fn text(s: &mut String, at: [f64; 2], t: &str, upx: f64) {
    let escaped = escape(t);
    let _ = writeln!(
        s,
        r##"<text transform="translate({} {}) scale({})" font-size="14" font-family="sans-serif" fill="#222222">{escaped}</text>"##,
        num(at[0]),
        num(-at[1]),
        num(upx)
    );
}

/// A number with about seven significant digits, whatever the figure's scale (f32's shortest
/// round-trip form); non-finite values become 0 (never invalid SVG).
fn num(x: f64) -> String {
    let x = x as f32;
    if !x.is_finite() {
        return "0".into();
    }
    if x == 0.0 {
        return "0".into();
    }
    x.to_string()
}

/// A point as `x,y` with y flipped (SVG's y points down).
fn pair(p: [f64; 2]) -> String {
    format!("{},{}", num(p[0]), num(-p[1]))
}

/// Figures side by side in one SVG document (a figure and its parameter-space view): the
/// first one's title and status as the header, the panels below it, and the legend of them all
/// in a column to their right.
pub fn side_by_side(figures: &[&Figure]) -> String {
    let gap = 16.0;
    let first = figures.first();
    let lines = legend::header_lines(
        first.and_then(|f| f.title.as_deref()),
        first.and_then(|f| f.status.as_ref()),
    );
    let top = if lines.is_empty() {
        0.0
    } else {
        LINE * lines.len() as f64 + 8.0
    };
    let (mut body, mut x, mut height) = (String::new(), 0.0, 0.0f64);
    let mut left_out = 0;
    for (k, f) in figures.iter().enumerate() {
        let (panel, pw, ph, skipped) = f.panel(x, top, k > 0);
        body.push_str(&panel);
        x += pw + gap;
        height = height.max(ph);
        left_out += skipped;
    }
    let mut entries: Vec<Entry> = Vec::new();
    for e in figures.iter().flat_map(|f| &f.legend) {
        if !entries.contains(e) {
            entries.push(e.clone());
        }
    }
    if left_out > 0 {
        entries.push(Entry {
            mark: Mark::Dashed,
            label: format!(
                "{left_out} numbers left out where they would overlap (the JSON lists all)"
            ),
        });
    }
    let bar = figures.iter().find_map(|f| f.bar.as_ref());
    let mut width = (x - gap).max(0.0);
    if bar.is_some() || !entries.is_empty() {
        let legend_height = legend::legend(&mut body, width + gap, top + 8.0, bar, &entries);
        width += gap + LEGEND_WIDTH;
        height = height.max(legend_height + 16.0);
    }
    let mut head = String::new();
    legend::header(&mut head, &lines);
    let total = top + height;
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width:.0}\" height=\"{total:.0}\">\n\
         <rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n{head}{body}</svg>\n"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn renders_fitted_y_up() {
        let mut f = Figure::new();
        f.curve(vec![[0.0, 0.0], [10.0, 0.0], [10.0, 5.0]], false);
        f.dot([10.0, 5.0]);
        f.segment([0.0, 0.0], [10.0, 5.0], Some("1".into()));
        let svg = f.render();
        assert!(svg.starts_with("<svg"));
        assert!(svg.contains("viewBox=\"-0.6 -5.6 11.2 6.2\""));
        assert!(svg.contains("cy=\"-5\""));
        assert!(svg.trim_end().ends_with("</svg>"));
    }

    #[test]
    fn frames_clip_and_panels_sit_side_by_side() {
        let mut f = Figure::new();
        f.thin(vec![[0.0, 0.0], [1e6, 0.0]], "#000000");
        f.frame([0.0, 0.0], [10.0, 10.0]);
        let mut g = Figure::new();
        g.curve(vec![[0.0, 0.0], [1.0, 1.0]], false);
        let svg = side_by_side(&[&f, &g]);
        // The frame, not the far point, sets the view box; the second panel follows the first.
        assert!(svg.contains("viewBox=\"-0.6 -10.6 11.2 11.2\""));
        assert!(svg.contains("<svg x=\"0\""));
        assert!(svg.contains("<svg x=\"656\""));
        assert_eq!(svg.matches("<svg").count(), 3);
    }
}
