//! Four hosts on one machine, in network namespaces joined by veth pairs: site A simulates a
//! robot and publishes it into Zenoh (`player-relay --world … --zenoh`), host B is a Zenoh
//! router (`player-relay --from-zenoh --zenoh-mode router`), this test's own namespace is
//! observer site C, and site D a second observer site whose commands the robot refuses (D is
//! not its controller; its clients reach D's relay routed through B). At C the robot is
//! watched by `pv3d --zenoh` (recording what it gets), by `playerprint` and by Player clients
//! of a `player-relay --from-zenoh`, and driven by those clients and by a second pv3d's
//! spoken "go to". Then the link between B and C is cut for 5 s and healed: C's observers
//! resume, and a command sent during the cut is not replayed.
//!
//! Needs root (`ip netns`), as CI has; anywhere else it says so and passes without running.

mod netns_hosts;

use std::io::{BufRead, BufReader};
use std::net::TcpStream;
use std::process::Stdio;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

use netns_hosts::*;
use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::position2d::{Position2d, Position2dCmdVel};
use player_proto::recording::{Event, RecordingReader};
use player_proto::wire::{Interface, MsgType};

fn pose(robot: &Client) -> Option<(f64, f64)> {
    robot
        .position2d(0)
        .state()
        .map(|(s, _)| (s.pos.px, s.pos.py))
}

fn newest_scan_seq(robot: &Client) -> Option<u64> {
    robot.laser(0).scan().map(|(_, stamped)| stamped.seq)
}

fn velocity(robot: &Client, vx: f64) {
    let go = Position2dCmdVel {
        vel: Pose2d {
            px: vx,
            py: 0.0,
            pa: 0.0,
        },
        state: 1,
    };
    let addr = robot.addr(Interface::POSITION2D, 0);
    robot
        .try_command(addr, Position2d::Velocity(go))
        .expect("a command leaves");
}

/// Unix time in nanoseconds, the recordings' clock.
fn now_ns() -> u64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos() as u64)
}

/// The receive times (Unix ns) of the laser scans in a pv3d recording.
fn recorded_scan_times(path: &std::path::Path) -> Vec<u64> {
    let file = std::fs::File::open(path).expect("pv3d wrote its recording");
    let reader = RecordingReader::new(std::io::BufReader::new(file)).expect("a recording");
    reader
        .filter_map(Result::ok)
        .filter_map(|record| match record.event {
            Event::Message { header, .. }
                if header.msg_type == MsgType::Data && header.addr.interf == Interface::LASER =>
            {
                Some(record.time_ns)
            }
            _ => None,
        })
        .collect()
}

/// `pv3d --zenoh` at site C, through the router, site A's robots only, offscreen.
fn pv3d_at_c(hosts: &Hosts, args: &[&str]) -> Program {
    let router = format!("tcp/{B_TO_C}:7447");
    let mut all = vec![
        "--zenoh",
        &router,
        "--zenoh-site",
        "a",
        "--connect-timeout",
        "20",
    ];
    all.push("--headless");
    all.extend(args);
    Program(
        hosts
            .command(None, &program("pv3d"), &all)
            .stdout(Stdio::null())
            .spawn()
            .expect("pv3d starts"),
    )
}

/// playerprint's lines as they come, with their arrival time (Unix ns).
fn print_lines(program: &mut Program) -> Arc<Mutex<Vec<(u64, String)>>> {
    let lines = Arc::new(Mutex::new(Vec::new()));
    let out = program
        .0
        .stdout
        .take()
        .expect("playerprint's output is piped");
    let kept = lines.clone();
    std::thread::spawn(move || {
        for line in BufReader::new(out).lines().map_while(Result::ok) {
            kept.lock().unwrap().push((now_ns(), line));
        }
    });
    lines
}

#[test]
fn a_robot_at_site_a_is_watched_and_driven_from_site_c_through_a_router_at_b() {
    if !is_root() {
        eprintln!("not root: the three-host Zenoh test needs `ip netns` and is not run here");
        return;
    }
    let mut hosts = Hosts::build();
    let router = format!("tcp/{B_TO_A}:7447");
    let (a, b) = (hosts.a.clone(), hosts.b.clone());
    // B: the router, listening on both of its links.
    hosts.relay(
        Some(&b),
        &[
            "--from-zenoh",
            "--zenoh-mode",
            "router",
            "--zenoh-listen",
            "tcp/0.0.0.0:7447",
        ],
    );
    // The relays would wait for their router (player-zenoh's options test shows it); starting
    // them once it listens keeps the timings below about the network, not the start-up.
    let listening = wait_until(Duration::from_secs(30), || {
        TcpStream::connect((B_TO_C, 7447)).is_ok()
    });
    assert!(listening.is_some(), "the router at B listens within 30 s");
    // A: the robot, published on site "a"; only "teacher" may drive it.
    hosts.relay(
        Some(&a),
        &[
            "--world",
            "stage-worlds/simple.world",
            "--zenoh",
            "--site",
            "a",
            "--zenoh-mode",
            "client",
            "--zenoh-connect",
            &router,
            "--zenoh-controller",
            "teacher",
        ],
    );
    // C (here): the robots of site "a" as Player servers, commanding as "teacher".
    let port = free_port();
    let port_text = port.to_string();
    hosts.relay(
        None,
        &[
            "--from-zenoh",
            "--site",
            "a",
            "--zenoh-mode",
            "client",
            "--zenoh-connect",
            &format!("tcp/{B_TO_C}:7447"),
            "--zenoh-id",
            "teacher",
            "--zenoh-base-port",
            &port_text,
            "--first-to-command",
        ],
    );
    // D: a second observer site; its clients may command D's server, but D is not the
    // robot's controller.
    let d = hosts.d.clone();
    let d_router = format!("tcp/{B_TO_D}:7447");
    hosts.relay(
        Some(&d),
        &[
            "--from-zenoh",
            "--site",
            "a",
            "--zenoh-mode",
            "client",
            "--zenoh-connect",
            &d_router,
            "--zenoh-id",
            "pupil",
            "--zenoh-base-port",
            "7665",
            "--bind",
            D,
            "--first-to-command",
        ],
    );
    let served = wait_until(Duration::from_secs(30), || {
        TcpStream::connect(("127.0.0.1", port)).is_ok()
    });
    assert!(
        served.is_some(),
        "site C serves site A's robot on port {port} within 30 s"
    );
    let served = wait_until(Duration::from_secs(30), || {
        TcpStream::connect((D, 7665)).is_ok()
    });
    assert!(
        served.is_some(),
        "site D serves site A's robot on {D}:7665 within 30 s"
    );
    // pv3d at C, straight from Zenoh through the router, watching and recording all along;
    // and playerprint, a plain Player program, on C's relay.
    let scratch = std::env::temp_dir().join(format!("zenoh-hosts-{}", std::process::id()));
    std::fs::create_dir_all(&scratch).unwrap();
    let recording = scratch.join("pv3d-at-c.prec");
    let mut watcher = pv3d_at_c(
        &hosts,
        &[
            "--observe",
            "--quit-after",
            "45",
            "--record",
            recording.to_str().unwrap(),
        ],
    );
    let mut printer = Program(
        hosts
            .command(
                None,
                &program("playerprint"),
                &["--host", "127.0.0.1", "--port", &port_text, "position2d:0"],
            )
            .stdout(Stdio::piped())
            .spawn()
            .expect("playerprint starts"),
    );
    let printed = print_lines(&mut printer);
    let watching_since = now_ns();

    let pupil = Client::connect(D, 7665, ClientOptions::default()).expect("a Player client of D");
    pupil.position2d(0).subscribe().expect("position2d at D");
    pupil.laser(0).subscribe().expect("laser at D");

    let robot =
        Client::connect("127.0.0.1", port, ClientOptions::default()).expect("a Player client at C");
    robot
        .position2d(0)
        .subscribe()
        .expect("position2d through Zenoh");
    robot.laser(0).subscribe().expect("laser through Zenoh");
    for (site, client) in [("C", &robot), ("D", &pupil)] {
        let seen = wait_until(Duration::from_secs(10), || {
            pose(client).is_some() && newest_scan_seq(client).is_some()
        });
        assert!(seen.is_some(), "poses and scans reach site {site}");
    }
    // D's commands leave D, and the robot refuses them.
    let start = pose(&robot).unwrap();
    let until = Instant::now() + Duration::from_secs(2);
    while Instant::now() < until {
        velocity(&pupil, 0.5);
        std::thread::sleep(Duration::from_millis(100));
    }
    std::thread::sleep(Duration::from_millis(500));
    let now = pose(&robot).unwrap();
    assert!(
        (now.0 - start.0).hypot(now.1 - start.1) < 0.01,
        "site D, not the controller, did not move the robot: {start:?} → {now:?}"
    );
    let driven = wait_until(Duration::from_secs(10), || {
        velocity(&robot, 0.4);
        pose(&robot).is_some_and(|p| (p.0 - start.0).hypot(p.1 - start.1) > 0.2)
    });
    velocity(&robot, 0.0);
    assert!(driven.is_some(), "site C drove the robot at site A");
    std::thread::sleep(Duration::from_millis(500));

    let printed_before_cut = printed.lock().unwrap().len();
    assert!(
        printed_before_cut > 10,
        "playerprint at C printed the robot's poses: {:?}",
        printed.lock().unwrap().last()
    );

    // The cut: B–C down for 5 s. A command sent meanwhile must not move the robot once healed.
    hosts.set_b_to_c(false);
    std::thread::sleep(Duration::from_millis(300));
    let before_cut = pose(&robot).unwrap();
    velocity(&robot, 0.5);
    std::thread::sleep(Duration::from_secs(5));
    let seen_before_heal = newest_scan_seq(&robot);
    hosts.set_b_to_c(true);
    let healed_at = now_ns();
    let resumed = wait_until(Duration::from_secs(10), || {
        newest_scan_seq(&robot) != seen_before_heal
    });
    let resumed = resumed.expect("scans resume at site C after the link heals");
    eprintln!(
        "scans resumed {:.2} s after the link healed",
        resumed.as_secs_f64()
    );
    std::thread::sleep(Duration::from_secs(2));
    let after = pose(&robot).unwrap();
    assert!(
        (after.0 - before_cut.0).hypot(after.1 - before_cut.1) < 0.05,
        "a command sent during the cut was not replayed: {before_cut:?} → {after:?}"
    );
    assert!(
        resumed < Duration::from_secs(2),
        "resumed within 2 s: {resumed:?}"
    );
    let printed_after_heal = printed
        .lock()
        .unwrap()
        .iter()
        .filter(|(at, _)| *at > healed_at)
        .count();
    assert!(
        printed_after_heal > 5,
        "playerprint at C prints again after the heal ({printed_after_heal} lines)"
    );

    // pv3d saw the robot before the cut and again after it; its recording says so.
    assert!(
        watcher.wait_exit(Duration::from_secs(60)),
        "pv3d --zenoh at C ran to its --quit-after and exited cleanly"
    );
    let scans = recorded_scan_times(&recording);
    let before = scans
        .iter()
        .filter(|&&t| t < healed_at - 5_000_000_000)
        .count();
    let after: Vec<_> = scans.iter().filter(|&&t| t > healed_at).collect();
    eprintln!(
        "pv3d at C recorded {} scans, {before} before the cut, {} after the heal (first {:.2} s after it)",
        scans.len(),
        after.len(),
        after
            .first()
            .map_or(f64::NAN, |&&t| (t - healed_at) as f64 / 1e9)
    );
    assert!(
        scans.first().is_some_and(|&t| t > watching_since) && before > 10,
        "pv3d at C got the robot's scans from Zenoh before the cut ({before})"
    );
    assert!(
        after.len() > 10
            && after
                .first()
                .is_some_and(|&&t| t - healed_at < 2_000_000_000),
        "pv3d at C got scans again within 2 s of the heal ({} after it)",
        after.len()
    );

    // A second pv3d at C drives the robot, as a person would: "all robots go to point x y".
    let from = pose(&robot).unwrap();
    let goal = (from.0 + 1.0, from.1);
    let script = scratch.join("drive.txt");
    std::fs::write(
        &script,
        format!("1 all robots go to point {} {}\n", goal.0, goal.1),
    )
    .unwrap();
    let mut driver = pv3d_at_c(
        &hosts,
        &[
            "--zenoh-id",
            "teacher",
            "--quit-after",
            "12",
            "--script",
            script.to_str().unwrap(),
        ],
    );
    let distance = |p: (f64, f64)| (p.0 - goal.0).hypot(p.1 - goal.1);
    let reached = wait_until(Duration::from_secs(40), || {
        pose(&robot).is_some_and(|p| distance(p) < 0.3)
    });
    assert!(
        reached.is_some(),
        "pv3d's \"go to\" at C brought the robot at A to {goal:?}: from {from:?}, now {:?}",
        pose(&robot)
    );
    assert!(
        driver.wait_exit(Duration::from_secs(40)),
        "the driving pv3d exited cleanly"
    );
    drop(printer);
    let _ = std::fs::remove_dir_all(&scratch);
}
