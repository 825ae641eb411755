//! Where the recorded Player sessions are: `captures/` at the repository root, or the folder
//! named by `PLAYER_CAPTURES_DIR` (e.g. the full, untrimmed set). Missing data fails the test
//! that needs it, naming the path: a golden test that quietly passes without its data proves
//! nothing.

use std::path::PathBuf;

/// Overrides the repository's folder.
pub const CAPTURES_DIR_VAR: &str = "PLAYER_CAPTURES_DIR";

/// The captures folder; panics if it is not there.
pub fn captures_dir() -> PathBuf {
    let dir = std::env::var_os(CAPTURES_DIR_VAR)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../captures"));
    assert!(
        dir.is_dir(),
        "missing captures folder {} (the repository's captures/, or set {CAPTURES_DIR_VAR})",
        dir.display()
    );
    dir
}

/// One file of the captures folder (`name` may have folders: `nav/map_info_data.jsonl`);
/// panics if it is not there.
pub fn capture(name: &str) -> PathBuf {
    let path = captures_dir().join(name);
    assert!(path.is_file(), "missing capture {}", path.display());
    path
}
