//! The position2d plugin fed known odometry: the body follows the pose, the trail grows, and
//! tele-operation sends safe velocity commands (and way-points in position mode); actions on
//! clicked objects ("Go to", "Follow") and the dragged target.

mod support;

use std::time::Duration;

use framework::PluginConfig;
use framework::action::ObjectRef;
use framework::config::DeviceRef;
use framework::config::Param;
use framework::device::{ConnectionState, RecordingDevice};
use framework::plugin::{AnchorKey, InputEvent, Plugin};
use framework::scene::Object3D;
use framework::scene::Scene;
use glam::Vec3;
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::position2d::{Position2d, Position2dData};
use player_proto::message::{Body, Message};
use player_proto::{DevAddr, MsgType};
use support::{Harness, harness};

fn config() -> PluginConfig {
    PluginConfig {
        library: "libpv3d_position2d".into(),
        id: "r0".into(),
        device: Some(DeviceRef {
            host: "localhost".into(),
            port: 6665,
            addr: "position2d:0".parse().unwrap(),
            driver: "stage".into(),
        }),
        ..PluginConfig::default()
    }
}

fn odometry(device: &RecordingDevice, x: f64, y: f64, a: f64) {
    let state = Position2dData {
        pos: Pose2d::new(x, y, a),
        vel: Pose2d::default(),
        stall: 0,
    };
    let addr: DevAddr = "position2d:0".parse().unwrap();
    device.push(Message::typed(
        addr,
        MsgType::Data,
        Position2d::State(state),
    ));
}

fn velocities(device: &RecordingDevice) -> Vec<(f64, f64)> {
    device
        .commands
        .lock()
        .unwrap()
        .iter()
        .filter_map(|b| match b {
            Body::Position2d(Position2d::Velocity(v)) => Some((v.vel.px, v.vel.pa)),
            _ => None,
        })
        .collect()
}

fn world() -> (Harness, Box<dyn Plugin>) {
    world_with(config())
}

fn waypoints(device: &RecordingDevice) -> Vec<(f64, f64, f64)> {
    device
        .commands
        .lock()
        .unwrap()
        .iter()
        .filter_map(|b| match b {
            Body::Position2d(Position2d::Position(p)) => Some((p.pos.px, p.pos.py, p.pos.pa)),
            _ => None,
        })
        .collect()
}

/// A fiducial marker as the fiducial plugin makes it (re-created every scan).
fn marker(scene: &mut Scene, id: i32, x: f32, y: f32) -> framework::scene::NodeId {
    let mut o = Object3D::new(format!("marker {id}"));
    o.tags = vec!["fiducial".into(), format!("id:{id}"), "person".into()];
    o.transform = glam::Affine3A::from_translation(Vec3::new(x, y, 0.0));
    scene.add(o)
}

fn world_with(config: PluginConfig) -> (Harness, Box<dyn Plugin>) {
    let mut w = harness();
    let plugin = w.make(config).unwrap();
    (w, plugin)
}

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
    let mut c = config();
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

    let mut bad = config();
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
fn go_to_and_follow_a_marker_that_is_re_created_every_scan() {
    let (mut w, mut plugin) = world();
    odometry(&w.device, 0.0, 0.0, 0.0);
    plugin.run(&mut w.ctx());
    let seen = marker(&mut w.scene, 7, 3.0, 0.0);
    let target = ObjectRef::of(&w.scene, seen).unwrap();
    let names: Vec<&str> = plugin.actions_on(&target).iter().map(|a| a.name).collect();
    assert_eq!(names, ["Go to", "Follow"]);
    let own = ObjectRef::of(&w.scene, plugin.node().unwrap()).unwrap();
    assert!(
        plugin.actions_on(&own).is_empty(),
        "nothing to do with itself"
    );

    // Go to: drives to 0.8 m short of the marker, then stops there.
    plugin.run_action("Go to", &target, &mut w.ctx());
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert!(velocities(&w.device).last().unwrap().0 > 0.4);
    odometry(&w.device, 2.19, 0.0, 0.0);
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(
        *velocities(&w.device).last().unwrap(),
        (0.0, 0.0),
        "next to it"
    );

    // Follow: the marker is re-created elsewhere; the robot turns and heads for it.
    plugin.run_action("Follow", &target, &mut w.ctx());
    w.scene.remove(seen);
    marker(&mut w.scene, 8, 2.5, -2.0);
    marker(&mut w.scene, 7, 2.2, 3.0);
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    let (_, turn) = *velocities(&w.device).last().unwrap();
    assert!(turn > 0.5, "turning left, towards marker 7 (not 8): {turn}");
    // Near enough: it holds still, but keeps following.
    odometry(&w.device, 2.2, 2.3, 1.57);
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(*velocities(&w.device).last().unwrap(), (0.0, 0.0));
    let held = velocities(&w.device).len();
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(
        velocities(&w.device).len(),
        held,
        "holding: no repeated commands"
    );
    // The person walks on; the robot goes after them, until stopped.
    let walked = w.scene.iter().find(|(_, o)| o.has_tag("id:7")).unwrap().0;
    w.scene.get_mut(walked).unwrap().transform =
        glam::Affine3A::from_translation(Vec3::new(2.2, 5.0, 0.0));
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert!(velocities(&w.device).last().unwrap().0 > 0.3, "after them");
    plugin.on_event(&InputEvent::StopAll, &mut w.ctx());
    assert_eq!(*velocities(&w.device).last().unwrap(), (0.0, 0.0));
    let stopped = velocities(&w.device).len();
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(velocities(&w.device).len(), stopped, "stopped following");
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

#[test]
fn following_in_position_mode_sends_a_new_waypoint_only_when_the_object_moved() {
    let mut c = config();
    c.params.push(Param::new("mode", "position"));
    c.params.push(Param::new("followDistance", "1"));
    let (mut w, mut plugin) = world_with(c);
    odometry(&w.device, 0.0, 0.0, 0.0);
    plugin.run(&mut w.ctx());
    let seen = marker(&mut w.scene, 7, 4.0, 0.0);
    let target = ObjectRef::of(&w.scene, seen).unwrap();
    plugin.run_action("Follow", &target, &mut w.ctx());
    for _ in 0..3 {
        w.now += Duration::from_millis(200);
        plugin.run(&mut w.ctx());
    }
    let sent = waypoints(&w.device);
    assert_eq!(sent.len(), 1, "{sent:?}");
    assert!(
        (sent[0].0 - 3.0).abs() < 1e-5 && sent[0].1.abs() < 1e-5,
        "1 m short"
    );
    // A small step of the person: no new way-point; a real one: a new way-point.
    w.scene.get_mut(seen).unwrap().transform =
        glam::Affine3A::from_translation(Vec3::new(4.05, 0.0, 0.0));
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(waypoints(&w.device).len(), 1);
    w.scene.get_mut(seen).unwrap().transform =
        glam::Affine3A::from_translation(Vec3::new(4.0, 2.0, 0.0));
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    let sent = waypoints(&w.device);
    assert_eq!(sent.len(), 2);
    let (x, y, a) = sent[1];
    let expected = Vec3::new(4.0, 2.0, 0.0) - Vec3::new(4.0, 2.0, 0.0).normalize();
    assert!((x - f64::from(expected.x)).abs() < 1e-4 && (y - f64::from(expected.y)).abs() < 1e-4);
    assert!(
        (a - (2.0f64).atan2(4.0)).abs() < 1e-4,
        "facing the person: {a}"
    );
    // Arrived within the distance: a zero velocity, and no more way-points.
    odometry(&w.device, expected.x.into(), expected.y.into(), a);
    w.now += Duration::from_millis(200);
    plugin.run(&mut w.ctx());
    assert_eq!(velocities(&w.device), vec![(0.0, 0.0)]);
    assert_eq!(waypoints(&w.device).len(), 2);
}
