//! A robot's body: a box of its size (or its OBJ skin fitted into that box), a nose showing
//! where it faces, its name, and a ring around it while it is the active (selected) robot.

use glam::Vec3;

use framework::scene::{Geometry, Rgba};
use framework::skin::{SkinMesh, fit_into};

/// Fills `g` (cleared first) with a body of `size` (length x, width y, height z): the skin
/// when there is one, else a box.
pub fn body_geometry(
    g: &mut Geometry,
    size: Vec3,
    color: Rgba,
    active: bool,
    name: &str,
    skin: Option<&SkinMesh>,
) {
    g.clear();
    match skin {
        Some(mesh) => fit_into(g, mesh, size, color),
        None => g.cuboid(Vec3::new(0.0, 0.0, size.z / 2.0), size, color),
    }
    // The nose: a bright triangle pointing forward (+x), on top of a box; a skin has a shape
    // of its own that need not be flat on top, so there it lies on the ground just ahead.
    let (l, w) = (size.x / 2.0, size.y / 2.0);
    let (tip, back, half_width, z) = match skin {
        None => (l, l * 0.2, w * 0.6, size.z + 0.005),
        Some(_) => (l + 0.12, l + 0.02, w * 0.3, 0.01),
    };
    g.triangle(
        Vec3::new(tip, 0.0, z),
        Vec3::new(back, half_width, z),
        Vec3::new(back, -half_width, z),
        Rgba::rgb(245, 245, 245),
    );
    if active {
        let radius = size.x.max(size.y) * 0.75;
        let ring: Vec<Vec3> = (0..32)
            .map(|i| {
                let a = i as f32 / 32.0 * std::f32::consts::TAU;
                Vec3::new(radius * a.cos(), radius * a.sin(), 0.02)
            })
            .collect();
        g.polygon_outline(&ring, Rgba::rgb(250, 200, 60));
    }
    g.label(Vec3::new(0.0, 0.0, size.z + 0.1), name, Rgba::WHITE);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_active_robot_gets_a_ring() {
        let mut g = Geometry::default();
        body_geometry(
            &mut g,
            Vec3::new(0.4, 0.3, 0.2),
            Rgba::WHITE,
            false,
            "r0",
            None,
        );
        assert!(g.lines.is_empty());
        assert_eq!(g.mesh.len(), 36);
        assert_eq!(g.labels[0].text, "r0");
        body_geometry(
            &mut g,
            Vec3::new(0.4, 0.3, 0.2),
            Rgba::WHITE,
            true,
            "r0",
            None,
        );
        assert_eq!(g.lines.len(), 64);
    }
}
