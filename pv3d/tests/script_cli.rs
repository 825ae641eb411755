//! `pv3d --script` and `--grammar` read their files before anything starts: a mistake is
//! reported naming file:line (a script) or file:line:col (a grammar), and nothing runs. And the
//! README's tour runs: a classroom robot told in a script to go to the charging zone goes.

use std::process::Command;

fn pv3d_with(args: &[&std::ffi::OsStr]) -> String {
    let composition = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../configs/single-laser.pv3d.xml"
    );
    let out = Command::new(env!("CARGO_BIN_EXE_pv3d"))
        .arg(composition)
        .args(["--headless", "--screenshot", "/nonexistent/never.png"])
        .args(args)
        .output()
        .unwrap();
    assert!(!out.status.success(), "a bad file must stop pv3d");
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[test]
fn a_bad_script_line_stops_pv3d_naming_it() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("tour.txt");
    std::fs::write(&script, "# a tour\n1 robot1 go to dock\nsoon robot1 stop\n").unwrap();
    let err = pv3d_with(&["--script".as_ref(), script.as_os_str()]);
    let expected = format!(
        "{}:3: \"soon\" is not a number of seconds",
        script.display()
    );
    assert!(err.contains(&expected), "{err}");
}

#[test]
fn a_bad_grammar_stops_pv3d_naming_its_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    let grammar = dir.path().join("mine.grammar.xml");
    std::fs::write(
        &grammar,
        "<commandGrammar start=\"s\">\n  <state name=\"s\">\n    <slot kind=\"robot\" fills=\"subject\" next=\"t\"/>\n  </state>\n</commandGrammar>\n",
    )
    .unwrap();
    let err = pv3d_with(&["--grammar".as_ref(), grammar.as_os_str()]);
    let expected = format!("{}:3:5: no state named \"t\"", grammar.display());
    assert!(err.contains(&expected), "{err}");
}

/// The README's example: `pv3d --world stage-worlds/classroom.world --script tour.txt` (the
/// world's own composition, with its zones), offscreen.
#[test]
fn the_readmes_tour_sends_robot4_to_charging() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("tour.txt");
    std::fs::write(&script, "1 robot4 go to charging\n6 all robots stop\n").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_pv3d"))
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .args(["--world", "stage-worlds/classroom.world", "--script"])
        .arg(&script)
        .args(["--headless", "--after", "2.5", "--screenshot"])
        .arg(dir.path().join("tour.png"))
        .env("RUST_LOG", "info")
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(
        err.contains("robot4: going to zone charging"),
        "the script's first line was carried out: {err}"
    );
    assert!(!err.contains("ERROR"), "{err}");
}
