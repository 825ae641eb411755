//! The position2d plugin fed known odometry: the body follows the pose, the trail grows, and
//! tele-operation sends safe velocity commands.

use std::time::{Duration, Instant};

use glam::Vec3;
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::position2d::{Position2d, Position2dData};
use player_proto::message::{Body, Message};
use player_proto::{DevAddr, MsgType};
use pv3d_plugins::config::DeviceRef;
use pv3d_plugins::device::{LinkState, RecordingDevice};
use pv3d_plugins::plugin::{AnchorKey, Anchors, InputEvent, Plugin, PluginContext};
use pv3d_plugins::scene::Scene;
use pv3d_plugins::{PluginConfig, standard_plugins};

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

struct World {
    scene: Scene,
    anchors: Anchors,
    device: RecordingDevice,
    now: Instant,
}

impl World {
    fn ctx(&mut self) -> PluginContext<'_> {
        PluginContext {
            scene: &mut self.scene,
            device: Some(&self.device),
            anchors: &mut self.anchors,
            now: self.now,
        }
    }
}

fn world() -> (World, Box<dyn Plugin>) {
    let mut w = World {
        scene: Scene::new(),
        anchors: Anchors::default(),
        device: RecordingDevice::default(),
        now: Instant::now(),
    };
    let create = standard_plugins()
        .constructor("libpv3d_position2d")
        .unwrap();
    let plugin = create(config(), &mut w.ctx()).unwrap();
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
    assert!(plugin.update(&mut w.ctx()));
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
    plugin.update(&mut w.ctx());
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
    plugin.update(&mut w.ctx());
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
    plugin.update(&mut w.ctx());
    let (speed, turn) = *velocities(&w.device).last().unwrap();
    assert!(
        speed > 0.4 && turn.abs() < 1e-6,
        "straight ahead at full speed: {speed} {turn}"
    );

    plugin.on_event(&InputEvent::StopAll, &mut w.ctx());
    assert_eq!(*velocities(&w.device).last().unwrap(), (0.0, 0.0));
    w.now += Duration::from_secs(1);
    plugin.update(&mut w.ctx());
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
    plugin.update(&mut w.ctx());
    odometry(&w.device, 0.98, 0.0, 0.0);
    w.now += Duration::from_millis(200);
    plugin.update(&mut w.ctx());
    assert_eq!(
        *velocities(&w.device).last().unwrap(),
        (0.0, 0.0),
        "arrived: stopped"
    );

    plugin.on_event(
        &InputEvent::GroundClicked(Vec3::new(5.0, 0.0, 0.0)),
        &mut w.ctx(),
    );
    *w.device.state.lock().unwrap() = Some(LinkState::Reconnecting { attempt: 1 });
    let before = velocities(&w.device).len();
    w.now += Duration::from_millis(200);
    plugin.update(&mut w.ctx());
    *w.device.state.lock().unwrap() = Some(LinkState::Connected);
    w.now += Duration::from_millis(200);
    plugin.update(&mut w.ctx());
    assert_eq!(
        velocities(&w.device).len(),
        before,
        "the target was dropped with the connection"
    );
}
