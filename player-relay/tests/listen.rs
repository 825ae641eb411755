//! A relay told to listen where it cannot (the observer port taken by another program) stops
//! at once, non-zero, with one line naming the address and port — rather than running on,
//! serving that robot to nobody and logging about it.

use std::io::Read;
use std::net::TcpListener;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use player_relay::{Relay, RelayConfig, RelayError, Route};

const RELAY: &str = env!("CARGO_BIN_EXE_player-relay");

/// Far longer than a refusal takes; a relay still running then has not refused.
const PATIENCE: Duration = Duration::from_secs(10);

/// Runs the relay with `args` until it ends (or [`PATIENCE`] passes, then kills it); returns
/// its exit status (None: still running) and what it wrote on standard error.
fn run_relay(args: &[String]) -> (Option<std::process::ExitStatus>, String) {
    let mut child = Command::new(RELAY)
        .args(args)
        .args(["--seconds", "60"])
        .env("NO_COLOR", "1")
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("player-relay starts");
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("player-relay can be waited for") {
            break Some(status);
        }
        if started.elapsed() > PATIENCE {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let mut stderr = String::new();
    child
        .stderr
        .take()
        .expect("piped")
        .read_to_string(&mut stderr)
        .expect("standard error reads");
    (status, stderr)
}

fn assert_refused(args: &[String], taken: u16) {
    let (status, stderr) = run_relay(args);
    let status = status.unwrap_or_else(|| {
        panic!("the relay still ran {PATIENCE:?} with its port taken; it said:\n{stderr}")
    });
    assert!(
        !status.success(),
        "exit status {status}; it said:\n{stderr}"
    );
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 1, "one line, not:\n{stderr}");
    assert!(
        lines[0].contains(&format!("127.0.0.1:{taken}")),
        "the line names the address and port: {stderr}"
    );
}

#[test]
fn a_taken_observer_port_stops_the_relay_at_once() {
    let taken = TcpListener::bind("127.0.0.1:0").expect("a free port");
    let port = taken.local_addr().expect("bound").port();
    // `HOST:PORT` listens on PORT + 1000 by default, the case a new user meets: no robot
    // needs to answer for the relay to know it cannot serve one.
    assert_refused(&[format!("localhost:{}", port - 1000)], port);
    // `HOST:PORT=LISTEN` names the port outright.
    assert_refused(&[format!("localhost:6665={port}")], port);
}

#[test]
fn two_robots_given_one_port_stop_the_relay() {
    let free = TcpListener::bind("127.0.0.1:0").expect("a free port");
    let port = free.local_addr().expect("bound").port();
    drop(free);
    assert_refused(
        &[
            format!("localhost:6665={port}"),
            format!("localhost:6666={port}"),
        ],
        port,
    );
}

#[test]
fn the_library_refuses_a_taken_port_before_starting_a_robot() {
    let taken = TcpListener::bind("127.0.0.1:0").expect("a free port");
    let port = taken.local_addr().expect("bound").port();
    let config = RelayConfig {
        routes: vec![Route {
            listen_port: port,
            ..Route::loopback(6665)
        }],
        ..RelayConfig::default()
    };
    match Relay::start(config) {
        Err(RelayError::Listen { addr, .. }) => assert_eq!(addr.port(), port),
        Err(other) => panic!("refused for another reason: {other}"),
        Ok(_) => panic!("started with its observer port taken"),
    }
}
