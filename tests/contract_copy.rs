//! The repository's copy of the interface contract, `docs/interfaces.md`, is the shared
//! contract word for word, followed only by sections headed `…: compatible additions` (what
//! the libraries add to a document without making any document of the contract invalid).
//! Where the shared copy sits beside the checkout (`../shared/`, as in the project's
//! workspace and CI), any other difference fails: the copy must be brought in step.
#![allow(clippy::unwrap_used)]

use std::path::PathBuf;

#[test]
fn docs_interfaces_is_the_shared_contract() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let ours = std::fs::read_to_string(root.join("docs/interfaces.md")).unwrap();
    assert!(ours.contains("## Command-line tool `curvekit`"));
    let shared = root.join("../shared/interfaces.md");
    let Ok(theirs) = std::fs::read_to_string(&shared) else {
        // A checkout without the shared folder has only its own copy to go by.
        return;
    };
    let Some(additions) = ours.strip_prefix(theirs.as_str()) else {
        panic!(
            "docs/interfaces.md differs from {}: copy the shared contract over",
            shared.display()
        );
    };
    assert!(
        only_compatible_additions(additions),
        "docs/interfaces.md adds to {} more than sections headed `…: compatible additions`",
        shared.display()
    );
}

/// Whether `text` (what follows the shared contract) is empty or only sections whose headings
/// end in `: compatible additions`.
fn only_compatible_additions(text: &str) -> bool {
    let mut in_addition = false;
    for line in text.lines() {
        if let Some(heading) = line.strip_prefix("## ") {
            in_addition = heading.ends_with(": compatible additions");
            if !in_addition {
                return false;
            }
        } else if !in_addition && !line.trim().is_empty() {
            return false;
        }
    }
    true
}

#[test]
fn only_sections_of_compatible_additions_may_follow() {
    assert!(only_compatible_additions(""));
    assert!(only_compatible_additions(
        "\n## Grasps: compatible additions\n\n- `parts`.\n"
    ));
    assert!(!only_compatible_additions("\nA changed line.\n"));
    assert!(!only_compatible_additions(
        "\n## Grasps\n\nA new command.\n"
    ));
}

/// This checkout's copy follows the rule on its own: whatever it adds after its last section
/// of the shared contract is additions only (checked in full where the shared copy is).
#[test]
fn the_additions_are_headed_as_such() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let ours = std::fs::read_to_string(root.join("docs/interfaces.md")).unwrap();
    if let Some(at) = ours.find("\n## Grasps: compatible additions") {
        assert!(only_compatible_additions(&ours[at..]));
    }
}
