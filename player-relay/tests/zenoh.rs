//! Robots through Zenoh: a relay with a Zenoh front on one Zenoh session (site A), bridges
//! serving what they find on another, and plain Player clients on the bridges' ports.

mod zenoh_support;

use std::time::{Duration, Instant};

use player_proto::client::RequestError;
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::laser::{self, Laser};
use player_proto::interfaces::position2d::{self, Position2d, Position2dCmdVel};
use player_proto::message::Body;
use player_proto::wire::Interface;
use player_zenoh::{FromZenoh, FromZenohConfig, Mode};
use zenoh_support::*;

fn position(running: &player_sim::serve::Running) -> (f64, f64) {
    let sim = running.sim.lock().expect("simulation");
    let pose = sim.robots[0].pose;
    (pose.x, pose.y)
}

fn moved(from: (f64, f64), to: (f64, f64)) -> f64 {
    (to.0 - from.0).hypot(to.1 - from.1)
}

/// Drives the robot through `client` for `how_long`.
fn drive(client: &player_proto::client::Client, how_long: Duration) {
    let addr = client.addr(Interface::POSITION2D, 0);
    let go = Position2dCmdVel {
        vel: Pose2d {
            px: 0.5,
            py: 0.0,
            pa: 0.0,
        },
        state: 1,
    };
    let until = Instant::now() + how_long;
    while Instant::now() < until {
        let _ = client.try_command(addr, Position2d::Velocity(go));
        std::thread::sleep(Duration::from_millis(50));
    }
}

#[test]
fn a_robot_through_two_zenoh_peers() {
    program_edge::logging::init("warn");
    let mut running = serve_world("simple.world", None);
    let zport = free_port();
    let robot_side = session(Mode::Peer, Some(zport), None);
    let viewer_side = session(Mode::Peer, None, Some(zport));
    let site = Site::start(robot_side, "A", "teacher", &running);
    let teacher = FromZenoh::start(viewer_side.clone(), FromZenohConfig::new("A", "teacher"))
        .expect("the bridge starts");
    let pupil = FromZenoh::start(viewer_side, FromZenohConfig::new("A", "pupil"))
        .expect("the second bridge starts");

    let served = teacher.wait_for_robots(1, PATIENCE);
    assert_eq!(served.len(), 1, "the robot is found through Zenoh");
    let (robot, port) = served[0].clone();
    assert_eq!(robot, site.front.robot_key("127.0.0.1", running.ports[0].1));

    // The device list, driver names and geometry, as the robot's server gave them.
    let bridged = connect(port);
    let direct = connect(running.ports[0].1);
    let mut devices: Vec<_> = bridged.devices().iter().map(|d| d.addr.interf).collect();
    devices.sort();
    let mut expected: Vec<_> = direct.devices().iter().map(|d| d.addr.interf).collect();
    expected.sort();
    assert_eq!(devices, expected);
    for interf in [Interface::LASER, Interface::POSITION2D] {
        let driver = |c: &player_proto::client::Client| {
            c.devices()
                .into_iter()
                .find(|d| d.addr.interf == interf)
                .map(|d| d.driver)
        };
        assert_eq!(driver(&bridged), driver(&direct));
    }
    let geometry = |c: &player_proto::client::Client| {
        c.request(laser_of(c), laser::REQ_GET_GEOM, Body::Empty)
            .expect("the laser's geometry")
            .body
    };
    assert_eq!(geometry(&bridged), geometry(&direct));
    assert!(matches!(
        geometry(&bridged),
        Body::Laser(Laser::Geometry(_))
    ));

    // Scans: the same ranges at the same timestamps as a direct client of the robot reads.
    bridged
        .subscribe(laser_of(&bridged))
        .expect("subscribed through Zenoh");
    direct
        .subscribe(laser_of(&direct))
        .expect("subscribed directly");
    assert!(matching_scans(&direct, &bridged, 5) >= 5, "scans match");

    // Someone else's commands do not move the robot; their requests are NACKed.
    let intruder_port = pupil.wait_for_robots(1, PATIENCE)[0].1;
    let intruder = connect(intruder_port);
    let before = position(&running);
    drive(&intruder, Duration::from_millis(800));
    assert!(
        moved(before, position(&running)) < 0.01,
        "the pupil cannot drive"
    );
    let reset = intruder.request(
        intruder.addr(Interface::POSITION2D, 0),
        position2d::REQ_RESET_ODOM,
        Body::Empty,
    );
    assert!(matches!(reset, Err(RequestError::Nack(_))), "{reset:?}");
    assert!(site.front.refused() > 0);

    // The controller's do.
    let before = position(&running);
    drive(&bridged, Duration::from_millis(800));
    assert!(
        moved(before, position(&running)) > 0.05,
        "the teacher drives"
    );

    // The robot's server goes: its bridged server goes too; back on the same port, it is
    // served again on the same local port.
    let ports = running.ports.clone();
    running.stop();
    drop(running);
    assert_eq!(teacher.wait_serving(&robot, false, PATIENCE), None);
    let running = serve_world("simple.world", Some(&ports));
    assert_eq!(teacher.wait_serving(&robot, true, PATIENCE), Some(port));
    let again = connect(port);
    again.subscribe(laser_of(&again)).expect("subscribed again");
    let direct = connect(running.ports[0].1);
    direct
        .subscribe(laser_of(&direct))
        .expect("subscribed directly again");
    assert!(matching_scans(&direct, &again, 3) >= 3, "scans flow again");
    assert_eq!(site.front.dropped(), 0);
}

#[test]
fn a_robot_through_a_zenoh_router() {
    program_edge::logging::init("warn");
    let running = serve_world("simple.world", None);
    let zport = free_port();
    let _router = session(Mode::Router, Some(zport), None);
    let robot_side = session(Mode::Client, None, Some(zport));
    let viewer_side = session(Mode::Client, None, Some(zport));
    let _site = Site::start(robot_side, "A", "teacher", &running);
    let bridge = FromZenoh::start(viewer_side, FromZenohConfig::new("A", "teacher"))
        .expect("the bridge starts");
    let port = bridge.wait_for_robots(1, PATIENCE)[0].1;
    let bridged = connect(port);
    let direct = connect(running.ports[0].1);
    bridged
        .subscribe(laser_of(&bridged))
        .expect("subscribed through the router");
    direct
        .subscribe(laser_of(&direct))
        .expect("subscribed directly");
    assert!(
        matching_scans(&direct, &bridged, 3) >= 3,
        "scans cross the router"
    );
    let before = position(&running);
    drive(&bridged, Duration::from_millis(800));
    assert!(
        moved(before, position(&running)) > 0.05,
        "commands cross the router"
    );
}
