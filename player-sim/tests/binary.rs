//! The `player-sim` program itself: serves on --port-base, steps --headless-once N times and
//! exits cleanly; a broken world fails with its file:line:col and a non-zero status.

mod support;

use std::io::{BufRead, BufReader};
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use player_proto::client::{Client, ClientOptions};
use support::free_port;

#[test]
fn headless_once_serves_on_the_port_base_then_exits() {
    let world = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds/simple.world");
    let port = free_port();
    // 30 steps of 0.1 s at real time: 3 s in which a client connects.
    let mut child = Command::new(env!("CARGO_BIN_EXE_player-sim"))
        .arg(&world)
        .args(["--headless-once", "30", "--port-base", &port.to_string()])
        .args(["--seed", "3", "--range-noise", "0.01"])
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stderr = BufReader::new(child.stderr.take().unwrap());
    let mut line = String::new();
    while !line.contains("serving") {
        line.clear();
        assert!(stderr.read_line(&mut line).unwrap() > 0, "no serving line");
    }
    assert!(
        line.trim_end().ends_with(&format!("on port(s) {port}")),
        "{line}"
    );
    let client = Client::connect("127.0.0.1", port, ClientOptions::default()).unwrap();
    let base = client.position2d(0);
    assert_eq!(base.subscribe().unwrap(), "stage");
    let deadline = Instant::now() + Duration::from_secs(3);
    while base.state().is_none() {
        assert!(Instant::now() < deadline, "no odometry");
        std::thread::sleep(Duration::from_millis(10));
    }
    drop(client);
    let started = Instant::now();
    let status = child.wait().unwrap();
    assert!(status.success(), "{status}");
    assert!(
        started.elapsed() < Duration::from_secs(5),
        "it stopped after its steps"
    );
}

/// player-sim serving `world` for one step on a free port.
fn one_step(world: &Path) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_player-sim"));
    command.arg(world).args([
        "--headless-once",
        "1",
        "--port-base",
        &free_port().to_string(),
    ]);
    command
}

#[test]
fn a_broken_world_fails_with_its_position() {
    let dir = tempfile::tempdir().unwrap();
    let world = dir.path().join("broken.world");
    std::fs::write(
        &world,
        "interval_sim 100\nposition( name \"r\" pose [ 0 0 0\n",
    )
    .unwrap();
    let out = one_step(&world).output().unwrap();
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains(&format!("{}:2:", world.display())),
        "{stderr}"
    );
}

/// A log written to a pipe (or a file) is read by programs and editors, not a terminal: no
/// ANSI colour codes in it.
#[test]
fn a_log_written_to_a_pipe_carries_no_colour_codes() {
    let world = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds/simple.world");
    let out = one_step(&world)
        .env_remove("NO_COLOR")
        .env("RUST_LOG", "info")
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", out.status);
    let log = String::from_utf8_lossy(&out.stderr);
    assert!(log.contains("serving"), "{log}");
    assert!(
        !log.contains('\u{1b}'),
        "escape codes in a piped log: {log:?}"
    );
}

#[test]
fn a_lockstep_run_nobody_drives_goes_on_after_the_patience_and_records_itself() {
    let world = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds/simple.world");
    let dir = tempfile::tempdir().unwrap();
    let record = dir.path().join("run.mcap");
    let started = Instant::now();
    let output = Command::new(env!("CARGO_BIN_EXE_player-sim"))
        .arg(&world)
        .args(["--lockstep", "--patience", "0.3", "--until", "2"])
        .args(["--port-base", &free_port().to_string()])
        .arg("--record")
        .arg(&record)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{stderr}");
    assert!(stderr.contains("runs on its own"), "{stderr}");
    assert!(
        started.elapsed() < Duration::from_secs(10),
        "20 steps, nobody waited for past the patience"
    );
    let file = std::fs::File::open(&record).unwrap();
    let mut records = player_mcap::McapRecords::new(std::io::BufReader::new(file));
    let (mut last_ns, mut data) = (0, 0);
    while let Some(record) = records.next_record().unwrap() {
        last_ns = last_ns.max(record.time_ns);
        if let player_proto::recording::Event::Message { header, .. } = &record.event {
            data += 1;
            let recorded = record.time_ns as f64 / 1e9;
            assert!(
                (header.timestamp - recorded).abs() < 1e-6,
                "stamped with simulated time: {} at {recorded}",
                header.timestamp
            );
        }
    }
    assert!(
        last_ns.abs_diff(2_000_000_000) < 1_000,
        "the last step at 2 s simulated: {last_ns} ns"
    );
    assert!(data >= 20 * 3, "every device every step: {data}");
}
