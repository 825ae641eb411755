//! Zones: drawn where the composition says, and aware of which robot is in which.

use std::time::Instant;

use framework::config::{Param, PluginConfig};
use framework::plugin::{Anchors, Plugin, PluginContext};
use framework::scene::{NodeId, Object3D, Scene};
use glam::{Affine3A, Vec3};
use plugins::standard_plugins;
use plugins::zones::ZonesPlugin;

/// An L-shaped dock: 2 × 2 m with its top-right metre missing.
const L_DOCK: &str = "0 0  2 0  2 1  1 1  1 2  0 2";

fn zone(name: &str, corners: &str) -> Param {
    let mut p = Param::new("zone", corners);
    p.attributes = vec![("name".into(), name.into())];
    p.origin = format!("classroom.xml:{}:3", name.len());
    p
}

fn config(params: Vec<Param>) -> PluginConfig {
    PluginConfig {
        library: "libpv3d_zones".into(),
        id: "zones".into(),
        params,
        origin: "classroom.xml:1:1".into(),
        ..PluginConfig::default()
    }
}

fn robot(scene: &mut Scene, name: &str, x: f32, y: f32) -> NodeId {
    let mut body = Object3D::new(name);
    body.tags = vec!["robot".into()];
    body.transform = Affine3A::from_translation(Vec3::new(x, y, 0.0));
    scene.add(body)
}

#[test]
fn robots_entering_and_leaving_a_zone_are_noticed() {
    let mut scene = Scene::new();
    let mut anchors = Anchors::default();
    let r1 = robot(&mut scene, "robot1", 0.5, 0.5);
    robot(&mut scene, "robot2", 5.0, 5.0);
    let create = standard_plugins().constructor("libpv3d_zones").unwrap();
    let mut ctx = PluginContext::new(&mut scene, &mut anchors, Instant::now());
    let mut plugin = create(config(vec![zone("dock", L_DOCK)]), &mut ctx).unwrap();
    let drawn = ctx
        .scene
        .iter()
        .find(|(_, o)| o.has_tag("zone:dock"))
        .map(|(_, o)| o.clone())
        .expect("a tagged zone object");
    assert_eq!(
        drawn.geometry.triangles.len(),
        4 * 3,
        "the L in four triangles"
    );
    assert_eq!(drawn.geometry.lines.len(), 6 * 2, "its six edges");
    assert!(
        drawn.geometry.triangles.iter().all(|v| v.color.0[3] < 255),
        "translucent"
    );

    let before = ctx.scene.generation();
    plugin.run(&mut ctx);
    assert_eq!(
        ctx.scene.generation(),
        before,
        "watching robots changes nothing in the scene"
    );
    plugin.clean(&mut ctx);
    assert!(
        !ctx.scene.iter().any(|(_, o)| o.has_tag("zone")),
        "clean removes the zones"
    );

    let mut zones = ZonesPlugin::new(config(vec![zone("dock", L_DOCK)]), &mut ctx).unwrap();
    zones.run(&mut ctx);
    assert_eq!(zones.robots_in("dock"), ["robot1"]);
    ctx.scene.get_mut(r1).unwrap().transform = Affine3A::from_translation(Vec3::new(1.5, 1.5, 0.0));
    zones.run(&mut ctx);
    assert!(
        zones.robots_in("dock").is_empty(),
        "the L's missing corner is outside"
    );
    let events: Vec<&str> = zones.events().collect();
    assert_eq!(events, ["robot1 entered dock", "robot1 left dock"]);
}

#[test]
fn a_bad_zone_says_where_and_why() {
    let mut scene = Scene::new();
    let mut anchors = Anchors::default();
    let mut ctx = PluginContext::new(&mut scene, &mut anchors, Instant::now());
    let cases = [
        (zone("dock", "0 0 1 1"), "three corners or more"),
        (zone("dock", "0 0 1 x 2 2"), "must be numbers"),
        (zone("", "0 0 1 0 1 1"), "needs a name"),
    ];
    for (param, expected) in cases {
        let origin = param.origin.clone();
        let err = ZonesPlugin::new(config(vec![param]), &mut ctx)
            .err()
            .unwrap()
            .to_string();
        assert!(err.starts_with(&origin), "{err}");
        assert!(err.contains(expected), "{err}");
    }
}
