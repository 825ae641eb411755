//! stage-worlds/navigation.world served in-process with configs/navigation.pv3d.xml, driven
//! through the viewer as a person would: a pose dragged with the localizer selected moves the
//! estimate drawn there; r0 selected, a click on the ground goes to wavefront, which draws its
//! path of way-points and brings r0 there.
//!
//! r1 wanders (`ctrl "wander"`) from the far room towards the doorway r0 must pass; when they
//! meet there, both stall against each other for good, as they would in Stage (wander stops
//! and turns in place, wavefront drives on), and in three runs of seven here they met. The arrival
//! test parks r1 in a corner first: it is about the viewer and the planner, not the traffic.

use std::time::Duration;

use framework::scene::{NodeId, Scene};
use glam::{Vec2, Vec3};
use player_sim::serve::Running;
use player_sim::sim::Command;
use player_sim::world::Pose;
use pv3d::app::Viewer;
use tests::{load, run_until, serve, sim_pose, viewer_for};

const PATIENCE: Duration = Duration::from_secs(30);
/// Simulated seconds per real second: the crossing takes about 40 simulated seconds.
const SPEEDUP: f64 = 20.0;
/// r0's pose in navigation.world.
const R0: Vec2 = Vec2::new(-6.5, -4.5);
/// Across the doorway and round the far room's wall (clear of the pucks).
const GOAL: Vec2 = Vec2::new(3.5, 4.5);
/// wavefront's `distance_epsilon` in navigation-nav.cfg.
const ARRIVED_WITHIN: f32 = 0.5;

fn start() -> (Running, Viewer) {
    let mut composition = load(&["configs/navigation.pv3d.xml"]);
    let running = serve("stage-worlds/navigation.world", &mut composition, SPEEDUP);
    let viewer = viewer_for(&composition);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    (running, viewer)
}

fn tagged(scene: &Scene, tag: &str) -> Option<NodeId> {
    scene.iter().find(|(_, o)| o.has_tag(tag)).map(|(id, _)| id)
}

/// Where the localize plugin draws its best estimate (the centre of what picks it).
fn estimate_drawn(viewer: &Viewer) -> Option<Vec2> {
    let scene = viewer.scene();
    let bounds = scene.get(tagged(scene, "localize")?)?.pick_bounds?;
    Some(((bounds.min + bounds.max) / 2.0).truncate())
}

#[test]
fn a_pose_dragged_with_the_localizer_selected_moves_the_estimate_drawn() {
    let (_running, mut viewer) = start();
    run_until(&mut viewer, "amcl's estimate drawn at r0", PATIENCE, |v| {
        estimate_drawn(v).is_some_and(|e| e.distance(R0) < 0.2)
    });
    let localize = viewer
        .titles()
        .iter()
        .position(|t| t.starts_with("Localize"))
        .expect("a localize plugin");
    viewer.set_active(Some(localize));
    let given = Vec3::new(-5.0, -3.5, 0.0);
    viewer.drag_target(given);
    viewer.drag_target(given + Vec3::X);
    viewer.release_target(Some(given + Vec3::X));
    run_until(
        &mut viewer,
        "the estimate drawn at the given pose",
        PATIENCE,
        |v| estimate_drawn(v).is_some_and(|e| e.distance(given.truncate()) < 0.05),
    );
}

/// The planner's drawn way-points (one point each), while it has a plan.
fn waypoints_drawn(viewer: &Viewer) -> Vec<Vec2> {
    let scene = viewer.scene();
    tagged(scene, "planner")
        .and_then(|p| scene.get(p))
        .map(|o| o.geometry.points.iter().map(|v| v.pos.truncate()).collect())
        .unwrap_or_default()
}

/// r0's body: the robot drawn nearest its pose in the world.
fn r0_body(viewer: &Viewer) -> Option<NodeId> {
    let scene = viewer.scene();
    scene
        .iter()
        .filter(|(_, o)| o.has_tag("robot"))
        .map(|(id, _)| (id, scene.world_transform(id).translation.truncate()))
        .filter(|(_, at)| at.distance(R0) < 0.3)
        .map(|(id, _)| id)
        .next()
}

/// Stops r1's wandering and stands it in the far room's lower right corner, off r0's path.
fn park_r1(running: &Running) {
    let mut sim = running.sim.lock().expect("simulation");
    sim.world.robots[1].controller = None;
    let r1 = &mut sim.robots[1];
    r1.command = Command::Velocity {
        vx: 0.0,
        vy: 0.0,
        va: 0.0,
    };
    r1.pose = Pose {
        x: 6.5,
        y: -4.5,
        a: 0.0,
    };
}

#[test]
fn a_ground_click_on_r0_goes_to_the_planner_which_draws_its_path_and_brings_r0_there() {
    let (running, mut viewer) = start();
    park_r1(&running);
    run_until(
        &mut viewer,
        "r0 drawn and claimed by the planner",
        PATIENCE,
        |v| {
            let scene = v.scene();
            let planner = tagged(scene, "planner").and_then(|p| scene.get(p));
            r0_body(v).is_some()
                && planner.is_some_and(|p| p.tags.iter().any(|t| t.starts_with("drives:")))
        },
    );
    let r0 = r0_body(&viewer).unwrap();
    viewer.click(Some(r0), None);
    assert!(viewer.active_title().is_some(), "r0 selected");
    viewer.click(None, Some(GOAL.extend(0.0)));

    let mut path = Vec::new();
    run_until(&mut viewer, "a path of way-points drawn", PATIENCE, |v| {
        path = waypoints_drawn(v);
        path.len() >= 2
    });
    let last = *path.last().unwrap();
    assert!(
        last.distance(GOAL) < 0.2,
        "the path ends at the goal: {path:?}"
    );
    run_until(&mut viewer, "r0 at the goal", PATIENCE, |_| {
        let (x, y, _) = sim_pose(&running, 0);
        Vec2::new(x as f32, y as f32).distance(GOAL) < ARRIVED_WITHIN
    });
    run_until(&mut viewer, "the path gone once arrived", PATIENCE, |v| {
        waypoints_drawn(v).is_empty()
    });
}
