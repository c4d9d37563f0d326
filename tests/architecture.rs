//! The house's arrows (docs/architecture.md): every crate uses only the crates to its left, and
//! no crate's modules import each other in a circle beyond the circles known today, which may
//! only go (a ratchet: a circle broken must leave `KNOWN_CIRCLES`, and no new one may come).
//! Read from the sources as text: `crate::module` paths between a crate's top-level modules,
//! test modules left out.
#![allow(clippy::unwrap_used)]

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The crates from left to right, with their source folders (a crate may use those before it).
const CRATES: [(&str, &str); 9] = [
    ("numeric", "crates/numeric"),
    ("bspline", "crates/bspline"),
    ("curve", "crates/curve"),
    ("zeroset", "crates/zeroset"),
    ("antipodal", "crates/antipodal"),
    ("medial", "crates/medial"),
    ("offset", "crates/offset"),
    ("curvekit", "."),
    ("python", "python"),
];

/// The circles of modules that import each other today, per crate (issue 41 breaks them).
const KNOWN_CIRCLES: [(&str, &[&str]); 0] = [];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The `.rs` files under `dir`, test modules in files of their own (`tests.rs`, declared
/// under `#[cfg(test)]`) left out as the test modules inside files are.
fn sources(dir: &Path) -> Vec<PathBuf> {
    let mut found = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            found.extend(sources(&path));
        } else if path.extension().is_some_and(|e| e == "rs")
            && path.file_name().is_some_and(|n| n != "tests.rs")
        {
            found.push(path);
        }
    }
    found
}

/// The code of a file before its test module, without comment lines.
fn code(text: &str) -> String {
    let mut out = String::new();
    let mut lines = text.lines().peekable();
    while let Some(line) = lines.next() {
        let t = line.trim_start();
        let module = |n: &&str| {
            let n = n.trim_start();
            let n = n.strip_prefix("pub(crate) ").unwrap_or(n);
            n.strip_prefix("pub ").unwrap_or(n).starts_with("mod ")
        };
        if t.starts_with("#[cfg(test)]") && lines.peek().is_some_and(module) {
            break;
        }
        if !t.starts_with("//") {
            out.push_str(line);
            out.push('\n');
        }
    }
    out
}

/// The crate's top-level modules each source file belongs to (`lib.rs`, `main.rs`: none).
fn module_of(src: &Path, file: &Path) -> Option<String> {
    let rel = file.strip_prefix(src).ok()?;
    let first = rel
        .components()
        .next()?
        .as_os_str()
        .to_string_lossy()
        .to_string();
    let name = first.trim_end_matches(".rs").to_string();
    (name != "lib" && name != "main").then_some(name)
}

/// The module names a piece of code reaches through `crate::` (in `crate::a::b`, and each
/// path of `crate::{a, b::c}`).
fn reached(code: &str) -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    let mut rest = code;
    while let Some(i) = rest.find("crate::") {
        rest = &rest[i + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let end = group.find('}').unwrap_or(group.len());
            for path in group[..end].split(',') {
                let head: String = path
                    .trim()
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                names.insert(head);
            }
        } else {
            let head: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            names.insert(head);
        }
    }
    names
}

/// The names the crate's root (`lib.rs` or `main.rs`) re-exports (`pub use module::{A, B}`),
/// each with its module.
fn reexports(src: &Path, modules: &BTreeSet<String>) -> BTreeMap<String, String> {
    let mut map = BTreeMap::new();
    for root in ["lib.rs", "main.rs"] {
        let Ok(text) = std::fs::read_to_string(src.join(root)) else {
            continue;
        };
        for statement in code(&text).split(';') {
            let Some(rest) = statement.trim().strip_prefix("pub use ") else {
                continue;
            };
            let Some((module, items)) = rest.split_once("::") else {
                continue;
            };
            if !modules.contains(module) {
                continue;
            }
            let items = items.trim().trim_start_matches('{').trim_end_matches('}');
            for item in items.split(',') {
                // (`a as b` is exported as `b`; `x::A` as `A`.)
                let item = item.trim();
                let name = item.rsplit(" as ").next().unwrap_or(item);
                let name = name.rsplit("::").next().unwrap_or(name).trim();
                if !name.is_empty() {
                    map.insert(name.to_string(), module.to_string());
                }
            }
        }
    }
    map
}

/// The strongly connected components of more than one module (Tarjan's algorithm).
fn circles(edges: &BTreeMap<String, BTreeSet<String>>) -> BTreeSet<Vec<String>> {
    struct State<'a> {
        edges: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on_stack: BTreeSet<&'a str>,
        found: BTreeSet<Vec<String>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a str) {
        let n = s.index.len();
        s.index.insert(v, n);
        s.low.insert(v, n);
        s.stack.push(v);
        s.on_stack.insert(v);
        for w in s.edges.get(v).into_iter().flatten() {
            let w = w.as_str();
            if !s.index.contains_key(w) {
                visit(s, w);
                let lw = s.low[w];
                let lv = s.low[v];
                s.low.insert(v, lv.min(lw));
            } else if s.on_stack.contains(w) {
                let iw = s.index[w];
                let lv = s.low[v];
                s.low.insert(v, lv.min(iw));
            }
        }
        if s.low[v] == s.index[v] {
            let mut component = Vec::new();
            while let Some(w) = s.stack.pop() {
                s.on_stack.remove(w);
                component.push(w.to_string());
                if w == v {
                    break;
                }
            }
            if component.len() > 1 {
                component.sort();
                s.found.insert(component);
            }
        }
    }
    let mut s = State {
        edges,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        found: BTreeSet::new(),
    };
    for v in edges.keys() {
        if !s.index.contains_key(v.as_str()) {
            visit(&mut s, v);
        }
    }
    s.found
}

/// No crate's modules import each other in a circle beyond the known ones, and each known one
/// still stands (remove it from the list once broken).
#[test]
fn modules_import_no_new_circle() {
    let mut found: BTreeSet<(String, Vec<String>)> = BTreeSet::new();
    for (name, dir) in CRATES {
        let src = root().join(dir).join("src");
        let files = sources(&src);
        let modules: BTreeSet<String> = files.iter().filter_map(|f| module_of(&src, f)).collect();
        let exported = reexports(&src, &modules);
        let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for file in &files {
            let Some(from) = module_of(&src, file) else {
                continue;
            };
            let text = std::fs::read_to_string(file).unwrap();
            for name in reached(&code(&text)) {
                // (A name the crate's root re-exports is its module's.)
                let to = exported.get(&name).cloned().unwrap_or(name);
                if to != from && modules.contains(&to) {
                    edges.entry(from.clone()).or_default().insert(to);
                }
            }
        }
        for c in circles(&edges) {
            found.insert((name.to_string(), c));
        }
    }
    let known: BTreeSet<(String, Vec<String>)> = KNOWN_CIRCLES
        .iter()
        .map(|(c, m)| (c.to_string(), m.iter().map(|s| s.to_string()).collect()))
        .collect();
    let new: Vec<_> = found.difference(&known).collect();
    let gone: Vec<_> = known.difference(&found).collect();
    assert!(
        new.is_empty(),
        "modules importing each other in a circle: {new:?}"
    );
    assert!(
        gone.is_empty(),
        "circles broken, to leave KNOWN_CIRCLES: {gone:?}"
    );
}

/// Every crate uses only the workspace crates to its left.
#[test]
fn crates_use_only_those_to_their_left() {
    let names: Vec<&str> = CRATES.iter().map(|(n, _)| *n).collect();
    for (k, (name, dir)) in CRATES.iter().enumerate() {
        let manifest = std::fs::read_to_string(root().join(dir).join("Cargo.toml")).unwrap();
        let deps = manifest
            .split("\n[")
            .filter(|section| section.starts_with("dependencies]"))
            .collect::<String>();
        for line in deps.lines().skip(1) {
            let dep = line.split(['.', ' ', '=']).next().unwrap_or("").trim();
            if let Some(j) = names.iter().position(|n| *n == dep) {
                assert!(j < k, "{name} uses {dep}, which stands to its right");
            }
        }
    }
}

/// The tests' shared ground (`crates/testkit`) is a dev-dependency only: no crate's library
/// or tool depends on it.
#[test]
fn testkit_is_for_tests_only() {
    for (name, dir) in CRATES {
        let manifest = std::fs::read_to_string(root().join(dir).join("Cargo.toml")).unwrap();
        for section in manifest.split("\n[") {
            if section.starts_with("dependencies]") {
                assert!(
                    !section
                        .lines()
                        .any(|l| l.trim_start().starts_with("testkit")),
                    "{name} depends on testkit outside its dev-dependencies"
                );
            }
        }
    }
}

/// The public types two crates define under one name, today (each to leave the list once
/// renamed). Every crate's `Error` and `Result` are left out: they are the idiom, always
/// reached through their crate.
const KNOWN_SHARED_TYPES: [&str; 0] = [];

/// The source folders of every crate (the tests' shared ground left out).
fn source_folders() -> Vec<(&'static str, PathBuf)> {
    CRATES
        .iter()
        .map(|(name, dir)| (*name, root().join(dir).join("src")))
        .collect()
}

/// The names after `keyword` at the start of a line of `code` (`pub struct Name`, …).
fn declared<'a>(code: &'a str, keyword: &'a str) -> impl Iterator<Item = String> + 'a {
    code.lines().filter_map(move |line| {
        let rest = line.strip_prefix(keyword)?;
        let name: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        (!name.is_empty()).then_some(name)
    })
}

/// One word, one type: no two crates define a public type of the same name, beyond the known
/// ones, which may only go.
#[test]
fn no_two_public_types_share_a_name() {
    let mut places: BTreeMap<String, BTreeSet<&str>> = BTreeMap::new();
    for (name, src) in source_folders() {
        for file in sources(&src) {
            let text = code(&std::fs::read_to_string(&file).unwrap());
            let text = text
                .lines()
                .map(str::trim_start)
                .collect::<Vec<_>>()
                .join("\n");
            for keyword in ["pub struct ", "pub enum ", "pub trait ", "pub type "] {
                for ty in declared(&text, keyword) {
                    places.entry(ty).or_default().insert(name);
                }
            }
        }
    }
    let shared: BTreeSet<&str> = places
        .iter()
        .filter(|(ty, crates)| crates.len() > 1 && *ty != "Error" && *ty != "Result")
        .map(|(ty, _)| ty.as_str())
        .collect();
    let known: BTreeSet<&str> = KNOWN_SHARED_TYPES.into_iter().collect();
    let new: Vec<_> = shared.difference(&known).collect();
    let gone: Vec<_> = known.difference(&shared).collect();
    assert!(
        new.is_empty(),
        "public types of one name in two crates: {new:?}"
    );
    assert!(
        gone.is_empty(),
        "renamed, to leave KNOWN_SHARED_TYPES: {gone:?}"
    );
}

/// Every constant is named once: two module-level constants of one name in the workspace hold
/// the same value (then one should serve both), or they are two things and need two names.
#[test]
fn no_two_constants_share_a_name_with_different_values() {
    let mut values: BTreeMap<String, BTreeSet<(String, String)>> = BTreeMap::new();
    for (_, src) in source_folders() {
        for file in sources(&src) {
            let text = code(&std::fs::read_to_string(&file).unwrap());
            // (Module-level only: a constant inside an impl or a function is its own.)
            for statement in text.split(';') {
                let line = statement.trim_start_matches(['\n', ' ', '}', '{']);
                let line = line
                    .strip_prefix("pub(crate) ")
                    .or_else(|| line.strip_prefix("pub(super) "))
                    .or_else(|| line.strip_prefix("pub "))
                    .unwrap_or(line);
                let Some(rest) = line.strip_prefix("const ") else {
                    continue;
                };
                if statement.trim_start_matches('\n').starts_with(' ') {
                    continue;
                }
                let Some((name, value)) = rest.split_once('=') else {
                    continue;
                };
                let name = name.split(':').next().unwrap_or("").trim().to_string();
                let value = value.split_whitespace().collect::<Vec<_>>().join(" ");
                let place = file.strip_prefix(root()).unwrap().display().to_string();
                values.entry(name).or_default().insert((value, place));
            }
        }
    }
    let clashes: Vec<_> = values
        .iter()
        .filter(|(_, v)| {
            v.iter()
                .map(|(value, _)| value)
                .collect::<BTreeSet<_>>()
                .len()
                > 1
        })
        .collect();
    assert!(
        clashes.is_empty(),
        "constants of one name with different values: {clashes:#?}"
    );
}
