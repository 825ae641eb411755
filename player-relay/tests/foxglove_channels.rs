//! The Foxglove front's channels come from what a robot has, not from what it sent, and the
//! front runs on a runtime it is handed — against Foxglove's own client
//! (`@foxglove/ws-protocol`, run by Node from tests/web/foxglove_client.mjs).
//!
//! The robot is the relay tests' mock: its laser sends nothing until the test publishes, and a
//! scan published reaches only those subscribed to it.

use std::net::{IpAddr, Ipv4Addr, TcpListener};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use player_foxglove::live::FoxgloveLive;
use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::message::Body;
use player_proto::wire::{DevAddr, Interface};
use player_relay::RelayConfig;

mod foxglove_node;
mod support;

use foxglove_node::{live_url, run_node};
use support::{Robot, relay_for};

const LOCALHOST: IpAddr = IpAddr::V4(Ipv4Addr::LOCALHOST);
/// Long enough for anything on a loaded machine; only reached when something is broken.
const PATIENCE: Duration = Duration::from_secs(30);

fn wait_for(what: &str, done: impl Fn() -> bool) {
    let deadline = Instant::now() + PATIENCE;
    while !done() {
        assert!(Instant::now() < deadline, "never: {what}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Publishes a scan every 50 ms until dropped; a scan reaches only those subscribed.
struct Publishing(Arc<AtomicBool>, Option<std::thread::JoinHandle<usize>>);

impl Publishing {
    fn start(robot: &Robot) -> Publishing {
        let stop = Arc::new(AtomicBool::new(false));
        let stopping = stop.clone();
        let publisher = robot.server.publisher();
        let mut laser = DevAddr::local(Interface::LASER, 0);
        laser.robot = u32::from(robot.port());
        let thread = std::thread::spawn(move || {
            let (mut id, mut delivered) = (0, 0);
            while !stopping.load(Ordering::Relaxed) {
                id += 1;
                let scan = LaserScan {
                    ranges: vec![1.5; 181],
                    id,
                    ..LaserScan::default()
                };
                delivered += publisher.publish(laser, 1, Body::Laser(Laser::Scan(scan)), 0.0);
                std::thread::sleep(Duration::from_millis(50));
            }
            delivered
        });
        Publishing(stop, Some(thread))
    }
}

impl Drop for Publishing {
    fn drop(&mut self) {
        self.0.store(true, Ordering::Relaxed);
        let _ = self.1.take().map(std::thread::JoinHandle::join);
    }
}

#[test]
fn a_laser_that_never_sent_has_a_channel_and_a_subscriber_makes_it_send() {
    let robot = Robot::start(0);
    let live = Arc::new(FoxgloveLive::start(LOCALHOST, 0).expect("the front starts"));
    let (relay, _) = relay_for(
        &robot,
        RelayConfig {
            fronts: vec![live.clone() as _],
            ..RelayConfig::default()
        },
    );
    let scan_topic = format!("/127.0.0.1:{}/laser/0/scan", robot.port());
    // Nothing was published: the channel comes from the robot's device list.
    wait_for("the laser's channel", || {
        live.topics().contains(&scan_topic)
    });
    // The survey let go of everything: nobody looks, so the relay subscribes to nothing.
    wait_for("no upstream subscription", || {
        relay.robots()[0].upstream_subscriptions().is_empty()
    });
    // A scan now reaches nobody: the relay is not subscribed.
    wait_for("the robot's server to have no subscriber", || {
        robot.publish_scan(0) == 0
    });
    let publishing = Publishing::start(&robot);

    let want = serde_json::json!({ "scans": 5, "topics": [scan_topic] }).to_string();
    let seen = run_node(&["observe", &live_url(&live), &want, "60000"]);
    let scans = seen["scans"].as_array().expect("scans");
    assert!(
        scans
            .iter()
            .filter(|s| s["topic"] == scan_topic.as_str())
            .count()
            >= 5,
        "{seen:#}"
    );
    drop(publishing);
    // The viewer went: the relay lets go of the laser again.
    wait_for("the laser let go", || {
        !relay.robots()[0]
            .upstream_subscriptions()
            .contains(&(Interface::LASER, 0))
    });
}

#[test]
fn a_front_on_a_handed_runtime_serves_and_once_dropped_frees_its_port() {
    let handed = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .unwrap();
    let robot = Robot::start(0);
    let live =
        FoxgloveLive::start_on(handed.handle().clone(), LOCALHOST, 0).expect("the front starts");
    let live = Arc::new(live);
    assert_eq!(live.tasks(), 1, "its listener");
    let (relay, _) = relay_for(
        &robot,
        RelayConfig {
            fronts: vec![live.clone() as _],
            ..RelayConfig::default()
        },
    );
    let scan_topic = format!("/127.0.0.1:{}/laser/0/scan", robot.port());
    wait_for("the laser's channel", || {
        live.topics().contains(&scan_topic)
    });
    let publishing = Publishing::start(&robot);
    let want = serde_json::json!({ "scans": 3 }).to_string();
    let seen = run_node(&["observe", &live_url(&live), &want, "60000"]);
    assert!(seen["scans"].as_array().is_some_and(|s| s.len() >= 3));
    drop(publishing);

    let port = live.port();
    // The relay stops its fronts once its robots stopped, and lets go of its share.
    drop(relay);
    assert_eq!(live.tasks(), 0, "stopped with the relay");
    drop(live);
    wait_for("the port freed", || {
        TcpListener::bind((LOCALHOST, port)).is_ok()
    });
    let ran = handed.block_on(handed.spawn(async { 7 })).unwrap();
    assert_eq!(ran, 7, "the handed runtime runs on");
}
