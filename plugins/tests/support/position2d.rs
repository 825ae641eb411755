//! A robot's position2d plugin fed by hand: its configuration, odometry pushed as Stage sends
//! it, and the commands it sent back.

use framework::PluginConfig;
use framework::config::DeviceRef;
use framework::device::RecordingDevice;
use framework::plugin::Plugin;
use framework::scene::{NodeId, Object3D, Scene};
use glam::Vec3;
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::position2d::{Position2d, Position2dData};
use player_proto::message::{Body, Message};
use player_proto::{DevAddr, MsgType};

use super::Harness;

/// The plugin for `position2d:0` of localhost:6665, called `id`.
pub fn config(id: &str) -> PluginConfig {
    PluginConfig {
        library: "libpv3d_position2d".into(),
        id: id.into(),
        device: Some(DeviceRef {
            host: "localhost".into(),
            port: 6665,
            addr: "position2d:0".parse().unwrap(),
            driver: "stage".into(),
        }),
        ..PluginConfig::default()
    }
}

/// The robot's odometry says it is at (`x`, `y`) facing `a` (rad).
pub fn odometry(device: &RecordingDevice, x: f64, y: f64, a: f64) {
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

/// The commands sent that `pick` recognises, oldest first.
fn sent<T>(device: &RecordingDevice, pick: impl Fn(&Position2d) -> Option<T>) -> Vec<T> {
    let commands = device.commands.lock().unwrap();
    commands
        .iter()
        .filter_map(|b| match b {
            Body::Position2d(command) => pick(command),
            _ => None,
        })
        .collect()
}

/// Every velocity command sent, (forward m/s, turn rad/s), oldest first.
pub fn velocities(device: &RecordingDevice) -> Vec<(f64, f64)> {
    sent(device, |c| match c {
        Position2d::Velocity(v) => Some((v.vel.px, v.vel.pa)),
        _ => None,
    })
}

/// Every way-point sent (position mode), (x, y, yaw), oldest first.
pub fn waypoints(device: &RecordingDevice) -> Vec<(f64, f64, f64)> {
    sent(device, |c| match c {
        Position2d::Position(p) => Some((p.pos.px, p.pos.py, p.pos.pa)),
        _ => None,
    })
}

/// A harness and the robot plugin `config` makes in it.
pub fn world_with(config: PluginConfig) -> (Harness, Box<dyn Plugin>) {
    let mut w = super::harness();
    let plugin = w.make(config).unwrap();
    (w, plugin)
}

/// A harness and robot `r0`.
pub fn world() -> (Harness, Box<dyn Plugin>) {
    world_with(config("r0"))
}

/// A fiducial marker as the fiducial plugin makes it (re-created every scan), also tagged
/// `person`.
pub fn marker(scene: &mut Scene, id: i32, x: f32, y: f32) -> NodeId {
    let mut o = Object3D::new(format!("marker {id}"));
    o.tags = vec!["fiducial".into(), format!("id:{id}"), "person".into()];
    o.transform = glam::Affine3A::from_translation(Vec3::new(x, y, 0.0));
    scene.add(o)
}
