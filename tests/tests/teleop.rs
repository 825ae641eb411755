//! Tele-operation end to end: the viewer's position2d plugin drives a robot simulated by
//! player-sim over real TCP — select the robot, click the ground, the robot goes there and
//! stops; Space stops it on the way.

use std::time::Duration;

use glam::Vec3;
use tests::{load, run_for, run_until, serve, sim_pose, viewer_for};

fn distance(a: (f64, f64, f64), b: (f64, f64)) -> f64 {
    ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt()
}

#[test]
fn a_clicked_target_is_reached_and_the_robot_stops_there() {
    let mut composition = load(&["configs/single-laser.pv3d.xml"]);
    let running = serve("stage-worlds/simple.world", &mut composition, 4.0);
    let mut viewer = viewer_for(&composition);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    // Let odometry arrive, then select the robot (Tab) and click the ground 1.5 m ahead of
    // it and 1 m to its left.
    run_for(&mut viewer, Duration::from_millis(500));
    let start = sim_pose(&running, 0);
    let target = (start.0 + 1.5, start.1 + 1.0);
    viewer.cycle_active();
    viewer.click(None, Some(Vec3::new(target.0 as f32, target.1 as f32, 0.0)));

    run_until(
        &mut viewer,
        "the robot to reach the clicked target",
        Duration::from_secs(20),
        |_| distance(sim_pose(&running, 0), target) < 0.12,
    );
    // Arrived: it was told to stop, and stays.
    run_for(&mut viewer, Duration::from_millis(300));
    let here = sim_pose(&running, 0);
    run_for(&mut viewer, Duration::from_millis(500));
    let later = sim_pose(&running, 0);
    assert!(
        distance(later, (here.0, here.1)) < 0.02,
        "the robot kept moving after it arrived: {here:?} -> {later:?}"
    );
    assert!(
        distance(later, target) < 0.15,
        "{later:?} is not {target:?}"
    );
}

#[test]
fn stop_all_halts_a_robot_on_its_way() {
    let mut composition = load(&["configs/single-laser.pv3d.xml"]);
    let running = serve("stage-worlds/simple.world", &mut composition, 2.0);
    let mut viewer = viewer_for(&composition);
    run_for(&mut viewer, Duration::from_millis(500));
    let start = sim_pose(&running, 0);
    let target = (start.0 + 3.0, start.1);
    viewer.cycle_active();
    viewer.click(None, Some(Vec3::new(target.0 as f32, target.1 as f32, 0.0)));
    run_until(
        &mut viewer,
        "the robot to set off",
        Duration::from_secs(10),
        |_| distance(sim_pose(&running, 0), (start.0, start.1)) > 0.3,
    );

    viewer.stop_all();
    run_for(&mut viewer, Duration::from_millis(300));
    let stopped = sim_pose(&running, 0);
    run_for(&mut viewer, Duration::from_millis(500));
    let later = sim_pose(&running, 0);
    assert!(
        distance(later, (stopped.0, stopped.1)) < 0.02,
        "Space did not stop the robot: {stopped:?} -> {later:?}"
    );
    assert!(
        distance(later, target) > 0.5,
        "the robot should have stopped well before the target"
    );
}
