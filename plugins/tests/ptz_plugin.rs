//! The PTZ plugin: its window shows the state the mount reports; "Centre" sends a command
//! that pans and tilts back to straight ahead, keeping the zoom.

mod support;

use egui::Shape;
use framework::PluginConfig;
use framework::config::{DeviceRef, Param};
use framework::plugin::Plugin;
use player_proto::interfaces::ptz::{Ptz, PtzData};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use support::{Harness, harness};

fn addr() -> DevAddr {
    "ptz:0".parse().unwrap()
}

fn config(params: Vec<Param>) -> PluginConfig {
    PluginConfig {
        library: "libpv3d_ptz".into(),
        id: "ptz".into(),
        device: Some(DeviceRef {
            host: "localhost".into(),
            port: 6665,
            addr: addr(),
            driver: "sonyevid30".into(),
        }),
        params,
        origin: "test.xml:1:1".into(),
        ..PluginConfig::default()
    }
}

fn feed(h: &Harness) {
    let state = PtzData {
        pan: 30f32.to_radians(),
        tilt: (-10f32).to_radians(),
        zoom: 40f32.to_radians(),
        ..PtzData::default()
    };
    h.device
        .push(Message::typed(addr(), MsgType::Data, Ptz::State(state)));
}

fn texts(h: &mut Harness, plugin: &mut dyn Plugin) -> Vec<String> {
    let egui_ctx = egui::Context::default();
    let mut all = Vec::new();
    // The first pass of a window only measures it: the second paints.
    for _ in 0..2 {
        let mut output = egui_ctx.run_ui(egui::RawInput::default(), |ui| {
            plugin.windows(ui.ctx(), &mut h.ctx());
        });
        output.textures_delta.clear();
        let mut shapes: Vec<Shape> = output.shapes.into_iter().map(|c| c.shape).collect();
        while let Some(shape) = shapes.pop() {
            match shape {
                Shape::Text(t) => all.push(t.galley.text().to_string()),
                Shape::Vec(inner) => shapes.extend(inner),
                _ => {}
            }
        }
    }
    all
}

#[test]
fn the_window_shows_the_state_and_centre_keeps_the_zoom() {
    let mut h = harness();
    let mut plugin = h.make(config(vec![])).unwrap();
    feed(&h);
    plugin.run(&mut h.ctx());
    let shown = texts(&mut h, plugin.as_mut());
    assert!(
        shown.iter().any(|t| t == "pan 30°, tilt -10°, zoom 40°"),
        "{shown:?}"
    );
    assert!(
        h.device.commands.lock().unwrap().is_empty(),
        "showing sends nothing"
    );

    plugin.run_service("Centre", &mut h.ctx());
    let commands = h.device.commands.lock().unwrap();
    let cmd = Ptz::CMD_STATE.body_of(&commands[0]).expect("a PTZ command");
    assert_eq!((cmd.pan, cmd.tilt), (0.0, 0.0));
    assert!((cmd.zoom - 40f32.to_radians()).abs() < 1e-5);
}

#[test]
fn limits_out_of_range_name_the_parameter() {
    let mut h = harness();
    let error = h
        .make(config(vec![Param::new("maxTilt", "120")]))
        .err()
        .expect("refused");
    assert!(error.to_string().contains("maxTilt"), "{error}");
}
