//! Safe by default when the connection comes back: the Player server goes away and a new one
//! answers on the same port with its robot still moving (as a server that kept an old command
//! would); the viewer reconnects and its first word to the robot is a zero velocity.

use std::net::TcpListener;
use std::time::Duration;

use player_sim::serve::{Running, ServeOptions, serve};
use player_sim::served::from_cfg;
use player_sim::sim::{Command, Simulation};
use player_sim::world::World;
use pv3d_integration_tests::{load, repo_root, run_for, run_until, sim_pose, viewer_for};

fn serve_simple(port: u16) -> Running {
    let world_file = repo_root().join("stage-worlds/simple.world");
    let world = World::load(&world_file).expect("world");
    let mut devices =
        from_cfg(&world_file.with_extension("cfg"), &world, &mut Vec::new()).expect("cfg");
    for device in &mut devices {
        device.port = port;
    }
    serve(Simulation::new(world), devices, ServeOptions::default()).expect("server starts")
}

fn distance(a: (f64, f64, f64), b: (f64, f64, f64)) -> f64 {
    ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt()
}

#[test]
fn a_returning_connection_gets_a_zero_velocity_first() {
    let port = TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .expect("a free port")
        .port();
    let mut composition = load(&["configs/single-laser.pv3d.xml"]);
    for client in &mut composition.clients {
        client.host = "127.0.0.1".into();
        client.port = port;
    }
    let mut first = serve_simple(port);
    let mut viewer = viewer_for(&composition);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    run_for(&mut viewer, Duration::from_millis(500));

    // The server goes away; the viewer keeps running (and trying).
    first.stop();
    drop(first);
    run_for(&mut viewer, Duration::from_millis(800));

    // A server answers again, its robot driving.
    let second = serve_simple(port);
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
