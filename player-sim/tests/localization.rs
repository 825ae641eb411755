//! What a robot's position2d reports as its pose, as Stage 4.3 reports it: the true pose with
//! `localization "gps"` (the default, whatever `localization_origin` says), odometry that drifts
//! by `odom_error` with `localization "odom"`, starting from the start pose in the frame of
//! `localization_origin`; the drift of a robot without `odom_error` follows the world's seed.
//! Over the wire, SET_ODOM and RESET_ODOM set the odometry, a position command steers to a goal
//! given in the reported frame, and a car command's angle is a turn rate, as Stage takes it.

mod support;

use std::time::Duration;

use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::position2d::{self, Position2d, Position2dCmdCar, Position2dSetOdom};
use player_proto::message::Body;
use player_sim::serve::{ServeOptions, serve};
use player_sim::served::from_cfg;
use player_sim::sim::{Command, Noise, Simulation};
use player_sim::world::{Localization, Pose, World};
use support::{run, wait_for, write};

/// A world of one robot `r` at (1, 2) facing north, with `extra` properties, and walls far away.
fn world(dir: &std::path::Path, extra: &str) -> World {
    let text = format!("position( name \"r\" pose [ 1 2 0 90 ] size [ 0.4 0.4 0.2 ] {extra} )\n");
    World::load(&write(dir, "odom.world", &text)).unwrap()
}

fn forward(sim: &mut Simulation, vx: f64, va: f64) {
    sim.robots[0].command = Command::Velocity { vx, vy: 0.0, va };
}

fn close(a: Pose, b: Pose, within: f64) -> bool {
    (a.x - b.x).abs() < within && (a.y - b.y).abs() < within && (a.a - b.a).abs() < within
}

#[test]
fn gps_reports_the_true_pose_whatever_the_origin() {
    let dir = tempfile::tempdir().unwrap();
    for extra in ["", "localization \"gps\" localization_origin [ 5 5 0 45 ]"] {
        let mut sim = Simulation::new(world(dir.path(), extra));
        assert_eq!(sim.world.robots[0].localization.mode, Localization::Gps);
        forward(&mut sim, 0.5, 0.2);
        run(&mut sim, 2.0);
        assert_eq!(sim.reported_pose(0), sim.robots[0].pose, "{extra}");
        assert!((sim.robots[0].pose.x - 1.0).abs() > 0.1, "it moved");
    }
}

#[test]
fn odometry_starts_at_zero_and_drifts_by_its_error() {
    let dir = tempfile::tempdir().unwrap();
    // 10 % long forward, the turn's error 0 (its fourth number is degrees, as Stage reads it).
    let mut sim = Simulation::new(world(
        dir.path(),
        "localization \"odom\" odom_error [ 0.1 0 0 0 ]",
    ));
    assert!(close(sim.reported_pose(0), Pose::default(), 1e-12));
    forward(&mut sim, 0.5, 0.0);
    run(&mut sim, 2.0);
    let truth = sim.robots[0].pose;
    assert!((truth.y - 3.0).abs() < 1e-9, "it went north 1 m: {truth:?}");
    let reported = sim.reported_pose(0);
    // The odometry's frame is the start pose's: forward is its x.
    assert!(
        close(
            reported,
            Pose {
                x: 1.1,
                y: 0.0,
                a: 0.0
            },
            1e-9
        ),
        "{reported:?}"
    );

    // The fourth number is an angle in degrees: 5.7296 degrees is a 0.1 turn error.
    let mut sim = Simulation::new(world(
        dir.path(),
        "localization \"odom\" odom_error [ 0 0 0 5.729577951308232 ]",
    ));
    forward(&mut sim, 0.0, 0.5);
    run(&mut sim, 1.0);
    assert!((sim.robots[0].pose.a - (90f64.to_radians() + 0.5)).abs() < 1e-9);
    assert!(
        (sim.reported_pose(0).a - 0.55).abs() < 1e-9,
        "{:?}",
        sim.reported_pose(0)
    );
}

#[test]
fn odometry_is_reported_in_the_frame_of_its_origin() {
    let dir = tempfile::tempdir().unwrap();
    // The origin at (1, 0) facing north: the robot at (1, 2) facing north is 2 m ahead of it.
    let sim = Simulation::new(world(
        dir.path(),
        "localization \"odom\" localization_origin [ 1 0 0 90 ] odom_error [ 0 0 0 0 ]",
    ));
    assert!(close(
        sim.reported_pose(0),
        Pose {
            x: 2.0,
            y: 0.0,
            a: 0.0
        },
        1e-9
    ));
}

#[test]
fn a_stalled_robot_still_counts_its_wheels() {
    let dir = tempfile::tempdir().unwrap();
    let text = "position( name \"r\" pose [ 0 0 0 0 ] size [ 0.4 0.4 0.2 ] \
                localization \"odom\" odom_error [ 0 0 0 0 ] )\n\
                model( name \"wall\" pose [ 0.5 0 0 0 ] size [ 0.2 2 0.5 ] )\n";
    let mut sim = Simulation::new(World::load(&write(dir.path(), "stall.world", text)).unwrap());
    forward(&mut sim, 0.5, 0.0);
    run(&mut sim, 2.0);
    assert!(sim.robots[0].stall && sim.robots[0].pose.x < 0.2);
    assert!(
        (sim.reported_pose(0).x - 1.0).abs() < 1e-9,
        "{:?}",
        sim.reported_pose(0)
    );
}

/// Where the odometry says the robot is after the same drive, with the world's seed `seed`.
fn drifted(dir: &std::path::Path, seed: u64) -> Pose {
    let mut sim = Simulation::new(world(dir, "localization \"odom\""));
    sim.noise = Noise {
        seed,
        range_sd: 0.0,
    };
    forward(&mut sim, 0.5, 0.3);
    run(&mut sim, 5.0);
    let p = sim.reported_pose(0);
    // Stage draws each error within ±1.5 % (x, y) and ±2.5 % (turn).
    assert!((p.a - 1.5).abs() <= 1.5 * 0.025 + 1e-9, "{p:?}");
    p
}

#[test]
fn without_odom_error_the_drift_follows_the_seed() {
    let dir = tempfile::tempdir().unwrap();
    assert_eq!(drifted(dir.path(), 3), drifted(dir.path(), 3));
    let drifts: Vec<Pose> = (0..8).map(|seed| drifted(dir.path(), seed)).collect();
    assert!(
        drifts.windows(2).any(|w| w[0] != w[1]),
        "another seed, another drift: {drifts:?}"
    );
}

#[test]
fn bad_localization_properties_are_refused_where_written() {
    let dir = tempfile::tempdir().unwrap();
    for (extra, says) in [
        ("localization \"slam\"", "Stage's are \"gps\" and \"odom\""),
        ("odom_error [ 0.05 0.05 0.1 ]", "at least 4 numbers"),
        ("localization_origin [ 0 0 ]", "at least 4 numbers"),
    ] {
        let text = format!("\nposition( name \"r\"\n {extra} )\n");
        let path = write(dir.path(), "bad.world", &text);
        let e = World::load(&path).unwrap_err().to_string();
        assert!(
            e.contains("bad.world:3:") && e.contains(says),
            "{extra}: {e}"
        );
    }
}

#[test]
fn over_the_wire_odometry_is_set_reset_and_steered_in() {
    let dir = tempfile::tempdir().unwrap();
    let world_file = write(
        dir.path(),
        "odom.world",
        "position( name \"r\" pose [ 1 2 0 90 ] size [ 0.4 0.4 0.2 ] \
         localization \"odom\" odom_error [ 0 0 0 0 ] )\n",
    );
    let cfg = write(
        dir.path(),
        "odom.cfg",
        "driver ( name \"stage\" provides [ \"position2d:0\" ] model \"r\" )\n",
    );
    let world = World::load(&world_file).unwrap();
    let devices = from_cfg(&cfg, &world, &mut Vec::new()).unwrap();
    let options = ServeOptions {
        speedup: 20.0,
        free_ports: true,
        ..ServeOptions::default()
    };
    let running = serve(Simulation::new(world), devices, options).unwrap();
    let client = Client::connect(
        "127.0.0.1",
        running.port(6665).unwrap(),
        ClientOptions::default(),
    )
    .unwrap();
    let base = client.position2d(0);
    base.subscribe().unwrap();
    let reads = |x: f64, y: f64| {
        wait_for("the odometry", Duration::from_secs(5), || {
            base.state()
                .filter(|(s, _)| (s.pos.px - x).abs() < 0.02 && (s.pos.py - y).abs() < 0.02)
        })
    };
    reads(0.0, 0.0);
    let set = Position2dSetOdom {
        pose: Pose2d::new(3.0, -1.0, 0.0),
    };
    client
        .request_with(base.addr(), Position2d::REQ_SET_ODOM, set)
        .unwrap();
    reads(3.0, -1.0);
    client
        .request(base.addr(), position2d::REQ_RESET_ODOM, Body::Empty)
        .unwrap();
    reads(0.0, 0.0);
    // A goal 1 m ahead in the odometry's frame: 1 m north in the world.
    base.go_to(Pose2d::new(1.0, 0.0, 0.0));
    reads(1.0, 0.0);
    let truth = running.sim.lock().unwrap().robots[0].pose;
    assert!(
        (truth.x - 1.0).abs() < 0.05 && (truth.y - 3.0).abs() < 0.05,
        "{truth:?}"
    );
    // A car command drives as Stage drives a robot that is no car: its angle is the turn rate.
    let car = Position2dCmdCar {
        velocity: 0.0,
        angle: 0.5,
    };
    client.command(base.addr(), Position2d::Car(car));
    wait_for("a turn", Duration::from_secs(5), || {
        base.state().filter(|(s, _)| s.pos.pa > 0.3)
    });
    base.set_velocity(0.0, 0.0, 0.0);
}
