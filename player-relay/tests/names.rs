//! A robot is named alike by every front: by the name the person gives it (`HOST:PORT=NAME`)
//! or the world it is simulated in gives it (`--world`, `--demo`), else by its server.

mod support;

use std::io::Read;
use std::net::{IpAddr, Ipv4Addr};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use player_foxglove::live::FoxgloveLive;
use player_proto::RobotId;
use player_relay::{Relay, RelayConfig, RelayError, Route};
use support::{PATIENCE, Robot};

const RELAY: &str = env!("CARGO_BIN_EXE_player-relay");

fn named(port: u16, name: &str) -> Route {
    Route {
        robot: RobotId::new("127.0.0.1", port).named(name).expect("a name"),
        listen_port: 0,
    }
}

#[test]
fn a_named_robot_is_a_foxglove_topic_under_its_name() {
    let robot = Robot::start(0);
    let live = FoxgloveLive::start(IpAddr::V4(Ipv4Addr::LOCALHOST), 0).expect("front starts");
    let live = std::sync::Arc::new(live);
    let _relay = Relay::start(RelayConfig {
        routes: vec![named(robot.port(), "scout")],
        fronts: vec![live.clone() as _],
        ..RelayConfig::default()
    })
    .expect("relay starts");
    let deadline = Instant::now() + PATIENCE;
    while live.topics().is_empty() && Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(20));
    }
    let topics = live.topics();
    assert!(!topics.is_empty(), "no topic in {PATIENCE:?}");
    assert!(
        topics.iter().all(|t| t.starts_with("/scout/")),
        "every topic under the robot's name: {topics:?}"
    );
}

#[test]
fn two_robots_given_one_name_are_refused() {
    let outcome = Relay::start(RelayConfig {
        routes: vec![named(6665, "scout"), named(6666, "scout")],
        ..RelayConfig::default()
    });
    assert!(
        matches!(outcome, Err(RelayError::SameName(ref name)) if name == "scout"),
        "{:?}",
        outcome.err()
    );
}

/// What the relay says on standard error about where each robot is served, for `args`.
fn announced(args: &[&str]) -> Vec<String> {
    let mut child = Command::new(RELAY)
        .args(args)
        .args(["--seconds", "2"])
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .env("RUST_LOG", "warn")
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("player-relay starts");
    let mut stderr = String::new();
    child
        .stderr
        .take()
        .expect("piped")
        .read_to_string(&mut stderr)
        .expect("standard error reads");
    assert!(child.wait().expect("it ends").success(), "{stderr}");
    stderr
        .lines()
        .filter(|l| l.contains(" → "))
        .map(|l| l.split(" → ").next().unwrap_or_default().to_string())
        .collect()
}

#[test]
fn a_simulated_world_names_its_robots_after_its_models() {
    let mut robots = announced(&["--world", "stage-worlds/multirobot.world"]);
    robots.iter_mut().for_each(|r| r.truncate(2));
    robots.sort();
    robots.dedup();
    assert_eq!(robots, ["r0", "r1", "r2", "r3", "r4"]);
    // Three robots on one port: the port is one robot to the relay, named by its server.
    let oneport = announced(&["--world", "stage-worlds/oneport.world"]);
    assert!(
        oneport.iter().all(|r| r.starts_with("127.0.0.1:")),
        "{oneport:?}"
    );
}

#[test]
fn a_robot_is_named_on_the_command_line() {
    let robot = Robot::start(0);
    let port = robot.port();
    let free = std::net::TcpListener::bind("127.0.0.1:0").expect("a free port");
    let listen = free.local_addr().expect("bound").port();
    drop(free);
    let robots = announced(&[&format!("127.0.0.1:{port}={listen}=scout")]);
    assert!(
        robots.contains(&format!("scout (127.0.0.1:{port})")),
        "{robots:?}"
    );
    let refused = Command::new(RELAY)
        .arg(format!("127.0.0.1:{port}=two words"))
        .output()
        .expect("player-relay runs");
    assert!(!refused.status.success());
    assert!(String::from_utf8_lossy(&refused.stderr).contains("bad robot name"));
}
