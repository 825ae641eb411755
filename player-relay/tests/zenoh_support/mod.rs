//! The Zenoh tests' rig: a player-sim world on loopback, a relay with a Zenoh front on one
//! Zenoh session, bridges (`FromZenoh`) on another, and ordinary Player clients.

#![allow(dead_code)]

use std::collections::HashMap;
use std::net::TcpListener;
use std::path::Path;
use std::time::{Duration, Instant};

use player_proto::client::{Backoff, Client, ClientOptions};
use player_proto::interfaces::laser::Laser;
use player_proto::wire::{DevAddr, Interface};
use player_relay::{Relay, RelayConfig, Route};
use player_sim::serve::{Running, ServeOptions, serve_world_file};
use player_zenoh::zenoh::Session;
use player_zenoh::{FrontConfig, Mode, ZenohFront, ZenohOptions};

/// Long enough for anything on loopback; only reached when something is broken.
pub const PATIENCE: Duration = Duration::from_secs(20);

pub fn free_port() -> u16 {
    TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .expect("a free port")
        .port()
}

pub fn tcp(port: u16) -> String {
    format!("tcp/127.0.0.1:{port}")
}

/// A Zenoh session on loopback only (no scouting).
pub fn session(mode: Mode, listen: Option<u16>, connect: Option<u16>) -> Session {
    ZenohOptions {
        mode: Some(mode),
        listen: listen.map(tcp).into_iter().collect(),
        connect: connect.map(tcp).into_iter().collect(),
        no_scouting: true,
        ..ZenohOptions::default()
    }
    .open()
    .expect("the Zenoh session opens")
}

/// Serves `world` from stage-worlds/, every robot on a free port, or on `ports`' actual
/// ports (a server restarted where it was).
pub fn serve_world(world: &str, ports: Option<&[(u16, u16)]>) -> Running {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../stage-worlds")
        .join(world);
    let options = ServeOptions {
        free_ports: ports.is_none(),
        ..ServeOptions::default()
    };
    serve_world_file(&path, options, ports.unwrap_or_default(), &mut Vec::new())
        .expect("the world is served")
}

/// Client options that notice and retry quickly.
pub fn quick() -> ClientOptions {
    ClientOptions {
        connect_timeout: Duration::from_secs(2),
        request_timeout: Duration::from_secs(5),
        backoff: Backoff {
            initial: Duration::from_millis(20),
            max: Duration::from_millis(200),
            max_attempts: None,
        },
        ..ClientOptions::default()
    }
}

/// The robot's site: a relay of `running`'s robots with a Zenoh front.
pub struct Site {
    pub front: std::sync::Arc<ZenohFront>,
    pub relay: Relay,
}

impl Site {
    pub fn start(session: Session, site: &str, controller: &str, running: &Running) -> Site {
        let config = FrontConfig {
            controller: Some(controller.into()),
            ..FrontConfig::new(site)
        };
        let front = ZenohFront::start(session, config).expect("the front starts");
        let front = std::sync::Arc::new(front);
        let routes = running
            .ports
            .iter()
            .map(|&(_, port)| Route::loopback(port))
            .collect();
        let relay = Relay::start(RelayConfig {
            routes,
            fronts: vec![front.clone() as _],
            fronts_command: true,
            upstream: quick(),
            ..RelayConfig::default()
        })
        .expect("the relay starts");
        Site { front, relay }
    }
}

pub fn connect(port: u16) -> Client {
    Client::connect("127.0.0.1", port, quick()).expect("the client connects")
}

pub fn laser_of(client: &Client) -> DevAddr {
    client.addr(Interface::LASER, 0)
}

/// Reads scans through both clients until `wanted` scans with the same timestamp were seen
/// on both; asserts their bodies are equal; returns how many matched.
pub fn matching_scans(direct: &Client, bridged: &Client, wanted: usize) -> usize {
    let mut seen = HashMap::new();
    let mut matched = 0;
    let mut last = None;
    let deadline = Instant::now() + PATIENCE;
    while matched < wanted && Instant::now() < deadline {
        if let Some(scan) = direct.latest(laser_of(direct), Laser::DATA_SCAN.subtype()) {
            let m = &scan.message;
            seen.insert(m.header.timestamp.to_bits(), m.body.clone());
        }
        if let Some(scan) = bridged.latest(laser_of(bridged), Laser::DATA_SCAN.subtype()) {
            let m = &scan.message;
            let stamp = m.header.timestamp.to_bits();
            if last != Some(stamp)
                && let Some(body) = seen.get(&stamp)
            {
                assert_eq!(body, &m.body, "the scan at {} differs", m.header.timestamp);
                matched += 1;
                last = Some(stamp);
            }
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    matched
}

/// Set in a test's own run inside its network namespace.
const IN_OWN_NAMESPACE: &str = "PLAYER_RELAY_TEST_IN_NETNS";

fn is_root() -> bool {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("Uid:"))
                .map(|l| l.split_whitespace().nth(1) == Some("0"))
        })
        .unwrap_or(false)
}

/// Whether to run `test` here: inside its network namespace, yes; outside, it is run again
/// under `unshare --net` with only loopback up (and must pass there), not here. Zenoh's
/// peers then never touch the machine's own network. Needs root (as CI has); anywhere else
/// the test says so and passes without running.
pub fn inside_own_namespace(test: &str) -> bool {
    if std::env::var_os(IN_OWN_NAMESPACE).is_some() {
        return true;
    }
    if !is_root() {
        eprintln!("not root: {test} needs a network namespace of its own and is not run here");
        return false;
    }
    let status = std::process::Command::new("unshare")
        .args([
            "--net",
            "sh",
            "-c",
            r#"ip link set lo up && exec "$0" "$@""#,
        ])
        .arg(std::env::current_exe().expect("the test's own path"))
        .args(["--exact", test, "--nocapture", "--test-threads=1"])
        .env(IN_OWN_NAMESPACE, "1")
        .status()
        .expect("unshare runs");
    assert!(status.success(), "{test} failed in its namespace: {status}");
    false
}
