//! Drawing a skin into a body's box.

use glam::Vec3;

use super::SkinMesh;
use crate::scene::{Geometry, MeshVertex, Rgba};

/// Adds `mesh` to `g`, stretched to fill a box of `size` (length x, width y, height z) centred
/// on the origin in x and y and standing on z = 0, lit by face normals, in `color`.
pub fn fit_into(g: &mut Geometry, mesh: &SkinMesh, size: Vec3, color: Rgba) {
    let extent = (mesh.max - mesh.min).max(Vec3::splat(1e-6));
    let centre = (mesh.min + mesh.max) / 2.0;
    let scale = size / extent;
    // A flat model (no height, say) keeps that axis flat instead of exploding it.
    let scale = Vec3::select(
        (mesh.max - mesh.min).cmpgt(Vec3::splat(1e-6)),
        scale,
        Vec3::ZERO,
    );
    let place = |p: Vec3| {
        let q = (p - centre) * scale;
        Vec3::new(q.x, q.y, q.z + size.z / 2.0)
    };
    g.mesh.reserve(mesh.triangles.len() * 3);
    for [a, b, c] in &mesh.triangles {
        let (a, b, c) = (place(*a), place(*b), place(*c));
        let normal = (b - a).cross(c - a).normalize_or_zero();
        if normal == Vec3::ZERO {
            continue; // degenerate, nothing to see
        }
        for pos in [a, b, c] {
            g.mesh.push(MeshVertex { pos, normal, color });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_model_is_stretched_into_the_box_and_stands_on_the_ground() {
        let mesh = SkinMesh {
            path: "t.obj".into(),
            triangles: vec![
                [
                    Vec3::new(-10.0, -5.0, 0.0),
                    Vec3::new(10.0, -5.0, 0.0),
                    Vec3::new(10.0, 5.0, 4.0),
                ],
                // Degenerate: dropped.
                [Vec3::ZERO, Vec3::ZERO, Vec3::ZERO],
            ],
            min: Vec3::new(-10.0, -5.0, 0.0),
            max: Vec3::new(10.0, 5.0, 4.0),
        };
        let mut g = Geometry::default();
        fit_into(&mut g, &mesh, Vec3::new(0.4, 0.2, 0.1), Rgba::WHITE);
        assert_eq!(g.mesh.len(), 3);
        let lo = g.mesh.iter().fold(Vec3::MAX, |m, v| m.min(v.pos));
        let hi = g.mesh.iter().fold(Vec3::MIN, |m, v| m.max(v.pos));
        assert!((lo - Vec3::new(-0.2, -0.1, 0.0)).length() < 1e-6, "{lo}");
        assert!((hi - Vec3::new(0.2, 0.1, 0.1)).length() < 1e-6, "{hi}");
        assert!(
            g.mesh[0].normal.z > 0.0,
            "counter-clockwise seen from above faces up"
        );
    }
}
