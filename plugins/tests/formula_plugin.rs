//! The formula plugin: a typeset formula that follows its robot's position (not its heading)
//! as a billboard the renderer turns to the viewer, or as a scene label the viewer typesets;
//! a formula that does not parse refused with the parameter named.

mod support;

use framework::PluginConfig;
use framework::config::Param;
use glam::{Affine3A, Quat, Vec3};
use support::harness;

fn config(text: &str) -> PluginConfig {
    support::on_robot(
        "libpv3d_formula",
        "speed",
        "position2d:0",
        vec![Param::new("text", text), Param::new("offset", "0.5 0 1")],
    )
}

#[test]
fn the_formula_follows_its_robot_and_stays_north_up() {
    let mut h = harness();
    let robot = h.robot_at(2.0);
    let mut plugin = h.make(config(r"$v = \omega r$")).unwrap();
    plugin.run(&mut h.ctx());
    let node = plugin.node().unwrap();
    let picture = &h.scene.get(node).unwrap().geometry.images[0];
    assert!(picture.size.x > picture.size.y && picture.size.x > 0.1);
    assert_eq!(
        picture.facing,
        framework::scene::Facing::Viewer {
            pivot: glam::Vec2::ZERO
        },
        "turned to the viewer by the renderer"
    );
    let at = |h: &framework::testing::Harness| h.scene.world_transform(node);
    assert!((at(&h).transform_point3(Vec3::ZERO) - Vec3::new(2.5, 0.0, 1.0)).length() < 1e-5);

    // The robot drives to (4, 1) and turns: the formula goes along, unturned.
    h.scene.get_mut(robot).unwrap().transform =
        Affine3A::from_rotation_translation(Quat::from_rotation_z(1.0), Vec3::new(4.0, 1.0, 0.0));
    plugin.run(&mut h.ctx());
    let moved = at(&h);
    assert!((moved.transform_point3(Vec3::ZERO) - Vec3::new(4.5, 1.0, 1.0)).length() < 1e-5);
    assert!((moved.transform_vector3(Vec3::X) - Vec3::X).length() < 1e-5);
    assert!(
        !h.run_changes_scene(plugin.as_mut()),
        "a robot standing still moves nothing"
    );
}

#[test]
fn a_formula_that_does_not_parse_is_refused_by_name() {
    for text in [r"$\frac{1}{$", "no dollars", "$$"] {
        let error = harness()
            .make(config(text))
            .err()
            .unwrap_or_else(|| panic!("{text} is refused"));
        assert!(error.to_string().contains("text"), "{text}: {error}");
    }
}

#[test]
fn as_a_label_the_formula_is_scene_text_for_the_viewer_to_typeset() {
    let mut h = harness();
    h.robot_at(0.0);
    let mut config = config(r"$v = \omega r$");
    config.params.push(Param::new("style", "label"));
    config.params.push(Param::new("title", "$v$ of the robot"));
    let plugin = h.make(config.clone()).unwrap();
    let object = h.scene.get(plugin.node().unwrap()).unwrap();
    assert!(object.geometry.images.is_empty());
    assert_eq!(object.geometry.labels[0].text, r"$v = \omega r$");
    assert_eq!(plugin.title(), "$v$ of the robot");

    config.params.retain(|p| p.name != "style");
    config.params.push(Param::new("style", "poster"));
    let error = harness().make(config).err().expect("an unknown style");
    assert!(error.to_string().contains("style"), "{error}");
}
