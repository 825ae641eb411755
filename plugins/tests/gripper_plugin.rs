//! The gripper plugin: its paddles stand in front of the robot at the reported pose, apart
//! when open and together when closed; Open and Close send the gripper's commands.

mod support;

use framework::PluginConfig;
use framework::config::Param;
use framework::plugin::Plugin;
use player_proto::interfaces::common::{BBox3d, Pose3d};
use player_proto::interfaces::gripper::{
    Gripper, GripperData, GripperGeometry, STATE_CLOSED, STATE_OPEN,
};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use support::{Harness, harness};

fn addr() -> DevAddr {
    "gripper:0".parse().unwrap()
}

fn config(params: Vec<Param>) -> PluginConfig {
    support::on_robot("libpv3d_gripper", "gripper", "gripper:0", params)
}

fn feed(h: &Harness, state: u8, beams: u32) {
    let data = GripperData {
        state,
        beams,
        stored: 0,
    };
    h.device
        .push(Message::typed(addr(), MsgType::Data, Gripper::State(data)));
}

/// How far apart the paddles' outer faces are, m.
fn spread(h: &Harness, plugin: &dyn Plugin) -> f32 {
    let mesh = &h.scene.get(plugin.node().unwrap()).unwrap().geometry.mesh;
    let ys = mesh.iter().map(|v| v.pos.y);
    ys.clone().fold(f32::MIN, f32::max) - ys.fold(f32::MAX, f32::min)
}

#[test]
fn the_paddles_open_and_close_in_front_of_the_robot() {
    let mut h = harness();
    let robot = h.robot_at(0.0);
    let geometry = GripperGeometry {
        pose: Pose3d {
            px: 0.3,
            ..Pose3d::default()
        },
        outer_size: BBox3d {
            sw: 0.3,
            sl: 0.2,
            sh: 0.1,
        },
        ..GripperGeometry::default()
    };
    h.device.reply_to(
        Gripper::REQ_GET_GEOM.kind(),
        Ok(Message::typed(
            addr(),
            MsgType::Ack,
            Gripper::Geometry(geometry),
        )),
    );
    let mut plugin = h.make(config(vec![])).unwrap();
    feed(&h, STATE_OPEN, 0);
    plugin.run(&mut h.ctx());
    let node = plugin.node().unwrap();
    assert_eq!(h.scene.get(node).unwrap().parent, Some(robot));
    let at = h.scene.world_transform(node).translation;
    assert!((at.x - 0.3).abs() < 1e-6, "{at}");
    assert!((spread(&h, plugin.as_ref()) - 0.3).abs() < 1e-5);
    assert!(
        h.scene.get(node).unwrap().geometry.lines.is_empty(),
        "no beam"
    );

    feed(&h, STATE_CLOSED, 1);
    plugin.run(&mut h.ctx());
    assert!(spread(&h, plugin.as_ref()) < 0.05, "closed");
    assert_eq!(
        h.scene.get(node).unwrap().geometry.lines.len(),
        2,
        "the broken beam"
    );
}

#[test]
fn open_and_close_send_the_grippers_commands() {
    let mut h = harness();
    let mut plugin = h.make(config(vec![])).unwrap();
    let names: Vec<_> = plugin.services().iter().map(|s| s.name).collect();
    assert_eq!(names, ["Open", "Close"]);
    plugin.run_service("Close", &mut h.ctx());
    plugin.run_service("Open", &mut h.ctx());
    let commands = h.device.commands.lock().unwrap();
    assert!(Gripper::CMD_CLOSE.body_of(&commands[0]).is_some());
    assert!(Gripper::CMD_OPEN.body_of(&commands[1]).is_some());
    assert_eq!(
        commands[0].kind().map(|(_, subtype)| subtype),
        Some(Gripper::CMD_CLOSE.subtype())
    );
}
