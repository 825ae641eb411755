//! The lines that show where a virtual camera looks: from its pinhole to the four corners of
//! its picture at a chosen distance, and the picture's rectangle there.

use framework::scene::{Geometry, Rgba, VirtualView};
use glam::{Vec2, Vec3};

/// The picture's corners at `distance` along the view axis, in the camera's frame,
/// counter-clockwise from the lower left (as the picture's rows count).
pub fn corners_at(view: &VirtualView, distance: f32) -> [Vec3; 4] {
    let (w, h) = (view.width as f32, view.height as f32);
    [
        Vec2::new(0.0, 0.0),
        Vec2::new(w, 0.0),
        Vec2::new(w, h),
        Vec2::new(0.0, h),
    ]
    .map(|pixel| {
        let ray = view.ray_through(pixel);
        ray * (distance / ray.x)
    })
}

/// Adds the frustum, `length` metres deep, to `geometry`.
pub fn draw_frustum(geometry: &mut Geometry, view: &VirtualView, length: f32, colour: Rgba) {
    let corners = corners_at(view, length);
    for (k, &corner) in corners.iter().enumerate() {
        geometry.line(Vec3::ZERO, corner, colour);
        geometry.line(corner, corners[(k + 1) % corners.len()], colour);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Affine3A;

    #[test]
    fn the_corners_lie_on_the_edges_of_the_picture() {
        let view = VirtualView::new(Affine3A::IDENTITY, 1.0, 64, 48).unwrap();
        let corners = corners_at(&view, 2.0);
        for c in corners {
            assert!((c.x - 2.0).abs() < 1e-5);
        }
        let lower_left = view.pixel_of(Affine3A::IDENTITY, corners[0] * 0.999 + Vec3::X * 0.002);
        assert!(
            lower_left.is_some_and(|p| p.x < 1.0 && p.y < 1.0),
            "{lower_left:?}"
        );
        assert!(
            corners[0].y > 0.0 && corners[0].z < 0.0,
            "lower left is left and down"
        );
        let mut geometry = Geometry::default();
        draw_frustum(&mut geometry, &view, 2.0, Rgba::WHITE);
        assert_eq!(
            geometry.lines.len(),
            16,
            "four rays and four edges, two vertices each"
        );
    }
}
