//! Walls stand where a floorplan bitmap's dark pixels are.

mod support;

use std::path::Path;

use framework::scene::{Geometry, Rgba};
use plugins::ground::{Placement, walls_from_bitmap};
use support::harness;

#[test]
fn the_arena_bitmap_becomes_walls_in_place() {
    let bitmap = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stage-worlds/bitmaps/arena.png");
    let mut g = Geometry::default();
    let placement = Placement {
        size: (20.0, 16.0),
        centre: (0.0, 0.0),
        wall_height: 0.5,
    };
    let boxes = walls_from_bitmap(&bitmap, placement, Rgba::WHITE, &mut g).unwrap();
    assert!(boxes > 100, "{boxes}");
    assert_eq!(g.mesh.len(), boxes * 36);
    // The inner wall of pixel columns 70-71 lies at x = -3.0 .. -2.8 m.
    let near_inner_wall = g
        .mesh
        .iter()
        .any(|v| (v.pos.x + 3.0).abs() < 1e-4 && v.pos.y > 2.0);
    assert!(near_inner_wall);
    let xs = g.mesh.iter().map(|v| v.pos.x);
    let (lo, hi) = xs.fold((f32::MAX, f32::MIN), |(lo, hi), x| (lo.min(x), hi.max(x)));
    assert!(
        (lo + 10.0).abs() < 1e-4 && (hi - 10.0).abs() < 1e-4,
        "{lo} {hi}"
    );
    assert!(
        walls_from_bitmap(
            Path::new("/nonexistent.png"),
            placement,
            Rgba::WHITE,
            &mut g
        )
        .is_err()
    );
}

#[test]
fn block_walls_stand_up_and_bad_ones_say_where() {
    use framework::config::{Param, PluginConfig};

    let wall = |text: &str| {
        let mut p = Param::new("wall", text);
        p.origin = "blocks.xml:7:5".into();
        p
    };
    let config = |params: Vec<Param>| PluginConfig {
        library: "libpv3d_ground".into(),
        params,
        origin: "blocks.xml:3:3".into(),
        ..PluginConfig::default()
    };
    let mut h = harness();
    // An L-shaped partition: six walls and a four-triangle top.
    h.make(config(vec![
        wall("0 0  2 0  2 0.2  0.2 0.2  0.2 2  0 2"),
        Param::new("wallHeight", "0.8"),
    ]))
    .unwrap();
    let (_, ground) = h.scene.iter().next().unwrap();
    assert_eq!(ground.geometry.mesh.len(), 6 * 6 + 4 * 3);
    let top = ground
        .geometry
        .mesh
        .iter()
        .map(|v| v.pos.z)
        .fold(0.0, f32::max);
    assert!((top - 0.8).abs() < 1e-6, "wallHeight: {top}");

    let err = h
        .make(config(vec![wall("0 0 1")]))
        .err()
        .unwrap()
        .to_string();
    assert!(err.starts_with("blocks.xml:7:5"), "{err}");
    assert!(err.contains("three corners"), "{err}");
}
