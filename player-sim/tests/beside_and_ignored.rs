//! Every world Stage runs, player-sim runs: a `.cfg` lying beside a world that names models the
//! world lacks (Stage's roomba.world and roomba.cfg) is a warning and one port per robot, not a
//! refusal; and what is not simulated is said once, in one line, however many models ask it.

use std::path::Path;
use std::process::Command;

use player_sim::served::{Source, devices_beside, from_cfgs};
use player_sim::world::World;

/// A world like Stage's roomba.world: its robot is `r0`, and the cfg beside it, written for
/// another world, names `roomba0`. Several models repeat properties player-sim does not read.
const WORLD: &str = r#"
interval_sim 100
resolution 0.02
gui_disable 1
window ( size [ 600 600 ] scale 30 )
define bot position
(
  size [ 0.33 0.33 0.1 ]
  gui_nose 1
  blinkenlight ( color "green" )
)
floorplan ( name "room" size [ 8 8 0.5 ] boundary 1 gui_move 0 )
bot ( name "r0" pose [ 0 0 0 0 ] )
bot ( name "r1" pose [ 1 0 0 0 ] )
bot ( name "r2" pose [ 2 0 0 0 ] )
"#;

const CFG: &str = r#"
driver ( name "stage" provides [ "simulation:0" ] plugin "stageplugin" worldfile "w.world" )
driver ( name "stage" provides [ "position2d:0" "bumper:0" ] model "roomba0" )
"#;

fn write_pair(dir: &Path) -> std::path::PathBuf {
    let world = dir.join("w.world");
    std::fs::write(&world, WORLD).unwrap();
    std::fs::write(dir.join("w.cfg"), CFG).unwrap();
    world
}

#[test]
fn a_cfg_beside_the_world_naming_other_models_gives_one_port_per_robot() {
    let dir = tempfile::tempdir().unwrap();
    let path = write_pair(dir.path());
    let world = World::load(&path).unwrap();
    let devices = devices_beside(&path, &world, &mut Vec::new()).unwrap();
    let mut ports: Vec<u16> = devices
        .iter()
        .filter(|d| matches!(d.source, Source::Position { .. }))
        .map(|d| d.port)
        .collect();
    ports.sort_unstable();
    assert_eq!(ports, [6665, 6666, 6667]);
    // Named on purpose, the same file is refused where it names the missing model.
    let cfg = dir.path().join("w.cfg");
    let refused = from_cfgs(&[cfg.as_path()], &world, &mut Vec::new())
        .unwrap_err()
        .to_string();
    assert!(
        refused.contains("w.cfg:3:") && refused.contains("roomba0"),
        "{refused}"
    );
}

#[test]
fn the_program_runs_such_a_world_and_says_what_it_ignores_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = write_pair(dir.path());
    let port = std::net::TcpListener::bind("127.0.0.1:0")
        .unwrap()
        .local_addr()
        .unwrap()
        .port();
    let out = Command::new(env!("CARGO_BIN_EXE_player-sim"))
        .arg(&path)
        .args(["--headless-once", "1", "--speedup", "0"])
        .args(["--port-base", &port.to_string()])
        .env("RUST_LOG", "info")
        .env("NO_COLOR", "1")
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    let lines: Vec<&str> = stderr.lines().collect();
    let warned: Vec<&&str> = lines.iter().filter(|l| l.contains("WARN")).collect();
    assert_eq!(warned.len(), 2, "{stderr}");
    assert!(
        warned[0].contains("\"roomba0\"") && warned[0].contains("one port per robot"),
        "{stderr}"
    );
    let summary = warned[1];
    // Each property is counted once per place it is written, not once per robot using it.
    for said in [
        "world property gui_disable",
        "window (the Stage GUI)",
        "bot property gui_nose;",
        "a blinkenlight's light (its body is solid);",
        "floorplan property gui_move",
    ] {
        assert!(summary.contains(said), "{said} in {summary}");
    }
    assert!(summary.contains("things in 7 places)"), "{summary}");
    assert_eq!(stderr.matches("gui_nose").count(), 1, "said once: {stderr}");
    let serving = format!("on port(s) {port}–{}", port + 2);
    assert!(stderr.contains(&serving), "{stderr}");
}
