//! Foxglove's own client (`@foxglove/ws-protocol`), run by Node from
//! tests/web/foxglove_client.mjs, for the tests of the relay's Foxglove front.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;

use player_foxglove::live::FoxgloveLive;
use serde_json::Value;

pub fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("player-relay lies in the checkout")
        .to_path_buf()
}

/// `node tests/web/foxglove_client.mjs ARGS…`; fails (never skips) when Node or the pinned
/// clients are missing.
pub fn node(args: &[&str]) -> Command {
    let web = repo_root().join("tests/web");
    assert!(
        web.join("node_modules/@foxglove/ws-protocol").is_dir()
            && web.join("node_modules/protobufjs").is_dir(),
        "tests/web/node_modules is missing or stale: run scripts/setup.sh \
         (or npm ci --prefix tests/web)"
    );
    let mut command = Command::new("node");
    command
        .current_dir(&web)
        .arg("foxglove_client.mjs")
        .args(args);
    command
}

/// Runs the script to its end and parses what it printed.
pub fn run_node(args: &[&str]) -> Value {
    let output = node(args)
        .output()
        .expect("node runs (install Node.js 20 or later: scripts/setup.sh)");
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "foxglove_client.mjs {args:?} failed: {}\n{stdout}\n{}",
        output.status,
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_str(stdout.trim()).expect("the script prints JSON")
}

pub fn live_url(live: &FoxgloveLive) -> String {
    format!("ws://127.0.0.1:{}", live.port())
}
