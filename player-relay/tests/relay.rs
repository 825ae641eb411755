//! The relay over real TCP on loopback: data reaches every observer over one upstream
//! connection; a slow observer neither delays the others nor gets a backlog; observers'
//! commands are refused and the controller's reach the robot; a robot that goes away and
//! comes back is seen to by the observers; an observer that vanishes leaves nothing behind.

mod support;

use player_proto::client::{ConnectionState, RequestError};
use player_proto::interfaces::position2d::{Position2d, Position2dCmdVel};
use player_proto::server::Commanders;
use player_proto::wire::MsgType;
use player_relay::RelayConfig;
use support::{Observer, PATIENCE, RawObserver, Robot, publish_until_seen, relay_for, scan_id};

#[test]
fn data_reaches_every_observer_over_one_upstream_connection() {
    let robot = Robot::start(0);
    let (relay, port) = relay_for(&robot, RelayConfig::default());
    let observers: Vec<Observer> = (0..3).map(|_| Observer::connect(port)).collect();
    let refs: Vec<&Observer> = observers.iter().collect();
    let last = publish_until_seen(&robot, &refs, 0);
    for observer in &observers {
        assert!(observer.newest_scan().is_some_and(|id| id <= last));
        let devices = observer.client.devices();
        assert_eq!(devices.len(), 2, "the robot's devices, through the relay");
        assert_eq!(devices[1].driver, "mocklaser");
    }
    assert_eq!(relay.observers(), 3);
    assert_eq!(
        robot.server.connections(),
        1,
        "one upstream connection for all"
    );
}

#[test]
fn a_slow_observer_gets_fresh_data_and_delays_nobody() {
    /// Scans published while the slow observer does not read: more than the server's queue
    /// limit (1024) and the kernel's buffers hold together.
    const SCANS: u32 = 1500;
    let robot = Robot::start(0);
    let (_relay, port) = relay_for(&robot, RelayConfig::default());
    let fast = Observer::connect(port);
    let mut slow = RawObserver::subscribe(port);
    let first = publish_until_seen(&robot, &[&fast], 0) + 1;
    // In step with the fast observer, so that every scan passes the relay on its own (the
    // relay would otherwise pass on only the newest of a burst) while the slow one reads
    // nothing: the fast one is never held up by it.
    for id in first..first + SCANS {
        robot.publish_scan(id);
        assert!(
            fast.wait_for_scan(|seen| seen == id),
            "the fast observer got scan {id} while another did not read"
        );
    }
    let newest = first + SCANS - 1;
    // Now the slow one reads: what waits for it is bounded by the buffers, not by what it
    // missed.
    let mut read = 0u32;
    loop {
        let message = slow.next().expect("the slow observer still gets data");
        read += 1;
        if scan_id(&message) == Some(newest) {
            break;
        }
    }
    // What is left is what the kernel's buffers held (the relay's send buffer, doubled by
    // Linux, and the observer's receive buffer: some 150 scans of 1.9 kB) and one queued
    // scan per device. Without newest-data replacement the relay's queue alone would hold
    // 1024 old scans, and drop the newest.
    let bound = SCANS / 4;
    assert!(
        read < bound,
        "the slow observer read {read} old scans of {SCANS} before the newest (bound {bound})"
    );
}

#[test]
fn observers_cannot_command_and_the_controller_can() {
    let robot = Robot::start(0);
    let config = RelayConfig {
        commanders: Commanders::FirstToAsk,
        ..RelayConfig::default()
    };
    let (_relay, port) = relay_for(&robot, config);
    let controller = Observer::connect(port);
    let observer = Observer::connect(port);
    let drive = |speed: f64| {
        Position2d::Velocity(Position2dCmdVel {
            vel: player_proto::interfaces::common::Pose2d::new(speed, 0.0, 0.0),
            state: 1,
        })
    };
    let base = controller.client.position2d(0).addr();
    controller.client.try_command(base, drive(0.1)).unwrap();
    let first = robot.received.recv_timeout(PATIENCE).expect("a command");
    assert_eq!(first.body, drive(0.1).into());

    // The observer asks after control is taken: its command is dropped, its configuration
    // request NACKed, and reading the geometry still works.
    observer.client.try_command(base, drive(9.0)).unwrap();
    let power = observer.client.position2d(0).set_motor_power(true);
    assert!(matches!(power, Err(RequestError::Nack(_))), "{power:?}");
    observer
        .client
        .position2d(0)
        .geometry()
        .expect("an observer reads the geometry");
    // The observer's messages were handled before its NACK came back; had its command been
    // relayed, it would be ahead of this one on the relay's single upstream connection.
    controller.client.try_command(base, drive(0.2)).unwrap();
    let next = robot.received.recv_timeout(PATIENCE).expect("a command");
    assert_eq!(
        next.body,
        drive(0.2).into(),
        "the observer's command never arrived"
    );
    controller
        .client
        .position2d(0)
        .set_motor_power(true)
        .expect("the controller configures");
    let power = robot.received.recv_timeout(PATIENCE).expect("the request");
    assert_eq!(power.header.msg_type, MsgType::Req);
}

#[test]
fn by_default_nobody_commands_through_the_relay() {
    let robot = Robot::start(0);
    let (_relay, port) = relay_for(&robot, RelayConfig::default());
    let observer = Observer::connect(port);
    let power = observer.client.position2d(0).set_motor_power(true);
    assert!(matches!(power, Err(RequestError::Nack(_))), "{power:?}");
    assert!(robot.received.try_recv().is_err());
}

#[test]
fn observers_see_the_robot_go_and_come_back() {
    let robot = Robot::start(0);
    let robot_port = robot.port();
    let (relay, port) = relay_for(&robot, RelayConfig::default());
    let observer = Observer::connect(port);
    publish_until_seen(&robot, &[&observer], 0);

    drop(robot);
    let gone = observer
        .client
        .wait_for_state(PATIENCE, |s| *s != ConnectionState::Connected);
    assert!(
        matches!(gone, Some(ConnectionState::Reconnecting { .. })),
        "{gone:?}"
    );
    assert!(relay.robots()[0].wait_serving(false, PATIENCE));

    let robot = Robot::start(robot_port);
    assert_eq!(relay.wait_serving(PATIENCE), 1);
    assert_eq!(
        relay.robots()[0].listen_port(),
        Some(port),
        "same port again"
    );
    let back = observer
        .client
        .wait_for_state(PATIENCE, |s| *s == ConnectionState::Connected);
    assert_eq!(back, Some(ConnectionState::Connected));
    publish_until_seen(&robot, &[&observer], 1_000_000);
}

#[test]
fn an_observer_that_vanishes_leaves_nothing_behind() {
    let robot = Robot::start(0);
    let (relay, port) = relay_for(&robot, RelayConfig::default());
    let stays = Observer::connect(port);
    let vanishes = RawObserver::subscribe(port);
    publish_until_seen(&robot, &[&stays], 0);
    let server = relay.robots()[0].server().expect("serving");
    assert_eq!(server.connections(), 2);
    drop(vanishes);
    assert_eq!(
        server.wait_for_connections(PATIENCE, |n| n == 1),
        Some(1),
        "its connection is gone"
    );
    publish_until_seen(&robot, &[&stays], 10_000);
    assert_eq!(robot.server.connections(), 1);
}
