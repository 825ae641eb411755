//! player-sim through the real client over TCP, as a Player user would meet it.

mod support;

use std::path::Path;
use std::time::Duration;

use player_proto::client::{Client, ClientOptions};
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::simulation::{Simulation as SimMsg, SimulationPose2d};
use player_proto::wire::{Interface, PlayerString};
use player_sim::serve::{Running, ServeOptions, serve};
use player_sim::served::from_cfg;
use player_sim::sim::Simulation;
use player_sim::world::{Pose, World};
use support::wait_for;

fn start(world: &str, speedup: f64) -> Running {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds");
    let world_file = dir.join(world);
    let world = World::load(&world_file).unwrap();
    let mut ignored = Vec::new();
    let devices = from_cfg(&world_file.with_extension("cfg"), &world, &mut ignored).unwrap();
    let options = ServeOptions {
        speedup,
        free_ports: true,
        ..ServeOptions::default()
    };
    serve(Simulation::new(world), devices, options).unwrap()
}

#[test]
fn a_commanded_robot_moves_one_metre_in_two_simulated_seconds() {
    let sim = start("simple.world", 10.0);
    let client = Client::connect(
        "127.0.0.1",
        sim.port(6665).unwrap(),
        ClientOptions::default(),
    )
    .unwrap();
    let base = client.position2d(0);
    assert_eq!(base.subscribe().unwrap(), "stage");
    let (start_state, stamp) = wait_for("odometry", Duration::from_secs(3), || base.state());
    base.set_velocity(0.5, 0.0, 0.0);
    // Wait for two simulated seconds after the first state that shows motion.
    let (moving, moved_at) = wait_for("motion", Duration::from_secs(3), || {
        base.state().filter(|(s, _)| s.pos.px > start_state.pos.px)
    });
    let (later, _) = wait_for("two simulated seconds", Duration::from_secs(5), || {
        base.state()
            .filter(|(_, s)| s.server_time >= moved_at.server_time + 2.0)
    });
    base.set_velocity(0.0, 0.0, 0.0);
    let travelled = later.pos.px - moving.pos.px;
    let (_, newest) = base.state().unwrap();
    let elapsed = newest.server_time - moved_at.server_time;
    assert!(
        (travelled - 0.5 * elapsed).abs() < 0.06,
        "{travelled} m in {elapsed} s"
    );
    assert!(stamp.server_time >= 0.0);
}

#[test]
fn the_laser_sees_the_wall_and_the_simulation_moves_models() {
    let sim = start("simple.world", 5.0);
    let client = Client::connect(
        "127.0.0.1",
        sim.port(6665).unwrap(),
        ClientOptions::default(),
    )
    .unwrap();
    // Put the robot 2.1 m from the east wall face (x = 4.8): its laser, 0.1 m ahead, sees 2 m.
    let set = SimulationPose2d {
        name: PlayerString::new("r0"),
        pose: Pose2d::new(2.7, 0.0, 0.0),
    };
    client
        .request_with(
            client.addr(Interface::SIMULATION, 0),
            SimMsg::REQ_SET_POSE2D,
            set,
        )
        .unwrap();
    let laser = client.laser(0);
    assert_eq!(laser.subscribe().unwrap(), "rangertolaser");
    let config = laser.config().unwrap();
    assert_eq!(config.max_range, 8.0);
    let geometry = laser.geometry().unwrap();
    assert!((geometry.pose.px - 0.1).abs() < 1e-9);
    let (scan, _) = wait_for("a scan from the new pose", Duration::from_secs(3), || {
        laser
            .scan()
            .filter(|(s, _)| (s.ranges[90] - 2.0).abs() < 0.05)
    });
    assert_eq!(scan.ranges.len(), 181);

    let ask = SimulationPose2d {
        name: PlayerString::new("r0"),
        pose: Pose2d::default(),
    };
    let reply = client
        .request_with(
            client.addr(Interface::SIMULATION, 0),
            SimMsg::REQ_GET_POSE2D,
            ask,
        )
        .unwrap();
    let p = SimMsg::REQ_GET_POSE2D.reply_of(&reply).unwrap();
    assert!((p.pose.px - 2.7).abs() < 0.2);
    let nobody = SimulationPose2d {
        name: PlayerString::new("nobody"),
        pose: Pose2d::default(),
    };
    assert!(
        client
            .request_with(
                client.addr(Interface::SIMULATION, 0),
                SimMsg::REQ_GET_POSE2D,
                nobody,
            )
            .is_err()
    );
}

#[test]
fn fiducials_and_sonar_rings_of_the_multirobot_world() {
    let sim = start("multirobot.world", 2.0);
    // Park r0 facing landmark lm1 (-6, 4) from 3 m: id 1 straight ahead.
    sim.sim.lock().unwrap().robots[0].pose = Pose {
        x: -6.0,
        y: 1.0,
        a: std::f64::consts::FRAC_PI_2,
    };
    let client = Client::connect(
        "127.0.0.1",
        sim.port(6665).unwrap(),
        ClientOptions::default(),
    )
    .unwrap();
    let finder = client.fiducial(0);
    finder.subscribe().unwrap();
    let (markers, _) = wait_for("markers", Duration::from_secs(3), || {
        finder
            .markers()
            .filter(|(m, _)| m.fiducials.iter().any(|f| f.id == 1))
    });
    let lm1 = markers.fiducials.iter().find(|f| f.id == 1).unwrap();
    assert!(
        (lm1.range() - 3.0).abs() < 0.05 && lm1.bearing().abs() < 0.02,
        "{lm1:?}"
    );
    let ring = client.ranger(1);
    ring.subscribe().unwrap();
    let (ranges, _) = wait_for("sonar readings", Duration::from_secs(3), || ring.ranges());
    assert_eq!(ranges.ranges.len(), 8);
    // As Stage does, intensities follow the ranges: what each sonar hit reflects, 0 where it
    // hit nothing. The front sonar sees lm1, whose retro-reflective tape (robots.inc) returns
    // 2; the walls return 1.
    let (intensities, _) = wait_for("intensities", Duration::from_secs(3), || ring.intensities());
    let values = &intensities.intensities;
    assert_eq!(values.len(), 8);
    assert_eq!(values[0], 2.0, "{values:?}");
    assert!(
        values[1..].iter().all(|&v| v == 0.0 || v == 1.0),
        "{values:?}"
    );
    assert_eq!(
        client.devices().len(),
        8,
        "simulation, position2d, 2 rangers, fiducial, camera, laser, JPEG camera"
    );
}

#[test]
fn a_laser_reads_the_distance_to_a_wall_drawn_with_blocks() {
    let sim = start("blocks.world", 5.0);
    let client = Client::connect(
        "127.0.0.1",
        sim.port(6665).unwrap(),
        ClientOptions::default(),
    )
    .unwrap();
    let laser = client.laser(0);
    laser.subscribe().unwrap();
    // From (0, 0) facing east the laser, 0.1 m ahead, is 4.7 m from the east wall's face.
    let (scan, _) = wait_for("a scan", Duration::from_secs(3), || laser.scan());
    assert_eq!(scan.ranges.len(), 181);
    assert!((scan.ranges[90] - 4.7).abs() < 0.03, "{}", scan.ranges[90]);
    // Facing north under the L-shaped partition's bar (y = 1.0): 0.9 m.
    let set = SimulationPose2d {
        name: PlayerString::new("r0"),
        pose: Pose2d::new(-2.0, 0.0, std::f64::consts::FRAC_PI_2),
    };
    client
        .request_with(
            client.addr(Interface::SIMULATION, 0),
            SimMsg::REQ_SET_POSE2D,
            set,
        )
        .unwrap();
    wait_for("a scan of the partition", Duration::from_secs(3), || {
        laser
            .scan()
            .filter(|(s, _)| (s.ranges[90] - 0.9).abs() < 0.03)
    });
}
