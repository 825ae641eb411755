//! Several robots on one Player port, end to end against player-sim over TCP: the shipped
//! templates hang each robot's laser and fiducial finder below that robot's own position2d
//! (r1's laser:1 below position2d:1), so every robot shows its sensors where it is.

use std::time::Duration;

use framework::scene::NodeId;
use glam::Vec3;
use pv3d::app::Viewer;
use tests::{load, run_until, serve, sim_pose, viewer_for};

/// How many robots stage-worlds/oneport.world serves on its one port.
const ROBOTS: usize = 3;

/// How far a sensor may sit from its robot's centre (the lidar is mounted 0.1 m forward).
const MOUNT_TOLERANCE: f32 = 0.3;

/// The scene node of the laser plugin made for `laser:index` (its name names the device).
fn laser_node(viewer: &Viewer, index: usize) -> Option<NodeId> {
    let prefix = format!("laser laser:{index}@");
    viewer
        .scene()
        .iter()
        .find(|(_, object)| object.name.starts_with(&prefix))
        .map(|(id, _)| id)
}

/// The fiducial finders' scene nodes (named by plugin id, not by device).
fn finder_nodes(viewer: &Viewer) -> Vec<NodeId> {
    viewer
        .scene()
        .iter()
        .filter(|(_, object)| object.name.starts_with("fiducial finder "))
        .map(|(id, _)| id)
        .collect()
}

fn is_attached(viewer: &Viewer, node: NodeId) -> bool {
    viewer
        .scene()
        .get(node)
        .is_some_and(|object| object.parent.is_some())
}

/// Where a node is in the world, on the ground plane.
fn ground_position(viewer: &Viewer, node: NodeId) -> Vec3 {
    let mut at = Vec3::from(viewer.scene().world_transform(node).translation);
    at.z = 0.0;
    at
}

/// The robot index whose simulated pose is nearest to `at`, and how far it is.
fn nearest_robot(running: &player_sim::serve::Running, at: Vec3) -> (usize, f32) {
    (0..ROBOTS)
        .map(|robot| {
            let (x, y, _) = sim_pose(running, robot);
            (robot, at.distance(Vec3::new(x as f32, y as f32, 0.0)))
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .expect("robots")
}

#[test]
fn each_robot_on_a_shared_port_carries_its_own_sensors() {
    let mut composition = load(&["configs/stage-world.pv3d.xml"]);
    let running = serve("stage-worlds/oneport.world", &mut composition, 1.0);
    assert_eq!(
        composition.clients.len(),
        1,
        "oneport.world serves one port"
    );
    let mut viewer = viewer_for(&composition);

    run_until(
        &mut viewer,
        "every laser and fiducial finder attached to a robot",
        Duration::from_secs(10),
        |viewer| {
            let lasers = (0..ROBOTS).filter_map(|i| laser_node(viewer, i));
            let finders = finder_nodes(viewer);
            lasers.filter(|&n| is_attached(viewer, n)).count() == ROBOTS
                && finders.len() == ROBOTS
                && finders.iter().all(|&n| is_attached(viewer, n))
        },
    );
    run_until(
        &mut viewer,
        "the second robot's laser returns",
        Duration::from_secs(10),
        |viewer| {
            laser_node(viewer, 1)
                .and_then(|node| viewer.scene().get(node))
                .is_some_and(|object| !object.geometry.is_empty())
        },
    );

    for index in 0..ROBOTS {
        let node = laser_node(&viewer, index).expect("made");
        let (robot, distance) = nearest_robot(&running, ground_position(&viewer, node));
        assert_eq!(robot, index, "laser:{index} is drawn on r{robot}");
        assert!(
            distance < MOUNT_TOLERANCE,
            "laser:{index} is {distance} m from its robot"
        );
    }
    // One fiducial finder on each robot, none left on r0.
    let mut carriers: Vec<usize> = finder_nodes(&viewer)
        .into_iter()
        .map(|node| {
            let (robot, distance) = nearest_robot(&running, ground_position(&viewer, node));
            assert!(
                distance < MOUNT_TOLERANCE,
                "a finder {distance} m from r{robot}"
            );
            robot
        })
        .collect();
    carriers.sort_unstable();
    assert_eq!(carriers, (0..ROBOTS).collect::<Vec<_>>());
}
