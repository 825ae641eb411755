//! The relay's Foxglove front against Foxglove's own client (`@foxglove/ws-protocol`, run by
//! Node from tests/web/foxglove_client.mjs, decoding with protobufjs from the advertised
//! schemas): Stage worlds served in-process by player-sim, relayed with the front on a free
//! port. The scans Foxglove decodes are the ones player-sim served; the frame tree and the map
//! reach a viewer that subscribes after they were sent; bad input is refused without harming
//! others; hundreds of viewers connect at once; viewers that stop reading cost a bounded
//! amount of memory.

use std::io::{BufRead, BufReader, Read};
use std::net::{IpAddr, Ipv4Addr};
use std::path::{Path, PathBuf};
use std::process::Stdio;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use bytes::Bytes;
use player_foxglove::live::FoxgloveLive;
use player_proto::capture::Direction;
use player_proto::client::{Client, ClientOptions, TapEvent};
use player_proto::interfaces::laser::Laser;
use player_proto::interfaces::map::{self, Map};
use player_proto::message::{Body, Message};
use player_proto::wire::{Header, Interface};
use player_relay::{Relay, RelayConfig, Route};
use player_sim::serve::{Running, ServeOptions};
use serde_json::Value;

mod foxglove_node;
use foxglove_node::{live_url, node, repo_root, run_node};

/// Long enough for anything on a loaded machine; only reached when something is broken.
const PATIENCE: Duration = Duration::from_secs(60);

/// Serves a Stage world as `player-sim WORLD` would (its .cfg files), on free ports.
fn serve_world(world: &str) -> Running {
    use player_sim::served::{cfgs_beside, from_cfgs};
    use player_sim::{sim::Simulation, world::World};
    let path = repo_root().join(world);
    let world = World::load(&path).expect("the world loads");
    let cfgs = cfgs_beside(&path);
    let cfgs: Vec<&Path> = cfgs.iter().map(PathBuf::as_path).collect();
    let devices = from_cfgs(&cfgs, &world, &mut Vec::new()).expect("its .cfg files read");
    let options = ServeOptions {
        free_ports: true,
        ..ServeOptions::default()
    };
    player_sim::serve::serve(Simulation::new(world), devices, options).expect("the world serves")
}

/// The relay of the robot on `port`, with the Foxglove front on a free port; returns once
/// the front has a channel with `topic` (so what describes the devices was sent before any
/// viewer connects: a viewer sees it only if it is latched).
fn relay_with_front(port: u16, topic: &str) -> (Relay, Arc<FoxgloveLive>) {
    let live = FoxgloveLive::start(IpAddr::V4(Ipv4Addr::LOCALHOST), 0).expect("front starts");
    let live = Arc::new(live);
    let relay = Relay::start(RelayConfig {
        routes: vec![Route::loopback(port)],
        fronts: vec![live.clone() as _],
        ..RelayConfig::default()
    })
    .expect("relay starts");
    let deadline = Instant::now() + PATIENCE;
    while !live.topics().iter().any(|t| t == topic) {
        assert!(
            Instant::now() < deadline,
            "no {topic} in {:?}",
            live.topics()
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    (relay, live)
}

/// Every laser scan a direct client of the robot got, by timestamp (ns): what player-sim
/// served, to compare with what Foxglove decoded.
type Served = Arc<Mutex<std::collections::HashMap<u64, Vec<f32>>>>;

fn direct_scans(port: u16) -> (Client, Served) {
    let served: Served = Arc::default();
    let record = served.clone();
    let tap: player_proto::client::Tap = Arc::new(move |_: &str, _: u16| {
        let record = record.clone();
        Arc::new(move |_, event| {
            if let TapEvent::Frame {
                direction: Direction::ServerToClient,
                header,
                body,
            } = event
            {
                record_scan(&record, header, body);
            }
        })
    });
    let options = ClientOptions {
        tap: Some(tap),
        ..ClientOptions::default()
    };
    let client = Client::connect("127.0.0.1", port, options).expect("direct client");
    client
        .subscribe(client.addr(Interface::LASER, 0))
        .expect("laser subscribed");
    (client, served)
}

fn record_scan(served: &Served, header: &Header, body: &Bytes) {
    if let Ok(Message {
        body: Body::Laser(Laser::Scan(scan)),
        ..
    }) = Message::decode(*header, body.clone())
    {
        let t = player_foxglove::frames::timestamp(header.timestamp).total_nanos();
        served.lock().unwrap().insert(t, scan.ranges);
    }
}

#[test]
fn foxglove_decodes_the_scans_player_sim_served_in_the_frame_tree() {
    let sim = serve_world("stage-worlds/simple.world");
    let port = sim.port(6665).expect("simple.world serves 6665");
    let robot = format!("127.0.0.1:{port}");
    let (direct, served) = direct_scans(port);
    let scan_topic = format!("/{robot}/laser/0/scan");
    let (_relay, live) = relay_with_front(port, &scan_topic);
    let laser = format!("{robot}/laser/0");
    let want = serde_json::json!({ "scans": 20, "children": [robot, laser] }).to_string();
    let seen = run_node(&["observe", &live_url(&live), &want, "60000"]);
    drop(direct);

    let transforms: Vec<(String, String)> = seen["transforms"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| {
            (
                t["parent"].as_str().unwrap().into(),
                t["child"].as_str().unwrap().into(),
            )
        })
        .collect();
    assert!(
        transforms.contains(&("world".into(), robot.clone())),
        "{transforms:?}"
    );
    assert!(
        transforms.contains(&(robot.clone(), laser.clone())),
        "{transforms:?}"
    );

    let served = served.lock().unwrap();
    let mut matched = 0;
    for scan in seen["scans"].as_array().unwrap() {
        if scan["topic"] != scan_topic.as_str() {
            continue;
        }
        assert_eq!(scan["frame"], laser.as_str());
        let t = scan["sec"].as_u64().unwrap() * 1_000_000_000 + scan["nsec"].as_u64().unwrap();
        assert_eq!(scan["logTime"].as_u64(), Some(t), "log time is the scan's");
        let Some(ranges) = served.get(&t) else {
            continue;
        };
        let decoded: Vec<f64> = scan["ranges"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r.as_f64().unwrap())
            .collect();
        assert_eq!(decoded.len(), ranges.len());
        for (d, r) in decoded.iter().zip(ranges) {
            assert!((d - f64::from(*r)).abs() < 1e-6, "{d} decoded, {r} served");
        }
        matched += 1;
    }
    assert!(
        matched >= 5,
        "only {matched} of the decoded scans were also served to the direct client"
    );
}

#[test]
fn a_late_viewer_gets_the_map_as_a_grid() {
    let sim = serve_world("stage-worlds/navigation.world");
    let port = sim
        .port(6665)
        .expect("navigation.world's navigation half serves 6665");
    let robot = format!("127.0.0.1:{port}");
    let grid_topic = format!("/{robot}/map/0/grid");
    let (_relay, live) = relay_with_front(port, &grid_topic);
    let want = serde_json::json!({ "topics": [grid_topic] }).to_string();
    let seen = run_node(&["observe", &live_url(&live), &want, "60000"]);

    let direct = Client::connect("127.0.0.1", port, ClientOptions::default()).expect("direct");
    let reply = direct
        .request(
            direct.addr(Interface::MAP, 0),
            map::REQ_GET_INFO,
            Body::Empty,
        )
        .expect("map info");
    let info = Map::REQ_GET_INFO.reply_of(&reply).expect("a map info");
    let grid = &seen["grids"][0];
    assert_eq!(grid["frame"], "world");
    assert_eq!(grid["columns"].as_u64(), Some(u64::from(info.width)));
    assert_eq!(
        grid["bytes"].as_u64(),
        Some(u64::from(info.width) * u64::from(info.height))
    );
    let cell = grid["cellSize"]["x"].as_f64().unwrap();
    assert!(
        (cell - f64::from(info.scale)).abs() < 1e-6,
        "{cell} vs {}",
        info.scale
    );
}

#[test]
fn bad_input_is_refused_and_others_are_still_served() {
    let sim = serve_world("stage-worlds/simple.world");
    let port = sim.port(6665).expect("simple.world serves 6665");
    let (_relay, live) = relay_with_front(port, &format!("/127.0.0.1:{port}/laser/0/scan"));
    let seen = run_node(&["bad", &live_url(&live), "60000"]);
    eprintln!("{seen:#}");
    let error_status =
        |case: &str, needle: &str| {
            let statuses = seen[case]["statuses"].as_array().unwrap();
            assert!(
                statuses.iter().any(|s| s["level"] == 2
                    && s["message"].as_str().is_some_and(|m| m.contains(needle))),
                "{case}: no error status with {needle:?}: {:#}",
                seen[case]
            );
            assert!(
                seen[case]["closed"].is_null(),
                "{case}: refused, not dropped"
            );
        };
    error_status("garbageText", "Invalid message");
    error_status("unknownOp", "Invalid message");
    error_status("garbageBinary", "Invalid message");
    error_status("unknownChannel", "Unknown channel ID");
    // Past tungstenite's frame limit (16 MiB): the connection is closed.
    let oversized = &seen["oversized"];
    assert!(
        !oversized["closed"].is_null(),
        "an oversized frame closes the connection: {oversized:#}"
    );
    assert!(seen["scansAfter"].as_u64() > seen["scansBefore"].as_u64());
}

#[test]
fn both_names_of_the_protocol_are_accepted() {
    let sim = serve_world("stage-worlds/simple.world");
    let port = sim.port(6665).expect("simple.world serves 6665");
    let (_relay, live) = relay_with_front(port, &format!("/127.0.0.1:{port}/laser/0/scan"));
    let seen = run_node(&["protocols", &live_url(&live), "60000"]);
    eprintln!("{seen:#}");
    // Older Lichtblick builds offer only the spec's name; the Foxglove app the SDK's.
    for (case, chosen) in [
        ("spec", "foxglove.websocket.v1"),
        ("sdk", "foxglove.sdk.v1"),
        ("both", "foxglove.websocket.v1"),
    ] {
        assert_eq!(seen[case]["protocol"], chosen, "{case}: {seen:#}");
        assert_eq!(seen[case]["firstOp"], "serverInfo", "{case}: {seen:#}");
    }
    assert_eq!(seen["other"]["refused"], 400, "{seen:#}");
}

#[test]
fn hundreds_of_viewers_connect_at_once() {
    const VIEWERS: usize = 500;
    let sim = serve_world("stage-worlds/simple.world");
    let port = sim.port(6665).expect("simple.world serves 6665");
    let (_relay, live) = relay_with_front(port, &format!("/127.0.0.1:{port}/laser/0/scan"));
    let before = resident_kib();
    let count = VIEWERS.to_string();
    let mut child = node(&["many", &live_url(&live), &count, "2000", "120000"])
        .stdout(Stdio::piped())
        .spawn()
        .expect("node runs");
    let mut stdout = BufReader::new(child.stdout.take().unwrap());
    let mut line = String::new();
    stdout.read_line(&mut line).unwrap();
    let (clients, during) = (live.clients(), resident_kib());
    let mut rest = String::new();
    stdout.read_to_string(&mut rest).unwrap();
    let status = child.wait().unwrap();
    assert_eq!(line.trim(), "CONNECTED", "{line}{rest}");
    assert!(status.success(), "{rest}");
    let seen: Value = serde_json::from_str(rest.trim()).expect("JSON");
    eprintln!(
        "{VIEWERS} viewers: {seen}; {clients} clients on the server; resident {before} KiB \
         before, {during} KiB with them"
    );
    assert_eq!(clients, VIEWERS);
    for what in ["connected", "advertised", "scanned"] {
        assert_eq!(seen[what].as_u64(), Some(VIEWERS as u64), "{what}: {seen}");
    }
    assert_eq!(seen["errors"].as_u64(), Some(0), "{seen}");
}

#[test]
fn viewers_that_stop_reading_hold_a_bounded_backlog() {
    const VIEWERS: usize = 10;
    const HOLD_MS: u64 = 20_000;
    // r0 of multirobot.world has a raw RGB camera: the heaviest stream there is.
    let sim = serve_world("stage-worlds/multirobot.world");
    let port = sim.port(6665).expect("multirobot.world serves 6665");
    let (_relay, live) = relay_with_front(port, &format!("/127.0.0.1:{port}/camera/0/image"));
    let count = VIEWERS.to_string();
    let hold = HOLD_MS.to_string();
    let mut child = node(&["stall", &live_url(&live), &count, &hold, "120000"])
        .stdout(Stdio::piped())
        .spawn()
        .expect("node runs");
    let mut stdout = BufReader::new(child.stdout.take().unwrap());
    let mut line = String::new();
    stdout.read_line(&mut line).unwrap();
    let mut samples = vec![resident_kib()];
    let started = Instant::now();
    while started.elapsed() < Duration::from_millis(HOLD_MS - 1000) {
        std::thread::sleep(Duration::from_secs(1));
        samples.push(resident_kib());
    }
    let mut rest = String::new();
    stdout.read_to_string(&mut rest).unwrap();
    assert!(child.wait().unwrap().success(), "{line}{rest}");
    eprintln!("{VIEWERS} stalled viewers: {rest}; resident KiB each second: {samples:?}");
    let seen: Value = serde_json::from_str(rest.trim()).expect("JSON");
    assert_eq!(
        seen["open"].as_u64(),
        Some(VIEWERS as u64),
        "a viewer that stops reading loses old data, not its connection"
    );
    // Once the kernel's buffers and each viewer's queue are full (some 8 s here), old data is
    // dropped instead of kept: the process stops growing. While filling it grew about 4 MB/s
    // with these viewers, so an unbounded queue would add some 20 MB over the last 6 s.
    let last = samples[samples.len() - 1];
    let earlier = samples[samples.len() - 7];
    assert!(
        last.saturating_sub(earlier) < 4 * 1024,
        "still growing with {VIEWERS} stalled viewers: {samples:?} KiB"
    );
}

/// This process's resident memory (the server, relay and simulation), KiB.
fn resident_kib() -> u64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find_map(|l| l.strip_prefix("VmRSS:"))
                .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        })
        .unwrap_or(0)
}
