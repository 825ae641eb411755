//! The client against the server module over real TCP: handshake, subscriptions, data, typed
//! requests and commands, PULL rounds, several robots. (A server that dies and comes back:
//! `client_restarts.rs`.)

mod support;

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use player_proto::client::{
    Client, ClientOptions, ConnectionState, DataMode, MultiClient, RequestError,
};
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::laser::Laser;
use player_proto::interfaces::position2d::Position2d;
use player_proto::message::Body;
use player_proto::server::Server;
use player_proto::wire::Interface;

use support::served_robots::*;

#[test]
fn handshake_subscribe_and_data_with_freshness() {
    let s = server(0, Arc::default());
    let notified = Arc::new(AtomicUsize::new(0));
    let count = notified.clone();
    let options = ClientOptions {
        notifier: Some(Arc::new(move || {
            count.fetch_add(1, Ordering::Relaxed);
        })),
        ..quick()
    };
    let client = Client::connect("127.0.0.1", s.port(0), options).unwrap();
    assert_eq!(client.banner().unwrap().version, "3.1.1-dev");
    let devices = client.devices();
    assert_eq!(devices.len(), 2);
    assert!(
        devices
            .iter()
            .any(|d| d.addr.interf == Interface::LASER && d.driver == "sicklms200")
    );

    let laser = client.laser(0);
    assert_eq!(laser.subscribe().unwrap(), "sicklms200");
    let _feed = Feeder::start(s.publisher(), addr(&s, "laser:0"));
    wait_for("a scan", Duration::from_secs(3), || laser.scan().is_some());
    let (first, stamp1) = laser.scan().unwrap();
    assert_eq!(first.ranges.len(), 361);
    wait_for("a newer scan", Duration::from_secs(3), || {
        laser.scan().unwrap().1.seq > stamp1.seq
    });
    let (_, stamp2) = laser.scan().unwrap();
    assert!(stamp2.server_time > stamp1.server_time && stamp2.received >= stamp1.received);
    assert!(notified.load(Ordering::Relaxed) >= 2);
    assert!(client.stats(laser.addr()).messages >= 2);

    laser.unsubscribe().unwrap();
    assert!(
        laser.scan().is_none(),
        "data of an unsubscribed device is forgotten"
    );
}

#[test]
fn typed_requests_commands_nacks_and_timeouts() {
    let commands = Arc::new(Mutex::new(Vec::new()));
    let s = server(0, commands.clone());
    let client = Client::connect("127.0.0.1", s.port(0), quick()).unwrap();
    let geometry = client.laser(0).geometry().unwrap();
    assert_eq!(geometry.pose.px, 0.12);
    assert!(matches!(
        client.laser(0).config(),
        Err(RequestError::Nack(_))
    ));

    let base = client.position2d(0);
    base.subscribe().unwrap();
    base.set_motor_power(true).unwrap();
    base.set_velocity(0.5, 0.0, 0.25);
    base.go_to(Pose2d::new(1.0, 2.0, 0.0));
    wait_for("two commands", Duration::from_secs(3), || {
        commands.lock().unwrap().len() == 2
    });
    let got = commands.lock().unwrap();
    assert!(
        matches!(&got[0].body, Body::Position2d(Position2d::Velocity(v)) if v.vel.px == 0.5 && v.vel.pa == 0.25 && v.state == 1)
    );
    assert!(matches!(&got[1].body, Body::Position2d(Position2d::Position(p)) if p.pos.py == 2.0));

    // Player drops requests to devices it does not have: the request times out.
    let options = ClientOptions {
        request_timeout: Duration::from_millis(300),
        ..quick()
    };
    let impatient = Client::connect("127.0.0.1", s.port(0), options).unwrap();
    let started = Instant::now();
    assert!(matches!(
        impatient.sonar(3).geometry(),
        Err(RequestError::Timeout(_))
    ));
    assert!(started.elapsed() < Duration::from_secs(2));
    // Several requests in flight at once, each matched to its reply.
    let pending: Vec<_> = (0..8)
        .map(|_| client.fetch_async(client.addr(Interface::LASER, 0), Laser::REQ_GET_GEOM))
        .collect();
    for p in pending {
        assert!(matches!(
            p.wait(Duration::from_secs(3)).unwrap().body,
            Body::Laser(Laser::Geometry(_))
        ));
    }
    assert!(matches!(
        client.subscribe(client.addr(Interface::SONAR, 0)),
        Err(RequestError::Nack(_))
    ));
}

#[test]
fn pull_mode_rounds_bring_the_newest_data() {
    let s = server(0, Arc::default());
    let client = Client::connect(
        "127.0.0.1",
        s.port(0),
        ClientOptions {
            data_mode: DataMode::Pull,
            ..quick()
        },
    )
    .unwrap();
    client.laser(0).subscribe().unwrap();
    for id in 0..20 {
        s.publisher().publish(addr(&s, "laser:0"), 1, scan(id), 0.0);
    }
    std::thread::sleep(Duration::from_millis(100));
    assert!(
        client.laser(0).scan().is_none(),
        "PULL: nothing until asked"
    );
    assert_eq!(
        client.pull().unwrap(),
        1,
        "the replace rule left only the newest scan"
    );
    assert_eq!(client.laser(0).scan().unwrap().0.id, 19);
    for id in 20..23 {
        s.publisher().publish(addr(&s, "laser:0"), 1, scan(id), 0.0);
        assert_eq!(client.pull().unwrap(), 1);
    }
    assert_eq!(
        client.rejected(),
        0,
        "a data request's ACK is expected, not a reply to nothing"
    );
}

#[test]
fn many_robots_flow_while_one_is_unreachable() {
    let servers: Vec<Server> = (0..3).map(|_| server(0, Arc::default())).collect();
    let dead_port = {
        let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
        l.local_addr().unwrap().port()
    };
    let mut robots = MultiClient::new();
    for s in &servers {
        robots.add("127.0.0.1", s.port(0), quick()).unwrap();
    }
    robots.add("127.0.0.1", dead_port, quick()).unwrap();
    assert_eq!(robots.wait_for_handshakes(Duration::from_secs(5)), 3);
    let feeds: Vec<Feeder> = servers
        .iter()
        .map(|s| Feeder::start(s.publisher(), addr(s, "laser:0")))
        .collect();
    for i in 0..3 {
        robots.get(i).unwrap().laser(0).subscribe().unwrap();
    }
    for i in 0..3 {
        wait_for("every live robot's scans", Duration::from_secs(3), || {
            robots.get(i).unwrap().laser(0).scan().is_some()
        });
    }
    assert!(matches!(
        robots.get(3).unwrap().state(),
        ConnectionState::Reconnecting { .. } | ConnectionState::Connecting
    ));
    let started = Instant::now();
    assert!(robots.get(3).unwrap().laser(0).geometry().is_err());
    assert!(
        started.elapsed() < Duration::from_secs(3),
        "an unreachable robot answers fast, never hangs"
    );
    drop(feeds);
}
