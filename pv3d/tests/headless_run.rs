//! `pv3d --headless` without a screenshot is a run with no display: a recording, a script or a
//! measurement, ended by `--quit-after`. It records what the robots sent, says its frames, and
//! never opens a window (no DISPLAY is given to it).

mod support;

use std::time::{Duration, Instant};

use player_proto::recording::{Event, RecordingReader};
use support::{pv3d, run_ok};

#[test]
fn a_headless_run_records_until_quit_after_with_no_display() {
    let dir = tempfile::tempdir().unwrap();
    let recording = dir.path().join("run.prec");
    let started = Instant::now();
    let out = run_ok(
        pv3d()
            .args(["--world", "stage-worlds/simple.world", "--headless"])
            .arg("--record")
            .arg(&recording)
            .args(["--quit-after", "2", "--frame-stats"])
            .env_remove("DISPLAY")
            .env_remove("WAYLAND_DISPLAY"),
    );
    assert!(
        started.elapsed() < Duration::from_secs(30),
        "it ended by itself"
    );
    let err = String::from_utf8_lossy(&out.stderr);
    let frames: u64 = err
        .lines()
        .find_map(|l| l.strip_prefix("frames: "))
        .and_then(|rest| rest.split_whitespace().next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("a frames line: {err}"));
    // 2 s at the 0.1 s redraw interval.
    assert!((5..=21).contains(&frames), "{frames} frames: {err}");
    // The robot's every device reported: a whole picture, and each stage of a frame timed.
    assert!(err.contains("the first whole picture at "), "{err}");
    let stages = err
        .lines()
        .find_map(|l| l.strip_prefix("per frame: "))
        .unwrap_or_else(|| panic!("a per-frame line: {err}"));
    for stage in ["update", "batch", "interface", "whole frame"] {
        assert!(stages.contains(stage), "{stage} in {stages}");
    }

    let file = std::fs::File::open(&recording).unwrap();
    let mut reader = RecordingReader::new(std::io::BufReader::new(file)).unwrap();
    let (mut connections, mut messages) = (0, 0);
    while let Some(record) = reader.next_record().unwrap() {
        match record.event {
            Event::Connection { .. } => connections += 1,
            Event::Message { .. } => messages += 1,
            _ => {}
        }
    }
    assert!(connections >= 1, "the robot's connection was recorded");
    assert!(messages > 20, "2 s of a robot's data: {messages} messages");
}
