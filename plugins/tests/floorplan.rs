//! Walls stand where a floorplan bitmap's dark pixels are.

use std::path::Path;

use pv3d_plugins::ground::{Placement, walls_from_bitmap};
use pv3d_plugins::scene::{Geometry, Rgba};

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
