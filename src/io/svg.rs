//! SVG drawings, read as a renderer draws them: every `<path>` element's data (each subpath a
//! chain) and the basic shapes (`<rect>` with rounded corners, `<circle>`, `<ellipse>`,
//! `<polygon>`, `<polyline>`, `<line>`), with the `transform` attributes of the element, its
//! ancestors and the `<use>` elements that place it applied exactly (affine maps carry every
//! segment's exact form). Coordinates are the file's user units, `y` pointing down as SVG
//! draws it. The XML is `roxmltree`'s, the transform and path syntax `svgtypes`'.
//!
//! - **Fill.** Each filled element is a group of outlines filled by its `fill-rule`
//!   (`nonzero`, the default, or `evenodd`; attribute or `style`, inherited), and the drawing
//!   is the union of the groups ([`curve::Region::filled`]); an open subpath of a filled
//!   element is closed by a line, as SVG fills it. Elements drawn with a stroke and no fill
//!   are outlines, nested even-odd together (a CAD export); their open subpaths stay open.
//!   An element with neither (`fill="none"` and no stroke, as icon sets write their bounding
//!   boxes) is not drawn, nor is one with `display: none` or `visibility: hidden`.
//! - **Not read**, and listed in `skipped`: `<text>`, `<image>`, `<foreignObject>`; elements
//!   that are not drawn; and `clip-path` and `mask`, whose effect on the outlines is not
//!   computed (no answer on such a drawing is certified).
//! - **Units**: the root's `width` in `mm`, `cm`, `in`, `pt` or `pc` with a `viewBox` of that
//!   width makes that the unit of the user units.
//!
//! Elements inside `<defs>`, `<clipPath>`, `<mask>`, `<symbol>`, `<marker>` and `<pattern>`
//! are drawn only where a `<use>` places them.

mod path_data;
mod shapes;

use super::drawing::{error, Chain, DrawingRead};
use super::{CurveFileError, Problem, MAX_ABS, MAX_SEGMENTS};
use curve::{Affine, FillRule, Segment};
use roxmltree::{Document, Node};

/// Containers whose content is not drawn where it stands.
const NOT_DRAWN: [&str; 6] = ["defs", "clipPath", "mask", "symbol", "marker", "pattern"];

/// The shape elements, whose outlines are read.
const SHAPE_ELEMENTS: [&str; 7] = [
    "path", "rect", "circle", "ellipse", "polygon", "polyline", "line",
];

/// Elements that draw something the reader does not read.
const NOT_READ: [&str; 3] = ["text", "image", "foreignObject"];

/// How deep `<use>` elements may refer through each other (a reference cycle would not end).
const MAX_USE_DEPTH: usize = 16;

/// Most elements one drawing may draw, `<use>` copies included (bounds the work).
const MAX_ELEMENTS: usize = 100_000;

/// Units a root `width` may give the user units.
const WIDTH_UNITS: [(&str, svgtypes::LengthUnit); 5] = [
    ("mm", svgtypes::LengthUnit::Mm),
    ("cm", svgtypes::LengthUnit::Cm),
    ("in", svgtypes::LengthUnit::In),
    ("pt", svgtypes::LengthUnit::Pt),
    ("pc", svgtypes::LengthUnit::Pc),
];

/// What an element inherits from where it is drawn.
#[derive(Debug, Clone, Copy)]
struct Style {
    /// From the element's coordinates to the document's.
    map: Affine,
    /// Filled (SVG's default: black).
    fill: bool,
    /// Stroked (SVG's default: not).
    stroke: bool,
    rule: FillRule,
    visible: bool,
}

/// The chains of an SVG drawing, in document order, with what was not read and its units.
pub(super) fn read(file: &str, text: &str) -> Result<DrawingRead, CurveFileError> {
    let doc = Document::parse(text).map_err(|e| {
        error(
            file,
            "document",
            Problem::Syntax(format!("invalid SVG (XML): {e}")),
        )
    })?;
    let root = doc.root_element();
    if root.tag_name().name() != "svg" {
        return Err(error(
            file,
            "document",
            Problem::Syntax(format!(
                "the root element is <{}>, not <svg>",
                root.tag_name().name()
            )),
        ));
    }
    let mut walk = Walk {
        file,
        doc: &doc,
        read: DrawingRead {
            units: units_of(&root),
            ..DrawingRead::default()
        },
        elements: 0,
        shapes: 0,
        segments: 0,
        groups: 0,
    };
    let style = Style {
        map: Affine::IDENTITY,
        fill: true,
        stroke: false,
        rule: FillRule::NonZero,
        visible: true,
    };
    walk.element(root, style, 0, "")?;
    Ok(walk.read)
}

/// The numbers of an element's `viewBox` (separated by commas or white space); `None`
/// without one, or where one is not a number.
fn view_box(node: &Node<'_, '_>) -> Option<Vec<f64>> {
    node.attribute("viewBox")?
        .split(|c: char| c == ',' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .map(str::parse)
        .collect::<Result<_, _>>()
        .ok()
}

/// The unit of the user units, where the root's width is in one and its `viewBox` as wide.
fn units_of(root: &Node<'_, '_>) -> Option<String> {
    let width: svgtypes::Length = root.attribute("width")?.trim().parse().ok()?;
    let view = view_box(root)?;
    let &(name, _) = WIDTH_UNITS.iter().find(|(_, u)| *u == width.unit)?;
    let same = view.len() == 4 && (view[2] - width.number).abs() <= 1e-9 * width.number.abs();
    same.then(|| name.to_string())
}

/// The walk through the document.
struct Walk<'d, 'input> {
    file: &'d str,
    doc: &'d Document<'input>,
    read: DrawingRead,
    elements: usize,
    shapes: usize,
    segments: usize,
    /// Groups given out (group 0 is the outlines drawn without fill).
    groups: usize,
}

impl Walk<'_, '_> {
    /// Draws `node` and what it holds, as `style` says it inherits; `via` names the `<use>`
    /// elements that placed it, for messages.
    fn element(
        &mut self,
        node: Node<'_, '_>,
        inherited: Style,
        uses: usize,
        via: &str,
    ) -> Result<(), CurveFileError> {
        let tag = node.tag_name().name();
        self.elements += 1;
        if self.elements > MAX_ELEMENTS {
            return Err(error(
                self.file,
                "document",
                Problem::OutOfRange {
                    rule: format!("at most {MAX_ELEMENTS} elements drawn (<use> copies included)"),
                    value: self.elements as f64,
                },
            ));
        }
        // (Shapes are numbered among the shapes drawn, in document order; others among all
        // the elements.)
        let index = if SHAPE_ELEMENTS.contains(&tag) {
            self.shapes += 1;
            self.shapes - 1
        } else {
            self.elements - 1
        };
        let name = match node.attribute("id") {
            Some(id) => format!("{via}{tag}#{id}"),
            None => format!("{via}{tag}[{index}]"),
        };
        let fail = |field: &str, why: String| {
            error(self.file, &format!("{name} {field}"), Problem::Syntax(why))
        };
        let style = style_of(&node, inherited).map_err(|why| fail("transform", why))?;
        if property(&node, "display") == Some("none") {
            return Ok(());
        }
        for attr in ["clip-path", "mask"] {
            if property(&node, attr).is_some_and(|v| v != "none") {
                self.read.skip(attr, true, || {
                    format!("{name} has a {attr}, whose effect on the outlines is not computed")
                });
            }
        }
        match tag {
            "svg" | "g" | "a" | "switch" => {
                for child in node.children().filter(Node::is_element) {
                    if !NOT_DRAWN.contains(&child.tag_name().name()) {
                        self.element(child, style, uses, via)?;
                    }
                }
            }
            "use" => self.place(node, style, uses, &name)?,
            t if SHAPE_ELEMENTS.contains(&t) => self.shape(node, tag, style, &name)?,
            t if NOT_READ.contains(&t) => {
                self.read
                    .skip(t, false, || format!("{name}: <{t}> is not read"));
            }
            _ => {}
        }
        Ok(())
    }

    /// A `<use>`: the element it refers to, moved by its `x`, `y` (and, for a `<symbol>` with
    /// a `viewBox`, fitted into its `width` and `height`).
    fn place(
        &mut self,
        node: Node<'_, '_>,
        style: Style,
        uses: usize,
        name: &str,
    ) -> Result<(), CurveFileError> {
        let fail = |why: String| error(self.file, &format!("{name} href"), Problem::Syntax(why));
        let href = node
            .attribute("href")
            .or_else(|| node.attribute(("http://www.w3.org/1999/xlink", "href")));
        let Some(id) = href.and_then(|h| h.strip_prefix('#')) else {
            return Err(fail(
                "a <use> refers to an element of this file by `#id`".into(),
            ));
        };
        if uses >= MAX_USE_DEPTH {
            return Err(fail(format!(
                "<use> elements refer through more than {MAX_USE_DEPTH} others (a cycle?)"
            )));
        }
        let Some(target) = self
            .doc
            .descendants()
            .find(|n| n.is_element() && n.attribute("id") == Some(id))
        else {
            return Err(fail(format!("no element has the id `{id}`")));
        };
        let length = |a: &str| -> Result<f64, String> {
            match node.attribute(a) {
                None => Ok(0.0),
                Some(v) => user_length(v).map_err(|e| format!("{a}: {e}")),
            }
        };
        let (x, y) = (length("x").map_err(&fail)?, length("y").map_err(&fail)?);
        let mut style = style;
        style.map = style.map.after(&Affine([1.0, 0.0, 0.0, 1.0, x, y]));
        let via = format!("{name} > ");
        if target.tag_name().name() == "symbol" {
            if let Some(fit) = symbol_fit(&target, &node) {
                style.map = style.map.after(&fit);
            }
            let inner = style_of(&target, style).map_err(fail)?;
            for child in target.children().filter(Node::is_element) {
                self.element(child, inner, uses + 1, &via)?;
            }
            return Ok(());
        }
        self.element(target, style, uses + 1, &via)
    }

    /// A shape element's chains.
    fn shape(
        &mut self,
        node: Node<'_, '_>,
        tag: &str,
        style: Style,
        name: &str,
    ) -> Result<(), CurveFileError> {
        if !style.visible || !(style.fill || style.stroke) {
            self.read.skip(tag, false, || {
                format!("{name} is not drawn (no fill, no stroke, or hidden)")
            });
            return Ok(());
        }
        let fail = |field: &str, why: String| {
            error(self.file, &format!("{name} {field}"), Problem::Syntax(why))
        };
        let (group, rule) = if style.fill {
            self.groups += 1;
            (self.groups, style.rule)
        } else {
            (0, FillRule::EvenOdd)
        };
        let pieces =
            shapes::chains(&node, tag, style.fill).map_err(|(field, why)| fail(field, why))?;
        for (k, (segments, closed)) in pieces.into_iter().enumerate() {
            self.segments += segments.len();
            if self.segments > MAX_SEGMENTS * 10 {
                return Err(error(
                    self.file,
                    "document",
                    Problem::OutOfRange {
                        rule: format!("at most {} segments in all", MAX_SEGMENTS * 10),
                        value: self.segments as f64,
                    },
                ));
            }
            let segments = segments
                .iter()
                .map(|s| s.transformed(&style.map))
                .collect::<Result<Vec<_>, _>>()
                .map_err(|e| fail("transform", e.to_string()))?;
            for s in &segments {
                check_size(s).map_err(|why| fail("d", why))?;
            }
            self.read.chains.push(Chain {
                name: if tag == "path" {
                    format!("{name} subpath {k}")
                } else {
                    name.to_string()
                },
                segments,
                closed: Some(closed),
                group,
                rule,
            });
        }
        Ok(())
    }
}

/// The value of a presentation property of the element itself: its `style` declaration, else
/// its attribute.
fn property<'a>(node: &Node<'a, '_>, name: &str) -> Option<&'a str> {
    let declared = node.attribute("style").and_then(|style| {
        style.split(';').find_map(|decl| {
            let (key, value) = decl.split_once(':')?;
            (key.trim() == name).then(|| value.trim())
        })
    });
    declared.or_else(|| node.attribute(name).map(str::trim))
}

/// What `node` draws with, from what it inherits and its own transform and properties.
fn style_of(node: &Node<'_, '_>, inherited: Style) -> Result<Style, String> {
    let mut style = inherited;
    if let Some(t) = node.attribute("transform") {
        let t: svgtypes::Transform = t
            .parse()
            .map_err(|e| format!("invalid transform `{t}`: {e}"))?;
        let own = Affine([t.a, t.b, t.c, t.d, t.e, t.f]);
        if !own.is_valid() {
            return Err(format!("transform `{t:?}` is not invertible"));
        }
        style.map = inherited.map.after(&own);
    }
    let painted = |v: &str| v != "none" && v != "transparent";
    if let Some(v) = property(node, "fill") {
        style.fill = painted(v);
    }
    if let Some(v) = property(node, "stroke") {
        style.stroke = painted(v);
    }
    match property(node, "fill-rule") {
        Some("evenodd") => style.rule = FillRule::EvenOdd,
        Some("nonzero") => style.rule = FillRule::NonZero,
        _ => {}
    }
    if let Some(v) = property(node, "visibility") {
        style.visible = v == "visible";
    }
    // (Wholly transparent: drawn nowhere.)
    let zero = |p: &str| property(node, p).and_then(|v| v.parse::<f64>().ok()) == Some(0.0);
    if zero("opacity") {
        style.visible = false;
    }
    if zero("fill-opacity") {
        style.fill = false;
    }
    Ok(style)
}

/// A `<symbol>`'s `viewBox` fitted into the `<use>`'s `width` and `height` (uniformly,
/// centred: SVG's default `xMidYMid meet`); `None` without them.
fn symbol_fit(symbol: &Node<'_, '_>, usage: &Node<'_, '_>) -> Option<Affine> {
    let view = view_box(symbol)?;
    let (w, h) = (
        user_length(usage.attribute("width")?).ok()?,
        user_length(usage.attribute("height")?).ok()?,
    );
    let [vx, vy, vw, vh] = <[f64; 4]>::try_from(view).ok()?;
    if !(vw > 0.0 && vh > 0.0 && w > 0.0 && h > 0.0) {
        return None;
    }
    let k = (w / vw).min(h / vh);
    let (dx, dy) = (0.5 * (w - k * vw) - k * vx, 0.5 * (h - k * vh) - k * vy);
    Some(Affine([k, 0.0, 0.0, k, dx, dy]))
}

/// A length in user units (a plain number or `px`).
fn user_length(v: &str) -> Result<f64, String> {
    let len: svgtypes::Length = v
        .trim()
        .parse()
        .map_err(|e| format!("`{v}` is not a length: {e}"))?;
    // (Other units would need the document's viewport to convert.)
    if !matches!(
        len.unit,
        svgtypes::LengthUnit::None | svgtypes::LengthUnit::Px
    ) {
        return Err(format!("`{v}`: only user units (or px) are read"));
    }
    let x = len.number;
    if x.is_finite() && x.abs() <= MAX_ABS {
        Ok(x)
    } else {
        Err(format!("{x} is out of range"))
    }
}

/// Coordinates within the range every reader accepts.
fn check_size(s: &Segment) -> Result<(), String> {
    match s
        .curve()
        .control_points()
        .iter()
        .flatten()
        .find(|x| !(x.is_finite() && x.abs() <= MAX_ABS))
    {
        Some(x) => Err(format!("coordinate {x:e} is too large (at most 1e100)")),
        None => Ok(()),
    }
}
