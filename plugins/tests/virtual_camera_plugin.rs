//! The virtual camera plugin describes a camera the viewer renders: it rides on its robot, asks
//! for the size and field of view it was given, draws its frustum, takes the rendered picture
//! and refuses impossible parameters with a message naming them.

mod support;

use framework::PluginConfig;
use framework::config::Param;
use framework::scene::{PixelFormat, Pixels};
use glam::Vec3;
use support::harness;

fn config(extra: Vec<Param>) -> PluginConfig {
    support::on_robot("libpv3d_virtual_camera", "onboard", "position2d:0", extra)
}

#[test]
fn the_camera_rides_on_its_robot_and_asks_for_its_picture() {
    let mut h = harness();
    let robot = h.robot_at(2.0);
    let mut plugin = h
        .make(config(vec![
            Param::new("width", "64"),
            Param::new("height", "48"),
            Param::new("fov", "90"),
            Param::new("pose", "0.1 0 0.5 90"),
        ]))
        .unwrap();
    plugin.run(&mut h.ctx());
    let node = plugin.node().unwrap();
    let object = h.scene.get(node).unwrap();
    assert_eq!(object.parent, Some(robot));
    let view = object.geometry.views.first().expect("a virtual view");
    assert_eq!((view.width, view.height), (64, 48));
    assert!((view.fov_y.to_degrees() - 90.0).abs() < 1e-3);
    assert_eq!(object.geometry.lines.len(), 16, "the frustum");
    let camera = h.scene.world_transform(node);
    let eye = camera.transform_point3(Vec3::ZERO);
    assert!((eye - Vec3::new(2.1, 0.0, 0.5)).length() < 1e-5, "{eye}");
    let looking = camera.transform_vector3(Vec3::X);
    assert!(
        (looking - Vec3::Y).length() < 1e-5,
        "yaw 90° looks north: {looking}"
    );

    // The viewer delivers a picture; the plugin takes it on its next runs without trouble.
    let mut bytes = vec![0u8; 64 * 48 * 4];
    bytes[..4].copy_from_slice(&[255, 0, 0, 255]); // row 0 = the bottom row
    view.output
        .deliver(Pixels::new(64, 48, PixelFormat::Rgba8, bytes).unwrap());
    plugin.run(&mut h.ctx());
    plugin.run(&mut h.ctx());
    assert!(plugin.title().contains("onboard"));
    let summary = plugin.save();
    assert_eq!(summary.text("showWindow"), Some("1"));
}

#[test]
fn impossible_cameras_are_refused_with_the_parameter_named() {
    for (name, text) in [
        ("width", "0"),
        ("height", "100000"),
        ("fov", "200"),
        ("pose", "1 2"),
        ("color", "not-a-colour"),
    ] {
        let error = harness()
            .make(config(vec![Param::new(name, text)]))
            .err()
            .unwrap_or_else(|| panic!("{name}={text} is refused"));
        assert!(error.to_string().contains(name), "{name}: {error}");
    }
}
