//! The infrared plugin fed poses and readings: narrow cones below the robot, along each
//! ranger's heading and as long as its reading, in the infrared's colour by default.

mod support;

use framework::PluginConfig;
use framework::config::Param;
use framework::scene::Vertex;
use glam::Vec3;
use player_proto::interfaces::common::Pose3d;
use player_proto::interfaces::ir::{Ir, IrData, IrPose};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use support::harness;

fn addr() -> DevAddr {
    "ir:0".parse().unwrap()
}

fn config(params: Vec<Param>) -> PluginConfig {
    support::on_robot("libpv3d_ir", "ir", "ir:0", params)
}

#[test]
fn each_ranger_is_a_cone_along_its_heading_as_long_as_its_reading() {
    let mut h = harness();
    let robot = h.robot_at(1.0);
    // One ranger at the front looking ahead, one at the left looking left.
    let poses = IrPose {
        poses: vec![
            Pose3d {
                px: 0.2,
                ..Pose3d::default()
            },
            Pose3d {
                py: 0.2,
                pyaw: std::f64::consts::FRAC_PI_2,
                ..Pose3d::default()
            },
        ],
    };
    h.device.reply_to(
        Ir::REQ_POSE.kind(),
        Ok(Message::typed(addr(), MsgType::Ack, Ir::Pose(poses))),
    );
    let mut plugin = h.make(config(vec![])).unwrap();
    let data = IrData {
        voltages: vec![1.0, 1.0],
        ranges: vec![0.5, 1.5],
    };
    h.device
        .push(Message::typed(addr(), MsgType::Data, Ir::Ranges(data)));
    assert!(h.run_changes_scene(plugin.as_mut()));
    let node = h.scene.get(plugin.node().unwrap()).unwrap();
    assert_eq!(node.parent, Some(robot));
    let fans = &node.geometry.fans;
    let triangles: Vec<Vertex> = (fans.iter())
        .flat_map(|f| {
            (f.fill_triangles().flatten()).map(|pos| Vertex {
                pos,
                color: f.fill.unwrap(),
            })
        })
        .collect();
    assert!(!triangles.is_empty());
    assert_eq!(triangles[0].color.0[..3], [230, 120, 60], "infrared colour");
    // The front cone (the triangles ahead of the robot's middle) reaches 0.5 m.
    let front = triangles
        .iter()
        .filter(|v| v.pos.x > 0.15)
        .map(|v| (v.pos - Vec3::new(0.2, 0.0, 0.0)).length())
        .fold(0.0, f32::max);
    assert!((front - 0.5).abs() < 1e-4, "{front}");
    // The left cone reaches 1.5 m along +y.
    assert!(
        triangles
            .iter()
            .any(|v| (v.pos - Vec3::new(0.0, 1.7, 0.0)).length() < 0.01),
        "the left cone's far rim"
    );
    // Narrow: the front cone's rim stays within 5° (≈ 0.022 m at 0.5 m) of the axis.
    assert!(
        triangles
            .iter()
            .filter(|v| v.pos.x > 0.3)
            .all(|v| v.pos.y.abs() < 0.03),
        "a narrow beam"
    );
}

#[test]
fn the_cone_parameters_are_the_sonars() {
    let mut h = harness();
    let error = h
        .make(config(vec![Param::new("coneAngle", "361")]))
        .err()
        .expect("refused");
    assert!(error.to_string().contains("coneAngle"), "{error}");
    let plugin = h.make(config(vec![Param::new("alpha", "0.5")])).unwrap();
    assert_eq!(plugin.save().param("alpha").unwrap().text, "0.50");
}
