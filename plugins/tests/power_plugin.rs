//! The battery gauge fed known readings: it stands above its robot, its filled length is the
//! charge, its colour and the item tree's words turn to "low" below the threshold.

mod support;

use framework::PluginConfig;
use framework::config::Param;
use framework::plugin::Plugin;
use framework::scene::Rgba;
use player_proto::interfaces::power::{MASK_PERCENT, MASK_VOLTS, Power, PowerData};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use support::{Harness, harness};

fn config(extra: Vec<Param>) -> PluginConfig {
    support::on_robot("libpv3d_power", "battery", "power:0", extra)
}

fn feed(h: &Harness, percent: f32) {
    let addr: DevAddr = "power:0".parse().unwrap();
    let data = PowerData {
        valid: MASK_PERCENT | MASK_VOLTS,
        percent,
        volts: 12.4,
        ..PowerData::default()
    };
    h.device
        .push(Message::typed(addr, MsgType::Data, Power::State(data)));
}

/// The gauge's filled bar (its only solid box) and its colour.
fn filled_width(h: &Harness, plugin: &dyn Plugin) -> (f32, Rgba) {
    let gauge = h.scene.get(plugin.node().unwrap()).unwrap();
    let bar = &gauge.geometry.mesh;
    let xs = bar.iter().map(|v| v.pos.x);
    let width = xs.clone().fold(f32::MIN, f32::max) - xs.fold(f32::MAX, f32::min);
    (width, bar[0].color)
}

fn make(h: &mut Harness, extra: Vec<Param>) -> Box<dyn Plugin> {
    h.make(config(extra)).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn the_gauge_stands_on_its_robot_and_shows_the_charge() {
    let mut h = harness();
    let robot = h.robot_at(3.0);
    let mut plugin = make(&mut h, vec![]);
    feed(&h, 80.0);
    assert!(h.run_changes_scene(plugin.as_mut()));
    let node = plugin.node().unwrap();
    assert_eq!(h.scene.get(node).unwrap().parent, Some(robot));
    let at = h
        .scene
        .world_transform(node)
        .transform_point3(glam::Vec3::ZERO);
    assert!((at.x - 3.0).abs() < 1e-5, "{at}");
    let gauge = h.scene.get(node).unwrap();
    assert_eq!(gauge.geometry.labels[0].text, "80 %");
    let (width, colour) = filled_width(&h, plugin.as_ref());
    assert!((width - 0.4 * 0.8).abs() < 1e-4, "{width}");
    assert_eq!(colour, Rgba::rgb(80, 200, 90));
}

#[test]
fn below_the_threshold_it_turns_amber_then_red() {
    let mut h = harness();
    h.robot_at(0.0);
    let mut plugin = make(&mut h, vec![Param::new("lowPercent", "30")]);
    feed(&h, 25.0);
    plugin.run(&mut h.ctx());
    assert_eq!(filled_width(&h, plugin.as_ref()).1, Rgba::rgb(240, 170, 40));
    feed(&h, 10.0);
    plugin.run(&mut h.ctx());
    assert_eq!(filled_width(&h, plugin.as_ref()).1, Rgba::rgb(230, 60, 50));
    assert!(
        !h.run_changes_scene(plugin.as_mut()),
        "the same reading twice changes nothing"
    );
}

#[test]
fn a_threshold_out_of_range_names_where() {
    let mut h = harness();
    let error = h
        .make(config(vec![Param::new("lowPercent", "140")]))
        .err()
        .expect("140 % is refused");
    assert!(error.to_string().contains("lowPercent"), "{error}");
}
