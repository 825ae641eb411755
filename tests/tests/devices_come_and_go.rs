//! Devices that come and go, over real TCP: a Player server restarted on the same port with a
//! device more gets that device's plugin from its handler; restarted with it missing, the
//! plugin is cleaned and the item tree and the status panel say "device gone"; restarted with
//! it back, the same plugin resumes — not a second one.

use std::time::Duration;

use player_proto::Interface;
use player_proto::client::ConnectionState;
use player_sim::serve::Running;
use pv3d::app::Viewer;
use tests::{load, point_at, run_until, serve_some_on_port, texts_drawn, unused_port, viewer_for};

const WORLD: &str = "stage-worlds/simple.world";

/// How long a restarted server may take to be answered and composed.
const PATIENCE: Duration = Duration::from_secs(15);

/// Serves the world with or without its laser.
fn serve(port: u16, with_laser: bool) -> Running {
    serve_some_on_port(WORLD, port, |device| {
        with_laser || device.interf != Interface::LASER
    })
}

/// Stops `server` and waits until the viewer's client has noticed.
fn stop(mut server: Running, viewer: &Viewer, port: u16) {
    server.stop();
    drop(server);
    let robots = viewer.robots.as_ref().expect("a composition with servers");
    let client = robots
        .client("127.0.0.1", port)
        .expect("the server's client");
    let lost = client.wait_for_state(PATIENCE, |s| *s != ConnectionState::Connected);
    assert!(lost.is_some(), "the client should notice the server went");
}

fn laser_nodes(viewer: &Viewer) -> usize {
    viewer
        .scene()
        .iter()
        .filter(|(_, o)| o.has_tag("laser"))
        .count()
}

fn laser_plugins(viewer: &Viewer) -> usize {
    viewer
        .titles()
        .iter()
        .filter(|t| t.starts_with("Laser"))
        .count()
}

#[test]
fn a_device_that_appears_goes_and_comes_back_gets_gone_and_resumes_its_plugin() {
    let port = unused_port();
    let mut composition = load(&["configs/single-laser.pv3d.xml"]);
    point_at(&mut composition, port);
    let first = serve(port, false);
    let mut viewer = viewer_for(&composition);
    assert!(viewer.errors.is_empty(), "{:?}", viewer.errors);
    assert_eq!(laser_plugins(&viewer), 0, "no laser served yet");
    let without_laser = viewer.plugin_count();

    // Restarted with a laser: the laser handler makes its plugin.
    stop(first, &viewer, port);
    let second = serve(port, true);
    run_until(&mut viewer, "the new laser's plugin", PATIENCE, |v| {
        laser_plugins(v) == 1
    });
    assert_eq!(viewer.plugin_count(), without_laser + 1);
    assert_eq!(laser_nodes(&viewer), 1);

    // Restarted without it: cleaned, and said to be gone.
    stop(second, &viewer, port);
    let third = serve(port, false);
    run_until(&mut viewer, "the laser plugin to be gone", PATIENCE, |v| {
        !v.gone_titles().is_empty()
    });
    assert_eq!(laser_plugins(&viewer), 0);
    assert_eq!(laser_nodes(&viewer), 0, "clean() took its nodes out");
    let gone = viewer.gone_titles();
    assert!(gone[0].starts_with("Laser"), "{gone:?}");
    assert!(
        viewer.save().iter().any(|i| i.library() == "libpv3d_laser"),
        "a saved composition keeps the gone plugin"
    );
    let texts = texts_drawn(&mut viewer, &egui::Context::default());
    let says_gone = |what: &str| texts.iter().any(|t| t.contains(what));
    assert!(
        says_gone(&format!("{}  (device gone)", gone[0])),
        "the item tree says so: {texts:?}"
    );
    assert!(
        says_gone("laser:0 device gone"),
        "the status panel says so: {texts:?}"
    );

    // Back again: the same plugin resumes, no second one is made.
    stop(third, &viewer, port);
    let _fourth = serve(port, true);
    run_until(&mut viewer, "the laser plugin to resume", PATIENCE, |v| {
        v.gone_titles().is_empty()
    });
    assert_eq!(laser_plugins(&viewer), 1);
    assert_eq!(viewer.plugin_count(), without_laser + 1);
    // And its data flows again: the scan is drawn.
    run_until(&mut viewer, "the resumed laser's scan", PATIENCE, |v| {
        v.scene()
            .iter()
            .any(|(_, o)| o.has_tag("laser") && !o.geometry.points.is_empty())
    });
}
