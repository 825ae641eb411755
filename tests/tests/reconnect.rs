//! Safe by default when the connection comes back: the Player server goes away and a new one
//! answers on the same port with its robot still moving (as a server that kept an old command
//! would); the viewer reconnects and its first word to the robot is a zero velocity.

use std::time::Duration;

use player_sim::sim::Command;
use tests::{load, point_at, run_for, run_until, serve_on_port, sim_pose, unused_port, viewer_for};

fn distance(a: (f64, f64, f64), b: (f64, f64, f64)) -> f64 {
    ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt()
}

#[test]
fn a_returning_connection_gets_a_zero_velocity_first() {
    let port = unused_port();
    let mut composition = load(&["configs/single-laser.pv3d.xml"]);
    point_at(&mut composition, port);
    let mut first = serve_on_port("stage-worlds/simple.world", port);
    let mut viewer = viewer_for(&composition);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    run_for(&mut viewer, Duration::from_millis(500));

    // The server goes away; the viewer keeps running (and trying).
    first.stop();
    drop(first);
    run_for(&mut viewer, Duration::from_millis(800));

    // A server answers again, its robot driving.
    let second = serve_on_port("stage-worlds/simple.world", port);
    second.sim.lock().unwrap().robots[0].command = Command::Velocity {
        vx: 0.3,
        vy: 0.0,
        va: 0.0,
    };
    let start = sim_pose(&second, 0);
    run_until(
        &mut viewer,
        "the robot to be stopped by the returning viewer",
        Duration::from_secs(15),
        |_| {
            let sim = second.sim.lock().unwrap();
            matches!(sim.robots[0].command, Command::Velocity { vx, va, .. } if vx == 0.0 && va == 0.0)
        },
    );
    let stopped = sim_pose(&second, 0);
    assert!(
        distance(stopped, start) > 0.0,
        "the robot was moving before the viewer came back"
    );
    run_for(&mut viewer, Duration::from_millis(500));
    assert!(
        distance(sim_pose(&second, 0), stopped) < 0.02,
        "and stays stopped"
    );
}
