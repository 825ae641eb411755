//! Which way billboards face for the camera drawing them: the world directions a billboard's
//! right and up run along. They are read off the view-projection matrix itself, so the main
//! view, the top view and every virtual camera turn billboards towards themselves with no
//! more said than the matrix they already draw with.

use glam::{Mat4, Vec3};

/// A camera's right leaning up or down more than this (its sine) is rolled too far to give a
/// horizontal: the billboard then simply faces the screen.
const LEVEL_ENOUGH: f32 = 0.1;

/// World directions of a billboard's columns (`right`) and rows (`up`), unit length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BillboardAxes {
    pub right: Vec3,
    pub up: Vec3,
}

impl BillboardAxes {
    /// The axes for a camera whose view-projection is `view_proj` (a symmetric perspective or
    /// orthographic projection times a rigid view, as all of ours are: then the matrix's first
    /// two rows point along the screen's right and up, and its last row is zero but for w
    /// exactly when the projection is orthographic).
    ///
    /// Perspective: upright, turned about the vertical to face the view — text stands like a
    /// sign and is read from any side. Orthographic (the top view): flat along the screen, so
    /// from above it lies on its back, north up, as readable as a map's legend.
    pub fn facing(view_proj: &Mat4) -> BillboardAxes {
        let screen_right = view_proj.row(0).truncate().normalize_or_zero();
        let screen_up = view_proj.row(1).truncate().normalize_or_zero();
        let perspective = view_proj.row(3).truncate().length_squared() > 1e-12;
        let level = Vec3::new(screen_right.x, screen_right.y, 0.0);
        if perspective && level.length() > LEVEL_ENOUGH {
            BillboardAxes {
                right: level.normalize(),
                up: Vec3::Z,
            }
        } else {
            BillboardAxes {
                right: screen_right,
                up: screen_up,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::{OrbitCamera, Projection};

    fn close(a: Vec3, b: Vec3) -> bool {
        a.distance(b) < 1e-4
    }

    #[test]
    fn in_the_top_view_a_billboard_lies_flat_north_up() {
        let camera = OrbitCamera::default();
        assert_eq!(camera.projection, Projection::Top);
        let axes = BillboardAxes::facing(&camera.view_projection(1.5));
        assert!(close(axes.right, Vec3::X), "{axes:?}");
        assert!(close(axes.up, Vec3::Y), "{axes:?}");
    }

    #[test]
    fn in_perspective_a_billboard_stands_up_and_turns_with_the_camera() {
        let mut camera = OrbitCamera {
            projection: Projection::Perspective,
            pitch: 1.2,
            ..OrbitCamera::default()
        };
        // Looking north, the screen's right is east.
        let axes = BillboardAxes::facing(&camera.view_projection(1.0));
        assert!(close(axes.right, Vec3::X), "{axes:?}");
        assert!(close(axes.up, Vec3::Z), "{axes:?}");
        // Looking west (yaw a quarter turn), the screen's right is north; the picture's front
        // (right × up) points back at the eye.
        camera.yaw = std::f32::consts::FRAC_PI_2;
        let axes = BillboardAxes::facing(&camera.view_projection(1.0));
        assert!(close(axes.right, Vec3::Y), "{axes:?}");
        let front = axes.right.cross(axes.up);
        let towards_eye = (camera.eye() - camera.centre).with_z(0.0).normalize();
        assert!(close(front, towards_eye), "{front} {towards_eye}");
    }
}
