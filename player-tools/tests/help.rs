//! Each tool's `--help` opens with what that tool does — not the crate's description, which
//! names the other tools (playerrecord said it was "playerprint and playerdump").

use std::process::Command;

fn first_line_of_help(binary: &str) -> String {
    let out = Command::new(binary).arg("--help").output().unwrap();
    assert!(out.status.success(), "{binary} --help");
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .next()
        .unwrap_or_default()
        .to_string()
}

#[test]
fn each_tool_says_what_it_does_itself() {
    assert_eq!(
        first_line_of_help(env!("CARGO_BIN_EXE_playerrecord")),
        "Record Player robots losslessly; summarise, convert and export recordings"
    );
    assert_eq!(
        first_line_of_help(env!("CARGO_BIN_EXE_playerprint")),
        "Print the data of Player devices as it arrives"
    );
    assert_eq!(
        first_line_of_help(env!("CARGO_BIN_EXE_playerdump")),
        "Decode a recorded Player byte stream, one line per message"
    );
}
