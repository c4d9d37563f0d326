//! The repository's copy of the interface contract, `docs/interfaces.md`, is the shared
//! contract word for word. Where the shared copy sits beside the checkout (`../shared/`, as in
//! the project's workspace and CI), any difference fails: the copy must be brought in step.
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
    assert!(
        ours == theirs,
        "docs/interfaces.md differs from {}: copy the shared contract over",
        shared.display()
    );
}
