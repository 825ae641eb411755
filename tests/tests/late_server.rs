//! A Player server that answers only after the viewer started (a robot still booting, a
//! simulation started second) gets its plugins when it answers, and its data flows.

use std::time::Duration;

use tests::{load, point_at, run_until, serve_on_port, unused_port, viewer_for};

#[test]
fn a_server_that_answers_late_gets_its_plugins() {
    // A port nobody listens on yet.
    let port = unused_port();
    let mut composition = load(&["configs/single-laser.pv3d.xml"]);
    point_at(&mut composition, port);
    let mut viewer = viewer_for(&composition);
    let named_outright = viewer.plugin_count();
    assert_eq!(
        named_outright, 2,
        "lights and ground only, while the server is down"
    );

    let _running = serve_on_port("stage-worlds/simple.world", port);

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
