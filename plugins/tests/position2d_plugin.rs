//! The position2d plugin fed known odometry: the body follows the pose, the trail grows, and
//! tele-operation sends safe velocity commands (and way-points in position mode); the dragged
//! target; the "Go to point…" service. (Actions on clicked objects: `position2d_actions.rs`.)

mod support;

use std::time::Duration;

use framework::config::Param;
use framework::device::ConnectionState;
use framework::plugin::{AnchorKey, InputEvent};
use glam::Vec3;
use support::position2d::{config, odometry, velocities, waypoints, world, world_with};
use support::{Harness, harness};

#[test]
fn the_body_follows_odometry_and_is_an_anchor_for_sensors() {
    let (mut w, mut plugin) = world();
    let key = AnchorKey {
        host: "localhost".into(),
        port: 6665,
        interface: "position2d".into(),
        index: 0,
    };
    assert_eq!(w.anchors.find(&key), plugin.node());
    odometry(&w.device, 1.0, 2.0, std::f64::consts::FRAC_PI_2);
    assert!(w.run_changes_scene(plugin.as_mut()));
    let node = plugin.node().unwrap();
    let nose = w
        .scene
        .world_transform(node)
        .transform_point3(Vec3::new(1.0, 0.0, 0.0));
    assert!(
        (nose - Vec3::new(1.0, 3.0, 0.0)).length() < 1e-5,
        "facing +y: {nose}"
    );
    odometry(&w.device, 1.5, 2.0, 0.0);
    plugin.run(&mut w.ctx());
    let trail_lines: usize = w
        .scene
        .iter()
        .filter(|(_, o)| o.name.ends_with("trail"))
        .map(|(_, o)| o.geometry.lines.len())
        .sum();
    assert_eq!(trail_lines, 2, "one trail segment between two poses");
}

#[test]
fn a_clicked_target_is_driven_to_and_stop_all_halts() {
    let (mut w, mut plugin) = world();
    odometry(&w.device, 0.0, 0.0, 0.0);
    plugin.run(&mut w.ctx());
    plugin.on_event(
        &InputEvent::GroundClicked(Vec3::new(2.0, 0.0, 0.0)),
        &mut w.ctx(),
    );
    assert!(
        velocities(&w.device).is_empty(),
        "not active: the click is not for this robot"
    );

    plugin.on_event(&InputEvent::Activated(true), &mut w.ctx());
    plugin.on_event(
        &InputEvent::GroundClicked(Vec3::new(2.0, 0.0, 0.0)),
        &mut w.ctx(),
    );
    plugin.run(&mut w.ctx());
    let (speed, turn) = *velocities(&w.device).last().unwrap();
    assert!(
        speed > 0.4 && turn.abs() < 1e-6,
        "straight ahead at full speed: {speed} {turn}"
    );

    plugin.on_event(&InputEvent::StopAll, &mut w.ctx());
    assert_eq!(*velocities(&w.device).last().unwrap(), (0.0, 0.0));
    w.now += Duration::from_secs(1);
    plugin.run(&mut w.ctx());
    assert_eq!(
        *velocities(&w.device).last().unwrap(),
        (0.0, 0.0),
        "no target any more"
    );
}

#[test]
fn arriving_stops_and_a_lost_connection_sends_nothing() {
    let (mut w, mut plugin) = world();
    odometry(&w.device, 0.0, 0.0, 0.0);
    plugin.on_event(&InputEvent::Activated(true), &mut w.ctx());
    plugin.on_event(
        &InputEvent::GroundClicked(Vec3::new(1.0, 0.0, 0.0)),
        &mut w.ctx(),
    );
    plugin.run(&mut w.ctx());
    odometry(&w.device, 0.98, 0.0, 0.0);
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(
        *velocities(&w.device).last().unwrap(),
        (0.0, 0.0),
        "arrived: stopped"
    );

    plugin.on_event(
        &InputEvent::GroundClicked(Vec3::new(5.0, 0.0, 0.0)),
        &mut w.ctx(),
    );
    *w.device.state.lock().unwrap() = Some(ConnectionState::Reconnecting { attempt: 1 });
    let before = velocities(&w.device).len();
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    *w.device.state.lock().unwrap() = Some(ConnectionState::Connected);
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(
        velocities(&w.device)[before..],
        [(0.0, 0.0)],
        "the target was dropped with the connection, and its return brought one zero command"
    );
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(velocities(&w.device).len(), before + 1, "and nothing more");
}

#[test]
fn position_mode_sends_one_waypoint_and_writes_the_mode_back() {
    let mut c = config("r0");
    c.params.push(Param::new("mode", "position"));
    let (mut w, mut plugin) = world_with(c);
    odometry(&w.device, 0.0, 0.0, 0.0);
    plugin.run(&mut w.ctx());
    plugin.on_event(&InputEvent::Activated(true), &mut w.ctx());
    plugin.on_event(
        &InputEvent::GroundClicked(Vec3::new(0.0, 2.0, 0.0)),
        &mut w.ctx(),
    );
    for _ in 0..3 {
        w.now += Duration::from_millis(200);
        plugin.run(&mut w.ctx());
    }
    let sent = waypoints(&w.device);
    assert_eq!(sent.len(), 1, "one way-point, not one per frame: {sent:?}");
    let (x, y, a) = sent[0];
    assert!(x.abs() < 1e-6 && (y - 2.0).abs() < 1e-6);
    assert!(
        (a - std::f64::consts::FRAC_PI_2).abs() < 1e-5,
        "facing the way it goes"
    );
    assert!(
        velocities(&w.device).is_empty(),
        "no velocities in position mode"
    );
    // The server drove it there: done, and a zero velocity makes sure it stays.
    odometry(&w.device, 0.0, 1.98, 1.5);
    plugin.run(&mut w.ctx());
    assert_eq!(velocities(&w.device), vec![(0.0, 0.0)]);
    let saved = plugin.save();
    assert_eq!(saved.text("mode"), Some("position"));
    assert_eq!(saved.text("followDistance"), Some("0.8"));

    let mut bad = config("r0");
    bad.params.push(Param::new("mode", "warp"));
    let err = harness().make(bad).err().unwrap().to_string();
    assert!(err.contains("<mode>") && err.contains("warp"), "{err}");
}

#[test]
fn a_dragged_target_shows_but_is_sent_only_on_release() {
    let (mut w, mut plugin) = world();
    odometry(&w.device, 0.0, 0.0, 0.0);
    plugin.run(&mut w.ctx());
    plugin.on_event(&InputEvent::Activated(true), &mut w.ctx());
    // The dragged target is drawn in cyan, a goal in amber.
    let drawn_in = |w: &Harness, rgb: [u8; 3]| -> usize {
        w.scene
            .iter()
            .filter(|(_, o)| o.name.ends_with("trail"))
            .flat_map(|(_, o)| o.geometry.lines.iter())
            .filter(|v| v.color.0 == [rgb[0], rgb[1], rgb[2], 255])
            .count()
    };
    let (cyan, amber) = ([90, 220, 240], [250, 200, 60]);
    plugin.on_event(
        &InputEvent::TargetDragged(Vec3::new(1.0, 1.0, 0.0)),
        &mut w.ctx(),
    );
    plugin.on_event(
        &InputEvent::TargetDragged(Vec3::new(2.0, 0.0, 0.0)),
        &mut w.ctx(),
    );
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(
        drawn_in(&w, cyan),
        4,
        "the dragged target's cross, where it is now"
    );
    assert_eq!(drawn_in(&w, amber), 0);
    assert!(
        velocities(&w.device).is_empty(),
        "nothing sent while dragging"
    );
    plugin.on_event(
        &InputEvent::GroundClicked(Vec3::new(2.0, 0.0, 0.0)),
        &mut w.ctx(),
    );
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    let (speed, _) = *velocities(&w.device).last().unwrap();
    assert!(speed > 0.4, "released: driving to the drop point");
    assert_eq!(drawn_in(&w, cyan), 0, "only the goal is drawn now");
    assert_eq!(drawn_in(&w, amber), 4);
}

#[test]
fn go_to_point_is_a_service_with_a_popup() {
    let (_w, plugin) = world();
    let services = plugin.services();
    let popup: Vec<&str> = services
        .iter()
        .filter(|s| s.popup)
        .map(|s| s.name)
        .collect();
    assert_eq!(popup, ["Go to point…"]);
    assert!(services.iter().any(|s| s.name == "Stop" && !s.popup));
}
