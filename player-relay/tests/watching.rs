//! Watching drives subscribing, for the fronts whose viewers are not pages (the page's own
//! test is player-web's `watching.rs`): the relay is subscribed to none of a robot's devices
//! upstream while nobody looks, to the laser while a Foxglove client is subscribed to its scan
//! channel (Foxglove's own client library, over real TCP) or a Zenoh subscriber matches its
//! data key, and to none again once they leave. The Zenoh test runs in a network namespace
//! of its own, loopback only: nothing leaves the machine.

mod zenoh_support;

use std::io::{BufRead, BufReader};
use std::net::{IpAddr, Ipv4Addr};
use std::path::Path;
use std::process::{Command, Stdio};
use std::sync::Arc;
use std::time::{Duration, Instant};

use player_foxglove::live::FoxgloveLive;
use player_proto::wire::Interface;
use player_relay::{Relay, RelayConfig, Route};
use player_zenoh::Mode;
use player_zenoh::keys::Leaf;
use player_zenoh::zenoh::Wait;
use zenoh_support::{PATIENCE, Site, free_port, inside_own_namespace, serve_world, session};

const LASER: (Interface, u16) = (Interface::LASER, 0);

/// Waits until `done`, at most [`PATIENCE`]; whether it came.
fn wait_for(mut done: impl FnMut() -> bool) -> bool {
    let end = Instant::now() + PATIENCE;
    while Instant::now() < end {
        if done() {
            return true;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    done()
}

fn subscribed(relay: &Relay) -> Vec<(Interface, u16)> {
    relay.robots()[0].upstream_subscriptions()
}

#[test]
fn a_foxglove_client_on_a_scan_channel_subscribes_the_laser_while_it_is_on_it() {
    program_edge::logging::init("warn");
    let running = serve_world("simple.world", None);
    let live = FoxgloveLive::start(IpAddr::V4(Ipv4Addr::LOCALHOST), 0).expect("front starts");
    let live = Arc::new(live);
    let relay = Relay::start(RelayConfig {
        routes: vec![Route::loopback(running.ports[0].1)],
        fronts: vec![live.clone() as _],
        ..RelayConfig::default()
    })
    .expect("relay starts");
    let scan_topic = |topics: Vec<String>| topics.iter().any(|t| t.ends_with("/laser/0/scan"));
    assert!(
        wait_for(|| scan_topic(live.topics())),
        "{:?}",
        live.topics()
    );
    assert!(
        wait_for(|| subscribed(&relay).is_empty()),
        "nobody looks: {:?}",
        subscribed(&relay)
    );

    let web = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/web");
    let url = format!("ws://127.0.0.1:{}", live.port());
    let mut client = Command::new("node")
        .current_dir(&web)
        .args(["foxglove_client.mjs", "watch", &url, "/laser/0/scan$", "2"])
        .arg("60000")
        .stdout(Stdio::piped())
        .spawn()
        .expect("node runs (scripts/setup.sh installs it)");
    let mut lines = BufReader::new(client.stdout.take().expect("stdout")).lines();
    let first = lines.next().and_then(Result::ok);
    assert_eq!(first.as_deref(), Some("WATCHING"), "the client got scans");
    assert_eq!(subscribed(&relay), [LASER], "the laser alone");
    assert_eq!(live.looks(), 1);
    let seen: serde_json::Value =
        serde_json::from_str(&lines.next().and_then(Result::ok).expect("its JSON")).expect("JSON");
    assert_eq!(seen["channels"], 1, "{seen}");
    assert!(seen["messages"].as_f64().unwrap_or(0.0) > 0.0, "{seen}");
    assert!(client.wait().expect("node ends").success());
    assert!(
        wait_for(|| subscribed(&relay).is_empty()),
        "let go: {:?}",
        subscribed(&relay)
    );
}

#[test]
fn a_zenoh_subscriber_on_a_data_key_subscribes_the_laser_while_it_matches() {
    if !inside_own_namespace(
        "a_zenoh_subscriber_on_a_data_key_subscribes_the_laser_while_it_matches",
    ) {
        return;
    }
    program_edge::logging::init("warn");
    let running = serve_world("simple.world", None);
    let zport = free_port();
    let robot_side = session(Mode::Peer, Some(zport), None);
    let viewer_side = session(Mode::Peer, None, Some(zport));
    let site = Site::start(robot_side, "A", "teacher", &running);
    assert!(wait_for(|| site.front.announced() == 1), "announced");
    assert!(
        wait_for(|| subscribed(&site.relay).is_empty()),
        "nobody subscribed in Zenoh: {:?}",
        subscribed(&site.relay)
    );

    let robot = site.front.robot_key("127.0.0.1", running.ports[0].1);
    let key = robot.device(Interface::LASER, 0, Leaf::Data);
    let subscriber = viewer_side
        .declare_subscriber(key.clone())
        .wait()
        .expect("the subscriber is declared");
    assert!(
        wait_for(|| subscribed(&site.relay) == [LASER]),
        "the laser alone while {key} is matched: {:?}",
        subscribed(&site.relay)
    );
    let scan = subscriber
        .recv_timeout(PATIENCE)
        .expect("the subscriber's channel")
        .expect("a scan through Zenoh");
    assert_eq!(scan.key_expr().as_str(), key);
    drop(subscriber);
    assert!(
        wait_for(|| subscribed(&site.relay).is_empty()),
        "let go once nobody matches: {:?}",
        subscribed(&site.relay)
    );
}
