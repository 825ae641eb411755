//! `playerprint` against a local server: the device list, and data as it arrives, pushed or
//! pulled.

use std::process::Command;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use player_proto::interfaces::laser::{Laser, LaserScan};
use player_proto::message::Body;
use player_proto::server::{Device, Server, ServerConfig};
use player_proto::wire::DevAddr;

struct Named(&'static str);
impl Device for Named {
    fn driver_name(&self) -> &str {
        self.0
    }
}

fn server() -> Server {
    let mut config = ServerConfig::default();
    let r = config.robot(0);
    config.device(r, "laser:0".parse().unwrap(), Named("sicklms200"));
    config.device(r, "position2d:0".parse().unwrap(), Named("p2os"));
    Server::start(config).unwrap()
}

fn playerprint(port: u16, args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_playerprint"))
        .args(["-h", "127.0.0.1", "-p", &port.to_string()])
        .args(args)
        .output()
        .unwrap()
}

/// Publishes scans until dropped.
struct Feed(Arc<AtomicBool>);
impl Drop for Feed {
    fn drop(&mut self) {
        self.0.store(true, Ordering::Relaxed);
    }
}

fn feed(server: &Server) -> Feed {
    let stop = Arc::new(AtomicBool::new(false));
    let (flag, publisher, port) = (stop.clone(), server.publisher(), server.port(0));
    std::thread::spawn(move || {
        let addr = DevAddr {
            robot: u32::from(port),
            ..DevAddr::local(player_proto::Interface::LASER, 0)
        };
        let mut id = 0;
        while !flag.load(Ordering::Relaxed) {
            let scan = LaserScan {
                ranges: vec![0.42, 3.0],
                max_range: 8.0,
                id,
                ..LaserScan::default()
            };
            publisher.publish(addr, 1, Body::Laser(Laser::Scan(scan)), f64::from(id));
            id += 1;
            std::thread::sleep(Duration::from_millis(20));
        }
    });
    Feed(stop)
}

#[test]
fn lists_devices_with_driver_names() {
    let s = server();
    let out = playerprint(s.port(0), &["--list"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(
        stdout.contains("laser:0") && stdout.contains("sicklms200"),
        "{stdout}"
    );
    assert!(
        stdout.contains("position2d:0") && stdout.contains("p2os"),
        "{stdout}"
    );
}

#[test]
fn prints_pushed_and_pulled_data() {
    let s = server();
    let _feed = feed(&s);
    for mode in [&[][..], &["--pull"][..]] {
        let mut args = vec!["laser:0", "-n", "3", "-t", "10"];
        args.extend_from_slice(mode);
        let out = playerprint(s.port(0), &args);
        assert!(
            out.status.success(),
            "{mode:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let stdout = String::from_utf8(out.stdout).unwrap();
        let lines: Vec<&str> = stdout.lines().collect();
        assert!(lines.len() >= 3, "{mode:?}: {stdout}");
        assert!(
            lines
                .iter()
                .all(|l| l.contains("laser:0 1  2 ranges, min 0.42 m")),
            "{stdout}"
        );
    }
}

#[test]
fn unknown_devices_and_servers_say_why() {
    let s = server();
    let out = playerprint(s.port(0), &["sonar:0"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("subscribing to sonar:0"));
    let out = playerprint(s.port(0), &["lazer:0"]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("unknown interface"));
    let closed = std::net::TcpListener::bind("127.0.0.1:0")
        .unwrap()
        .local_addr()
        .unwrap()
        .port();
    let out = playerprint(closed, &["--list"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot reach the Player server"));
}

#[test]
fn a_reader_that_goes_away_ends_it_quietly() {
    use std::io::{BufRead, BufReader};
    let s = server();
    let _feed = feed(&s);
    let mut child = Command::new(env!("CARGO_BIN_EXE_playerprint"))
        .args(["-h", "127.0.0.1", "-p", &s.port(0).to_string()])
        .args(["laser:0", "-t", "20"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // Read one line, as `| head -1` does, then close the pipe.
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    assert!(first.contains("laser:0"), "{first}");
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        !stderr.contains("panicked") && !stderr.contains("Broken pipe"),
        "{stderr}"
    );
}
