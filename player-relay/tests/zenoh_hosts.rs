//! Four hosts on one machine, in network namespaces joined by veth pairs: site A simulates a
//! robot and publishes it into Zenoh (`player-relay --world … --zenoh`), host B is a Zenoh
//! router (`player-relay --from-zenoh --zenoh-mode router`), this test's own namespace is
//! observer site C (`player-relay --from-zenoh`, a client of the router), where plain Player
//! clients watch and drive the robot, and site D a second observer site whose commands the
//! robot refuses (D is not its controller; its clients reach D's relay routed through B). Then the link between B and C is cut for 5 s and healed:
//! C's observers resume, and a command sent during the cut is not replayed.
//!
//! Needs root (`ip netns`), as CI has; anywhere else it says so and passes without running.

use std::net::TcpStream;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::position2d::{Position2d, Position2dCmdVel};
use player_proto::wire::Interface;

const RELAY: &str = env!("CARGO_BIN_EXE_player-relay");

/// Addresses: A–B on 10.77.1.0/24, B–C on 10.77.2.0/24 (C is this namespace).
const A: &str = "10.77.1.1";
const B_TO_A: &str = "10.77.1.2";
const B_TO_C: &str = "10.77.2.1";
const C: &str = "10.77.2.2";
/// B–D on 10.77.3.0/24; B forwards between C and D so that this namespace reaches D's relay.
const B_TO_D: &str = "10.77.3.1";
const D: &str = "10.77.3.2";

fn ip(args: &[&str]) {
    let status = Command::new("ip").args(args).status().expect("ip runs");
    assert!(status.success(), "ip {}", args.join(" "));
}

/// The namespaces and links, and the processes in them; all removed when dropped.
struct Hosts {
    a: String,
    b: String,
    d: String,
    /// B's end of the B–C link (cut and healed by the test).
    b_to_c: String,
    c_end: String,
    children: Vec<Child>,
}

impl Hosts {
    fn build() -> Hosts {
        let tag = std::process::id() % 100_000;
        let hosts = Hosts {
            a: format!("pz-a-{tag}"),
            b: format!("pz-b-{tag}"),
            d: format!("pz-d-{tag}"),
            b_to_c: format!("pzbc{tag}"),
            c_end: format!("pzc{tag}"),
            children: Vec::new(),
        };
        let (a_end, b_to_a) = (format!("pza{tag}"), format!("pzba{tag}"));
        ip(&["netns", "add", &hosts.a]);
        ip(&["netns", "add", &hosts.b]);
        ip(&["netns", "add", &hosts.d]);
        let (d_end, b_to_d) = (format!("pzd{tag}"), format!("pzbd{tag}"));
        ip(&[
            "link", "add", &d_end, "type", "veth", "peer", "name", &b_to_d,
        ]);
        ip(&["link", "set", &d_end, "netns", &hosts.d]);
        ip(&["link", "set", &b_to_d, "netns", &hosts.b]);
        ip(&[
            "link", "add", &a_end, "type", "veth", "peer", "name", &b_to_a,
        ]);
        ip(&["link", "set", &a_end, "netns", &hosts.a]);
        ip(&["link", "set", &b_to_a, "netns", &hosts.b]);
        ip(&[
            "link",
            "add",
            &hosts.c_end,
            "type",
            "veth",
            "peer",
            "name",
            &hosts.b_to_c,
        ]);
        ip(&["link", "set", &hosts.b_to_c, "netns", &hosts.b]);
        for (ns, dev, addr) in [
            (&hosts.a, &a_end, A),
            (&hosts.b, &b_to_a, B_TO_A),
            (&hosts.b, &hosts.b_to_c, B_TO_C),
            (&hosts.b, &b_to_d, B_TO_D),
            (&hosts.d, &d_end, D),
        ] {
            ip(&["-n", ns, "addr", "add", &format!("{addr}/24"), "dev", dev]);
            ip(&["-n", ns, "link", "set", dev, "up"]);
            ip(&["-n", ns, "link", "set", "lo", "up"]);
        }
        ip(&["addr", "add", &format!("{C}/24"), "dev", &hosts.c_end]);
        ip(&["link", "set", &hosts.c_end, "up"]);
        // C reaches D's relay through B, as one site reaches another through its router.
        ip(&["route", "add", "10.77.3.0/24", "via", B_TO_C]);
        ip(&["-n", &hosts.d, "route", "add", "default", "via", B_TO_D]);
        let forward = Command::new("ip")
            .args([
                "netns",
                "exec",
                &hosts.b,
                "sysctl",
                "-qw",
                "net.ipv4.ip_forward=1",
            ])
            .status()
            .expect("sysctl runs");
        assert!(forward.success(), "B forwards");
        hosts
    }

    /// Runs the relay with `args` in namespace `ns` (this one with `None`).
    fn relay(&mut self, ns: Option<&str>, args: &[&str]) {
        let mut command = match ns {
            Some(ns) => {
                let mut c = Command::new("ip");
                c.args(["netns", "exec", ns, RELAY]);
                c
            }
            None => Command::new(RELAY),
        };
        let child = command
            .args(args)
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .env("RUST_LOG", "warn")
            .spawn()
            .expect("the relay starts");
        self.children.push(child);
    }

    fn set_b_to_c(&self, up: bool) {
        ip(&[
            "-n",
            &self.b,
            "link",
            "set",
            &self.b_to_c,
            if up { "up" } else { "down" },
        ]);
    }
}

impl Drop for Hosts {
    fn drop(&mut self) {
        for child in &mut self.children {
            let _ = child.kill();
            let _ = child.wait();
        }
        let _ = Command::new("ip")
            .args(["link", "del", &self.c_end])
            .status();
        for ns in [&self.a, &self.b, &self.d] {
            let _ = Command::new("ip").args(["netns", "del", ns]).status();
        }
    }
}

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

/// A free port on this namespace's loopback, for C's Player server.
fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .map(|a| a.port())
        .expect("a free port")
}

fn wait_until(timeout: Duration, mut done: impl FnMut() -> bool) -> Option<Duration> {
    let start = Instant::now();
    while start.elapsed() < timeout {
        if done() {
            return Some(start.elapsed());
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    None
}

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
    // Zenoh clients give up when their router is not there yet: start them once it listens.
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

    // The cut: B–C down for 5 s. A command sent meanwhile must not move the robot once healed.
    hosts.set_b_to_c(false);
    std::thread::sleep(Duration::from_millis(300));
    let before_cut = pose(&robot).unwrap();
    velocity(&robot, 0.5);
    std::thread::sleep(Duration::from_secs(5));
    let seen_before_heal = newest_scan_seq(&robot);
    hosts.set_b_to_c(true);
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
}
