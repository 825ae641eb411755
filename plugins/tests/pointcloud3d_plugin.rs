//! The point-cloud plugin: every point drawn where the device puts it, coloured by its height
//! over the configured range; a range upside down is refused, naming the parameter.

mod support;

use framework::PluginConfig;
use framework::config::{DeviceRef, Param};
use framework::scene::Rgba;
use player_proto::interfaces::common::{Color, Point3d};
use player_proto::interfaces::pointcloud3d::{PointCloud3dData, PointCloud3dElement, Pointcloud3d};
use player_proto::message::Message;
use player_proto::{DevAddr, MsgType};
use support::harness;

fn addr() -> DevAddr {
    "pointcloud3d:0".parse().unwrap()
}

fn config(params: Vec<Param>) -> PluginConfig {
    PluginConfig {
        library: "libpv3d_pointcloud3d".into(),
        id: "cloud".into(),
        device: Some(DeviceRef {
            host: "localhost".into(),
            port: 6665,
            addr: addr(),
            driver: "reconstruction".into(),
        }),
        params,
        origin: "test.xml:1:1".into(),
        ..PluginConfig::default()
    }
}

fn cloud(heights: &[f64]) -> Message {
    let points = heights
        .iter()
        .enumerate()
        .map(|(i, &z)| PointCloud3dElement {
            point: Point3d {
                px: i as f64,
                py: 1.0,
                pz: z,
            },
            color: Color {
                alpha: 255,
                red: 1,
                green: 2,
                blue: 3,
            },
        })
        .collect();
    Message::typed(
        addr(),
        MsgType::Data,
        Pointcloud3d::State(PointCloud3dData { points }),
    )
}

#[test]
fn points_are_coloured_by_height_over_the_range() {
    let mut h = harness();
    let mut plugin = h
        .make(config(vec![
            Param::new("minHeight", "1"),
            Param::new("maxHeight", "3"),
        ]))
        .unwrap();
    h.device.push(cloud(&[1.0, 2.0, 3.0, 0.0]));
    assert!(h.run_changes_scene(plugin.as_mut()));
    let points = &h.scene.get(plugin.node().unwrap()).unwrap().geometry.points;
    assert_eq!(points.len(), 4);
    assert_eq!(points[1].pos, glam::Vec3::new(1.0, 1.0, 2.0));
    // Bottom blue, middle green, top red; below the range as the bottom.
    assert!(points[0].color.0[2] > 200 && points[0].color.0[0] < 60);
    assert!(points[1].color.0[1] > 180 && points[1].color.0[0] < 80);
    assert!(points[2].color.0[0] > 200 && points[2].color.0[2] < 60);
    assert_eq!(points[3].color, points[0].color);
}

#[test]
fn the_devices_colours_when_asked_and_huge_clouds_thinned() {
    let mut h = harness();
    let mut plugin = h
        .make(config(vec![
            Param::new("useDeviceColors", "1"),
            Param::new("maxPoints", "5"),
        ]))
        .unwrap();
    h.device.push(cloud(&[0.5; 12]));
    plugin.run(&mut h.ctx());
    let points = &h.scene.get(plugin.node().unwrap()).unwrap().geometry.points;
    assert!(points.len() <= 5 && points.len() >= 4, "{}", points.len());
    assert!(points.iter().all(|p| p.color == Rgba::rgb(1, 2, 3)));
}

#[test]
fn an_upside_down_range_names_the_parameter() {
    let mut h = harness();
    let error = h
        .make(config(vec![
            Param::new("minHeight", "2"),
            Param::new("maxHeight", "1"),
        ]))
        .err()
        .expect("refused");
    assert!(error.to_string().contains("maxHeight"), "{error}");
}
