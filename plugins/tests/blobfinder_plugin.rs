//! The blobfinder plugin: fed blobs, one egui pass of its window draws a box per blob in the
//! blob's colour, placed on the canvas as the blob lies in the image.

mod support;

use egui::{Color32, Shape};
use framework::PluginConfig;
use framework::config::{DeviceRef, Param};
use framework::plugin::Plugin;
use player_proto::interfaces::blobfinder::{Blob, Blobfinder, BlobfinderData};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use support::{Harness, harness};

fn addr() -> DevAddr {
    "blobfinder:0".parse().unwrap()
}

fn config(params: Vec<Param>) -> PluginConfig {
    PluginConfig {
        library: "libpv3d_blobfinder".into(),
        id: "blobs".into(),
        device: Some(DeviceRef {
            host: "localhost".into(),
            port: 6668,
            addr: addr(),
            driver: "stage".into(),
        }),
        params,
        origin: "test.xml:1:1".into(),
        ..PluginConfig::default()
    }
}

/// The outlined rectangles one pass of the plugin's windows draws, with their stroke colour.
fn outlined_rects(h: &mut Harness, plugin: &mut dyn Plugin) -> Vec<(egui::Rect, Color32)> {
    let egui_ctx = egui::Context::default();
    // A window's first pass only measures it (nothing is painted): draw the second.
    let mut output = egui_ctx.run_ui(egui::RawInput::default(), |ui| {
        plugin.windows(ui.ctx(), &mut h.ctx());
    });
    output.textures_delta.clear();
    output = egui_ctx.run_ui(egui::RawInput::default(), |ui| {
        plugin.windows(ui.ctx(), &mut h.ctx());
    });
    output.textures_delta.clear();
    let mut shapes: Vec<Shape> = output.shapes.into_iter().map(|c| c.shape).collect();
    let mut rects = Vec::new();
    while let Some(shape) = shapes.pop() {
        match shape {
            Shape::Rect(r) if r.stroke.width > 0.0 => rects.push((r.rect, r.stroke.color)),
            Shape::Vec(inner) => shapes.extend(inner),
            _ => {}
        }
    }
    rects
}

#[test]
fn each_blob_is_a_box_in_its_colour_over_the_canvas() {
    let mut h = harness();
    let mut plugin = h
        .make(config(vec![Param::new("canvasWidth", "160")]))
        .unwrap();
    let red = Blob {
        id: 0,
        color: 0x00ff_0000,
        left: 0,
        top: 0,
        right: 39,
        bottom: 29,
        ..Blob::default()
    };
    let green = Blob {
        id: 1,
        color: 0x0000_ff00,
        left: 60,
        top: 40,
        right: 69,
        bottom: 49,
        ..Blob::default()
    };
    let data = BlobfinderData {
        width: 80,
        height: 60,
        blobs: vec![red, green],
    };
    h.device.push(Message::typed(
        addr(),
        MsgType::Data,
        Blobfinder::Blobs(data),
    ));
    assert!(
        !h.run_changes_scene(plugin.as_mut()),
        "the blobs live in their window, not the scene"
    );
    let rects = outlined_rects(&mut h, plugin.as_mut());
    // The window fades in, so its colours are dimmed: the hue tells the blobs apart.
    let of = |hue: fn(Color32) -> bool| rects.iter().find(|(_, c)| hue(*c)).map(|(r, _)| *r);
    let red_box = of(|c| c.r() > 0 && c.g() == 0 && c.b() == 0).expect("the red blob's box");
    let green_box = of(|c| c.g() > 0 && c.r() == 0 && c.b() == 0).expect("the green blob's box");
    // A 160 px canvas for an 80 px image: twice the size; the red blob is the top-left
    // half of the image in each direction.
    assert!((red_box.width() - 80.0).abs() < 0.5, "{red_box:?}");
    assert!((red_box.height() - 60.0).abs() < 0.5, "{red_box:?}");
    assert!((green_box.min.x - red_box.min.x - 120.0).abs() < 0.5);
    assert!((green_box.min.y - red_box.min.y - 80.0).abs() < 0.5);
}

#[test]
fn a_closed_window_draws_nothing_and_is_saved_closed() {
    let mut h = harness();
    let mut plugin = h.make(config(vec![Param::new("showWindow", "0")])).unwrap();
    assert!(outlined_rects(&mut h, plugin.as_mut()).is_empty());
    assert_eq!(plugin.save().param("showWindow").unwrap().text, "0");
    let error = h
        .make(config(vec![Param::new("canvasWidth", "5")]))
        .err()
        .expect("too small");
    assert!(error.to_string().contains("canvasWidth"), "{error}");
}
