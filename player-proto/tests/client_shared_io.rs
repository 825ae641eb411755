//! Many clients on one shared I/O thread ([`SharedIo`]), over real TCP: every robot's data
//! flows, an unreachable robot holds nobody up, a robot whose server restarts comes back, and
//! closing a client ends its connection — also when it is closed on the shared thread itself.

mod support;

use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use player_proto::client::{Client, ClientOptions, ConnectionState, MultiClient, SharedIo};
use player_proto::server::Server;

use support::served_robots::*;

fn shared(io: &SharedIo) -> ClientOptions {
    ClientOptions {
        shared_io: Some(io.clone()),
        ..quick()
    }
}

#[test]
fn robots_on_one_thread_all_flow_while_one_is_unreachable() {
    let io = SharedIo::new(1).unwrap();
    let servers: Vec<Server> = (0..8).map(|_| server(0, Arc::default())).collect();
    let dead_port = {
        let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
        l.local_addr().unwrap().port()
    };
    let mut robots = MultiClient::new();
    robots.add("127.0.0.1", dead_port, shared(&io)).unwrap();
    for s in &servers {
        robots.add("127.0.0.1", s.port(0), shared(&io)).unwrap();
    }
    assert_eq!(robots.wait_for_handshakes(Duration::from_secs(5)), 8);
    let feeds: Vec<Feeder> = (servers.iter())
        .map(|s| Feeder::start(s.publisher(), addr(s, "laser:0")))
        .collect();
    for robot in robots.iter().skip(1) {
        assert_eq!(robot.laser(0).subscribe().unwrap(), "sicklms200");
    }
    for robot in robots.iter().skip(1) {
        let laser = robot.laser(0);
        wait_for("every live robot's scans", Duration::from_secs(3), || {
            laser.scan().is_some()
        });
        let first = laser.scan().unwrap().1.seq;
        wait_for("newer scans", Duration::from_secs(3), || {
            laser.scan().unwrap().1.seq > first
        });
    }
    let unreachable = robots.get(0).unwrap();
    assert!(matches!(
        unreachable.state(),
        ConnectionState::Reconnecting { .. } | ConnectionState::Connecting
    ));
    let started = Instant::now();
    assert!(unreachable.laser(0).geometry().is_err());
    assert!(
        started.elapsed() < Duration::from_secs(3),
        "answers at once"
    );
    drop(feeds);
}

#[test]
fn a_restarted_server_is_reconnected_on_the_shared_thread() {
    let io = SharedIo::new(1).unwrap();
    let first = server(0, Arc::default());
    let port = first.port(0);
    let client = Client::connect("127.0.0.1", port, shared(&io)).unwrap();
    client.laser(0).subscribe().unwrap();
    first.shutdown();
    drop(first);
    wait_for_state(&client, "reconnecting", Duration::from_secs(3), |s| {
        matches!(s, ConnectionState::Reconnecting { .. })
    });
    let second = server(port, Arc::default());
    wait_for_state(&client, "connected again", Duration::from_secs(5), |s| {
        *s == ConnectionState::Connected
    });
    let _feed = Feeder::start(second.publisher(), addr(&second, "laser:0"));
    wait_for("scans after the restart", Duration::from_secs(3), || {
        client.laser(0).scan().is_some()
    });
}

#[test]
fn closing_ends_the_connection_even_on_the_shared_thread() {
    let io = SharedIo::new(1).unwrap();
    let s = server(0, Arc::default());
    let port = s.port(0);
    let closed = Client::connect("127.0.0.1", port, shared(&io)).unwrap();
    assert!(
        s.wait_for_connections(Duration::from_secs(3), |n| n == 1)
            .is_some()
    );
    drop(closed);
    assert!(
        s.wait_for_connections(Duration::from_secs(3), |n| n == 0)
            .is_some(),
        "the server saw the client go"
    );

    // A client whose own notifier — which runs on the shared thread — drops it: no deadlock,
    // and the connection still ends.
    let slot: Arc<Mutex<Option<Client>>> = Arc::default();
    let in_notifier = slot.clone();
    let options = ClientOptions {
        notifier: Some(Arc::new(move || {
            if let Ok(mut held) = in_notifier.try_lock() {
                held.take();
            }
        })),
        ..shared(&io)
    };
    let client = Client::spawn("127.0.0.1", port, options).unwrap();
    *slot.lock().unwrap() = Some(client);
    // The next state change (the handshake, so the server took the connection) runs the
    // notifier, which closes the client. The server's count is 1 only for that moment: on a
    // loaded machine it can go back to 0 before a waiter for 1 looks (a fresh-clone CI run).
    wait_for("the client dropped itself", Duration::from_secs(3), || {
        slot.lock().unwrap().is_none()
    });
    assert!(
        s.wait_for_connections(Duration::from_secs(3), |n| n == 0)
            .is_some(),
        "its connection ended"
    );

    // The thread still serves the others.
    let other = Client::connect("127.0.0.1", port, shared(&io)).unwrap();
    assert_eq!(other.state(), ConnectionState::Connected);
}
