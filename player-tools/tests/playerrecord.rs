//! `playerrecord` end to end on real Player traffic: the repository's captures turned into a
//! recording, summarised, and exported as a Player log whose every line has the words
//! `readlog` expects for its message.

use std::path::{Path, PathBuf};
use std::process::Command;

use player_proto::recording::{self, Event};

fn captures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../captures")
}

fn playerrecord(args: &[&str]) -> std::process::Output {
    let out = Command::new(env!("CARGO_BIN_EXE_playerrecord"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "playerrecord {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// Words `readlog` needs on a line: the 7 of the header, then the payload's.
fn expected_words(interface: &str, kind: &str, subtype: &str, payload: &[&str]) -> usize {
    let count = |at: usize| payload[at].parse::<usize>().unwrap();
    7 + match (interface, kind, subtype) {
        ("position2d", "001", "001") => 7,
        ("position2d", "004", "001") | ("laser", "004", "001") => 5,
        ("laser", "001", "001") => 6 + 2 * count(5),
        ("sonar", "001", "001") | ("ranger", "001", "001") | ("ranger", "001", "003") => {
            1 + count(0)
        }
        ("sonar", _, _) => 1 + 3 * count(0),
        ("ranger", "004", "001") => {
            let poses = count(9);
            11 + 6 * poses + 3 * count(10 + 6 * poses)
        }
        other => panic!("an exported line of a kind not covered: {other:?}"),
    }
}

#[test]
fn captures_become_a_recording_and_a_player_log_readlog_can_read() {
    let dir = tempfile::tempdir().unwrap();
    let rec = dir.path().join("captures.prec");
    let log = dir.path().join("captures.log");
    let inputs = [
        "laser_push.jsonl",
        "position2d_push.jsonl",
        "sonar_push.jsonl",
        "ranger_sonar_push.jsonl",
        "geom_config.jsonl",
    ]
    .map(|name| captures().join(name));
    let mut args = vec!["from-capture", "-o", rec.to_str().unwrap()];
    args.extend(inputs.iter().map(|p| p.to_str().unwrap()));
    playerrecord(&args);

    let records: Vec<_> = recording::open(&rec).unwrap().map(Result::unwrap).collect();
    let connections = records
        .iter()
        .filter(|r| matches!(r.event, Event::Connection { .. }))
        .count();
    assert_eq!(connections, inputs.len());
    let info = String::from_utf8(playerrecord(&["info", rec.to_str().unwrap()]).stdout).unwrap();
    assert!(info.contains("5 connections"), "{info}");
    assert!(info.contains("laser:0"), "{info}");

    playerrecord(&["export", rec.to_str().unwrap(), "-o", log.to_str().unwrap()]);
    let text = std::fs::read_to_string(&log).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("## Player version 3.1.1-dev "));
    assert_eq!(lines.next(), Some("## File version 0.3.0 "));
    let mut kinds = std::collections::BTreeSet::new();
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let words: Vec<&str> = line.split_whitespace().collect();
        let (interface, kind, subtype) = (words[3], words[5], words[6]);
        assert!(words[0].parse::<f64>().is_ok(), "{line}");
        assert_eq!(words[2], "6665", "the recorded port: {line}");
        assert_eq!(
            words.len(),
            expected_words(interface, kind, subtype, &words[7..]),
            "{line}"
        );
        kinds.insert(format!("{interface} {kind} {subtype}"));
    }
    for kind in [
        "laser 001 001",
        "laser 004 001",
        "position2d 001 001",
        "sonar 001 001",
        "ranger 001 001",
        "ranger 004 001",
    ] {
        assert!(kinds.contains(kind), "no {kind} line in {kinds:?}");
    }
}
