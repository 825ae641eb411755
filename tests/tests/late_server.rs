//! A Player server that answers only after the viewer started (a robot still booting, a
//! simulation started second) gets its plugins when it answers, and its data flows.

use std::net::TcpListener;
use std::time::Duration;

use player_sim::serve::{ServeOptions, serve};
use player_sim::served::from_cfg;
use player_sim::sim::Simulation;
use player_sim::world::World;
use pv3d_integration_tests::{load, repo_root, run_until, viewer_for};

#[test]
fn a_server_that_answers_late_gets_its_plugins() {
    // A port nobody listens on yet.
    let port = TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .expect("a free port")
        .port();
    let mut composition = load(&["configs/single-laser.pv3d.xml"]);
    for client in &mut composition.clients {
        client.host = "127.0.0.1".into();
        client.port = port;
    }
    let mut viewer = viewer_for(&composition);
    let named_outright = viewer.plugin_count();
    assert_eq!(
        named_outright, 2,
        "lights and ground only, while the server is down"
    );

    let world_file = repo_root().join("stage-worlds/simple.world");
    let world = World::load(&world_file).expect("world");
    let mut devices =
        from_cfg(&world_file.with_extension("cfg"), &world, &mut Vec::new()).expect("cfg");
    for device in &mut devices {
        device.port = port;
    }
    let _running = serve(Simulation::new(world), devices, ServeOptions::default())
        .expect("the late server starts");

    run_until(
        &mut viewer,
        "the late server's plugins",
        Duration::from_secs(15),
        |v| v.plugin_count() == named_outright + 2,
    );
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    let ids: Vec<String> = viewer.save().iter().map(|i| i.id().to_string()).collect();
    assert!(
        ids.iter().any(|id| id.starts_with("robot"))
            && ids.iter().any(|id| id.starts_with("laser")),
        "a robot and a laser plugin: {ids:?}"
    );
    // Its data reaches the plugins: scans and odometry keep changing the scene.
    let before = viewer.scene().generation();
    run_until(
        &mut viewer,
        "the scene to change with data",
        Duration::from_secs(5),
        |v| v.scene().generation() > before + 5,
    );
}
