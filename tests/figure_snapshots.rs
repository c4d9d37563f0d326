//! The demo's figures, read as a person reads them: each has a header (the input, the command,
//! whether the result is certified), and the structure of every figure (its elements by tag,
//! and every word it shows: titles, legends, colour bars' ticks) is kept as a snapshot, so a
//! change to what a figure shows is reviewed. (Looked at as PNGs with resvg when changed.)
#![allow(clippy::unwrap_used)]

mod common;

use common::curvekit;
use std::collections::BTreeMap;

/// The structure of one SVG figure: its element tags with their counts, then its texts.
fn structure(svg: &str) -> String {
    let doc = roxmltree::Document::parse(svg).unwrap();
    let mut tags: BTreeMap<&str, usize> = BTreeMap::new();
    let mut texts = Vec::new();
    for node in doc.descendants().filter(|n| n.is_element()) {
        *tags.entry(node.tag_name().name()).or_default() += 1;
        if node.tag_name().name() == "text" {
            texts.push(node.text().unwrap_or("").to_string());
        }
    }
    let counts: Vec<String> = tags.iter().map(|(t, n)| format!("{t} {n}")).collect();
    format!(
        "  {}\n{}",
        counts.join(", "),
        texts
            .iter()
            .map(|t| format!("  | {t}\n"))
            .collect::<String>()
    )
}

#[test]
fn demo_figures_say_what_they_show() {
    let dir = tempfile::tempdir().unwrap();
    let run = curvekit(&["demo", "--out", dir.path().to_str().unwrap()]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let mut names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .collect();
    names.sort();
    assert!(names.len() >= 30, "{} figures", names.len());
    let mut all = String::new();
    for path in names {
        let svg = std::fs::read_to_string(&path).unwrap();
        let shape = structure(&svg);
        let name = path.file_name().unwrap().to_string_lossy();
        // Every figure opens with its title, naming the demo input and the command.
        let title = shape.lines().nth(1).unwrap_or("");
        assert!(
            title.contains("demo") && title.contains(" — "),
            "{name}: {title}"
        );
        all.push_str(&format!("{name}\n{shape}"));
    }
    insta::assert_snapshot!(all);
}
