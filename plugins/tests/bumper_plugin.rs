//! The bumper plugin fed a geometry and readings: the bumpers hang below their robot where
//! the geometry puts them, and the pressed one turns red.

mod support;

use framework::PluginConfig;
use framework::config::Param;
use framework::plugin::Plugin;
use framework::scene::Rgba;
use player_proto::interfaces::bumper::{Bumper, BumperData, BumperDefine, BumperGeometry};
use player_proto::interfaces::common::Pose3d;
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use support::{Harness, harness};

const RED: Rgba = Rgba::rgb(224, 60, 50);

fn addr() -> DevAddr {
    "bumper:0".parse().unwrap()
}

fn config(params: Vec<Param>) -> PluginConfig {
    support::on_robot("libpv3d_bumper", "bumper", "bumper:0", params)
}

/// Front bumper at +x, rear at −x.
fn geometry() -> BumperGeometry {
    let at = |x: f64, yaw: f64| BumperDefine {
        pose: Pose3d {
            px: x,
            pyaw: yaw,
            ..Pose3d::default()
        },
        length: 0.3,
        radius: 0.0,
    };
    BumperGeometry {
        bumper_def: vec![at(0.25, 0.0), at(-0.25, std::f64::consts::PI)],
    }
}

fn press(h: &Harness, states: Vec<u8>) {
    let data = BumperData {
        bumpers: states.into(),
    };
    h.device
        .push(Message::typed(addr(), MsgType::Data, Bumper::State(data)));
}

fn red_x(h: &Harness, plugin: &dyn Plugin) -> Vec<f32> {
    let node = h.scene.get(plugin.node().unwrap()).unwrap();
    node.geometry
        .lines
        .iter()
        .filter(|v| v.color == RED)
        .map(|v| v.pos.x)
        .collect()
}

#[test]
fn the_pressed_bumper_is_lit_where_the_geometry_puts_it() {
    let mut h = harness();
    let robot = h.robot_at(2.0);
    h.device.reply_to(
        Bumper::REQ_GET_GEOM.kind(),
        Ok(Message::typed(
            addr(),
            MsgType::Ack,
            Bumper::Geometry(geometry()),
        )),
    );
    let mut plugin = h.make(config(vec![])).unwrap();
    press(&h, vec![0, 1]);
    plugin.run(&mut h.ctx());
    let node = plugin.node().unwrap();
    assert_eq!(h.scene.get(node).unwrap().parent, Some(robot));
    let lit = red_x(&h, plugin.as_ref());
    assert_eq!(lit.len(), 2, "one red segment");
    assert!(
        lit.iter().all(|x| (x + 0.25).abs() < 1e-5),
        "the rear: {lit:?}"
    );
    assert_eq!(h.scene.get(node).unwrap().geometry.lines.len(), 4);

    press(&h, vec![1, 0]);
    plugin.run(&mut h.ctx());
    let lit = red_x(&h, plugin.as_ref());
    assert!(
        lit.iter().all(|x| (x - 0.25).abs() < 1e-5),
        "the front: {lit:?}"
    );
    press(&h, vec![1, 0]);
    assert!(
        !h.run_changes_scene(plugin.as_mut()),
        "the same reading again"
    );
}

#[test]
fn without_a_geometry_nothing_is_drawn_until_it_is_pushed() {
    let mut h = harness();
    let mut plugin = h.make(config(vec![])).unwrap();
    press(&h, vec![1, 1]);
    plugin.run(&mut h.ctx());
    let node = plugin.node().unwrap();
    assert!(h.scene.get(node).unwrap().geometry.is_empty());
    h.device.push(Message::typed(
        addr(),
        MsgType::Data,
        Bumper::GeometryData(geometry()),
    ));
    plugin.run(&mut h.ctx());
    assert_eq!(red_x(&h, plugin.as_ref()).len(), 4, "both pressed");
}

#[test]
fn a_bad_colour_names_the_parameter() {
    let mut h = harness();
    let error = h
        .make(config(vec![Param::new("idleColor", "#12")]))
        .err()
        .expect("refused");
    assert!(error.to_string().contains("idleColor"), "{error}");
}
