//! The house's arrows (docs/architecture.md): every crate uses only the crates to its left, and
//! no crate's modules import each other in a circle beyond the circles known today, which may
//! only go (a ratchet: a circle broken must leave `KNOWN_CIRCLES`, and no new one may come).
//! Read from the sources as text: `crate::module` paths between a crate's top-level modules,
//! test modules left out.
#![allow(clippy::unwrap_used)]

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The crates from left to right, with their source folders (a crate may use those before it).
const CRATES: [(&str, &str); 12] = [
    ("numeric", "crates/numeric"),
    ("bspline", "crates/bspline"),
    ("curve", "crates/curve"),
    ("geometry", "crates/geometry"),
    ("testkit", "crates/testkit"),
    ("zeroset", "crates/zeroset"),
    ("antipodal", "crates/antipodal"),
    ("grasp", "crates/grasp"),
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

/// The `.rs` files under `dir`, less the test modules kept in files of their own (a
/// `tests.rs` its parent declares under `#[cfg(test)]`), as the test modules inside files are
/// left out by [`code`].
fn sources(dir: &Path) -> Vec<PathBuf> {
    let mut found = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            found.extend(sources(&path));
        } else if path.extension().is_some_and(|e| e == "rs") && !is_test_module(&path) {
            found.push(path);
        }
    }
    found
}

/// Whether `file` is a `tests.rs` its parent module declares under `#[cfg(test)]`.
fn is_test_module(file: &Path) -> bool {
    if file.file_name().is_none_or(|n| n != "tests.rs") {
        return false;
    }
    let folder = file.parent().unwrap();
    let parent = [folder.with_extension("rs"), folder.join("mod.rs")]
        .into_iter()
        .find(|p| p.exists());
    parent.is_some_and(|p| {
        let text = std::fs::read_to_string(p).unwrap();
        let lines: Vec<&str> = text.lines().map(str::trim).collect();
        lines.windows(2).any(|w| {
            w[0] == "#[cfg(test)]" && (w[1] == "mod tests;" || w[1] == "pub(crate) mod tests;")
        })
    })
}

/// The code of a file before its inline test module (`#[cfg(test)] mod tests { … }`),
/// without comment lines and without the declarations of test modules kept in files of their
/// own (`#[cfg(test)] mod tests;`).
fn code(text: &str) -> String {
    let mut out = String::new();
    let mut lines = text.lines().peekable();
    while let Some(line) = lines.next() {
        let t = line.trim_start();
        let module = |n: &str| {
            let n = n.trim_start();
            let n = n.strip_prefix("pub(crate) ").unwrap_or(n);
            n.strip_prefix("pub ").unwrap_or(n).starts_with("mod ")
        };
        if t.starts_with("#[cfg(test)]") && lines.peek().is_some_and(|n| module(n)) {
            let declaration = lines.next().unwrap_or_default();
            if declaration.trim_end().ends_with(';') {
                continue;
            }
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

/// The heads of the paths in a `use` group's text (`a, b::{c, d}, e` gives `a`, `b`, `e`):
/// split at the commas outside nested braces.
fn group_heads(group: &str) -> Vec<String> {
    let mut heads = Vec::new();
    let (mut depth, mut start) = (0usize, 0usize);
    for (i, c) in group.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth = depth.saturating_sub(1),
            ',' if depth == 0 => {
                heads.push(head(&group[start..i]));
                start = i + 1;
            }
            _ => {}
        }
    }
    heads.push(head(&group[start..]));
    heads
}

/// The first name of a path.
fn head(path: &str) -> String {
    path.trim()
        .chars()
        .take_while(|c| c.is_alphanumeric() || *c == '_')
        .collect()
}

/// The text of the `{ … }` group `rest` starts with (without its braces), to its matching
/// brace.
fn braced(rest: &str) -> &str {
    let mut depth = 0usize;
    for (i, c) in rest.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return &rest[1..i];
                }
            }
            _ => {}
        }
    }
    &rest[1..]
}

/// The top-level module names a piece of code reaches: through `crate::` (`crate::a::b`, and
/// each path of `crate::{a, b::{c, d}}`), and through as many `super::` as lead from the
/// file's module path (`depth` names deep: 1 for `src/a.rs` or `src/a/mod.rs`) to the crate's
/// root.
fn reached(code: &str, depth: usize) -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    let mut roots = vec!["crate::".to_string()];
    if depth > 0 {
        roots.push("super::".repeat(depth));
    }
    for root in &roots {
        let mut rest = code;
        while let Some(i) = rest.find(root.as_str()) {
            // (`super::super::x` seen from a file one deep is not a path to the root's `x`.)
            let before = &rest[..i];
            rest = &rest[i + root.len()..];
            if root.starts_with("super")
                && (before.ends_with("super::") || rest.starts_with("super::"))
            {
                continue;
            }
            if rest.starts_with('{') {
                names.extend(group_heads(braced(rest)));
            } else {
                names.insert(head(rest));
            }
        }
    }
    names.retain(|n| !n.is_empty() && n != "self" && n != "super");
    names
}

/// How many names deep the module of `file` is below the crate's root (`src/a.rs` and
/// `src/a/mod.rs`: 1; `src/a/b.rs`: 2; `lib.rs`: 0).
fn depth_of(src: &Path, file: &Path) -> usize {
    let rel = file.strip_prefix(src).unwrap_or(file);
    let parts = rel.components().count();
    let named = rel
        .file_name()
        .is_some_and(|n| n == "mod.rs" || n == "lib.rs" || n == "main.rs");
    if named {
        parts - 1
    } else {
        parts
    }
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
            for name in reached(&code(&text), depth_of(&src, file)) {
                // (A name the crate's root re-exports is its module's; a module's own name is
                // that module, though a function of another is re-exported under it, as
                // `zeroset::bisector` beside the module `bisector`: paths reach modules.)
                let to = match exported.get(&name) {
                    Some(owner) if !modules.contains(&name) => owner.clone(),
                    _ => name,
                };
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
    ratchet(
        &found,
        &known,
        "modules importing each other in a circle",
        "circles broken, to leave KNOWN_CIRCLES",
    );
}

/// A ratchet's check: nothing `found` that is not `known` (`new` says what that is), and
/// nothing `known` that is no longer found (`gone` says what to do).
fn ratchet<T: Ord + std::fmt::Debug>(
    found: &BTreeSet<T>,
    known: &BTreeSet<T>,
    new: &str,
    gone: &str,
) {
    let added: Vec<_> = found.difference(known).collect();
    let left: Vec<_> = known.difference(found).collect();
    assert!(added.is_empty(), "{new}: {added:?}");
    assert!(left.is_empty(), "{gone}: {left:?}");
}

/// Each workspace crate's library name, and the library names of what it depends on outside
/// its tests (normal and build dependencies, on every target), as `cargo metadata` reads the
/// manifests (tables, renames and all).
fn dependencies() -> BTreeMap<String, BTreeSet<String>> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let out = std::process::Command::new(cargo)
        .args([
            "metadata",
            "--no-deps",
            "--format-version",
            "1",
            "--offline",
        ])
        .current_dir(root())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let meta: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    // (A dependency is named by its package; the crates use each other by library name.)
    let packages = meta["packages"].as_array().unwrap();
    let library = |package: &serde_json::Value| -> String {
        package["targets"]
            .as_array()
            .and_then(|t| {
                t.iter()
                    .find(|t| ["lib", "rlib", "cdylib"].iter().any(|k| t["kind"][0] == *k))
            })
            .and_then(|t| t["name"].as_str())
            .unwrap_or_else(|| package["name"].as_str().unwrap())
            .replace('-', "_")
    };
    let by_package: BTreeMap<&str, String> = packages
        .iter()
        .map(|p| (p["name"].as_str().unwrap(), library(p)))
        .collect();
    packages
        .iter()
        .map(|p| {
            let uses = p["dependencies"]
                .as_array()
                .unwrap()
                .iter()
                .filter(|d| d["kind"] != "dev")
                .filter_map(|d| by_package.get(d["name"].as_str().unwrap()).cloned())
                .collect();
            (library(p), uses)
        })
        .collect()
}

/// Every crate uses only the workspace crates to its left.
#[test]
fn crates_use_only_those_to_their_left() {
    let names: Vec<&str> = CRATES.iter().map(|(n, _)| *n).collect();
    let deps = dependencies();
    for (k, name) in names.iter().enumerate() {
        // (The Python package's library is `_curvekit`; the others' are their names.)
        let uses = deps
            .get(*name)
            .or_else(|| (*name == "python").then(|| deps.get("_curvekit")).flatten())
            .unwrap_or_else(|| panic!("no crate {name} in the workspace's metadata"));
        for dep in uses {
            if let Some(j) = names.iter().position(|n| n == dep) {
                assert!(j < k, "{name} uses {dep}, which stands to its right");
            }
        }
    }
}

/// The tests' shared ground (`crates/testkit`) is a dev-dependency only: no crate's library
/// or tool depends on it.
#[test]
fn testkit_is_for_tests_only() {
    for (name, uses) in dependencies() {
        assert!(
            !uses.contains("testkit"),
            "{name} depends on testkit outside its dev-dependencies"
        );
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
    ratchet(
        &shared,
        &known,
        "public types of one name in two crates",
        "renamed, to leave KNOWN_SHARED_TYPES",
    );
}

/// The module-level constants of a file's code (a `const` at the start of a line, with any
/// visibility), each with its value's text, white space folded; the value runs to the `;` at
/// the statement's own level (an array type's `[T; N]` and an array value's items inside
/// brackets do not end it).
fn constants(code: &str) -> Vec<(String, String)> {
    let mut found = Vec::new();
    let lines: Vec<&str> = code.lines().collect();
    for (k, line) in lines.iter().enumerate() {
        let rest = ["pub(crate) ", "pub(super) ", "pub "]
            .iter()
            .find_map(|v| line.strip_prefix(v))
            .unwrap_or(line);
        let Some(rest) = rest.strip_prefix("const ") else {
            continue;
        };
        if rest.starts_with("fn ") {
            continue;
        }
        let statement = lines[k..].join("\n");
        let statement = &statement[statement.find("const ").unwrap_or(0)..];
        let (mut depth, mut end) = (0i32, statement.len());
        for (i, c) in statement.char_indices() {
            match c {
                '[' | '(' | '{' => depth += 1,
                ']' | ')' | '}' => depth -= 1,
                ';' if depth == 0 => {
                    end = i;
                    break;
                }
                _ => {}
            }
        }
        let name = head(rest);
        let Some((_, value)) = statement[..end].split_once(" = ") else {
            continue;
        };
        found.push((name, value.split_whitespace().collect::<Vec<_>>().join(" ")));
    }
    found
}

/// Every constant is named once: two module-level constants of one name in the workspace hold
/// the same value (then one should serve both), or they are two things and need two names.
#[test]
fn no_two_constants_share_a_name_with_different_values() {
    let mut values: BTreeMap<String, BTreeSet<(String, String)>> = BTreeMap::new();
    for (_, src) in source_folders() {
        for file in sources(&src) {
            let text = code(&std::fs::read_to_string(&file).unwrap());
            let place = file.strip_prefix(root()).unwrap().display().to_string();
            for (name, value) in constants(&text) {
                values
                    .entry(name)
                    .or_default()
                    .insert((value, place.clone()));
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

/// The parsers the tests above read the sources with, on the cases they must not miss.
#[test]
fn the_source_readers_see_what_they_must() {
    let text = "use crate::{a::{b, c}, d};\nfn f() { super::e::g(); }\n#[cfg(test)]\nmod tests;\n\
                pub(crate) const UNITS: [(&str, u8); 2] = [(\"mm\", 1), (\"cm\", 2)];\n\
                #[allow(dead_code)]\nconst AFTER: f64 = 1e-9;\nfn h() {\n    const INNER: u8 = 1;\n}\n";
    let code = code(text);
    let modules = reached(&code, 1);
    assert_eq!(
        modules,
        ["a", "d", "e"].into_iter().map(String::from).collect(),
        "{code}"
    );
    assert_eq!(
        constants(&code),
        vec![
            (
                "UNITS".to_string(),
                "[(\"mm\", 1), (\"cm\", 2)]".to_string()
            ),
            ("AFTER".to_string(), "1e-9".to_string()),
        ]
    );
    // (Two deep, one `super::` is the same top-level module; two reach the root.)
    assert_eq!(
        reached("use super::x; use super::super::y;", 2)
            .into_iter()
            .collect::<Vec<_>>(),
        ["y"]
    );
}
