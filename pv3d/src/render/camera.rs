//! The world camera: a top orthographic view and a perspective view that share one centre,
//! so a person can pan in the map-like top view, switch, and orbit around the same point.

use glam::camera::rh::{proj::opengl, view::look_at_mat4};
use glam::{Mat4, Vec2, Vec3, Vec4};

/// Which projection the camera uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Projection {
    /// Looking straight down, north (+y) up: a map.
    Top,
    /// Orbiting the centre at `yaw` and `pitch`.
    Perspective,
}

/// An orbit camera. World frame: x east, y north, z up, metres.
#[derive(Debug, Clone, PartialEq)]
pub struct OrbitCamera {
    pub centre: Vec3,
    /// Distance from the centre (perspective); the top view shows the same extent.
    pub distance: f32,
    /// Radians about +z, 0 = looking north.
    pub yaw: f32,
    /// Radians above the ground plane, in (0, π/2).
    pub pitch: f32,
    pub projection: Projection,
    /// Vertical field of view of the perspective view, radians.
    pub fov_y: f32,
}

impl Default for OrbitCamera {
    fn default() -> Self {
        OrbitCamera {
            centre: Vec3::ZERO,
            distance: 16.0,
            yaw: 0.0,
            pitch: 0.9,
            projection: Projection::Top,
            fov_y: 45f32.to_radians(),
        }
    }
}

const MIN_DISTANCE: f32 = 0.2;
const MAX_DISTANCE: f32 = 2000.0;

impl OrbitCamera {
    /// Half the visible height at the centre: the same in both projections, so switching keeps
    /// the scale.
    fn half_height(&self) -> f32 {
        self.distance * (self.fov_y / 2.0).tan()
    }

    fn eye_offset(&self) -> Vec3 {
        let (sp, cp) = self.pitch.sin_cos();
        let (sy, cy) = self.yaw.sin_cos();
        // Behind the centre relative to the view direction (yaw 0 looks north).
        Vec3::new(sy * cp, -cy * cp, sp) * self.distance
    }

    pub fn eye(&self) -> Vec3 {
        match self.projection {
            Projection::Top => self.centre + Vec3::Z * self.distance,
            Projection::Perspective => self.centre + self.eye_offset(),
        }
    }

    pub fn view(&self) -> Mat4 {
        match self.projection {
            Projection::Top => look_at_mat4(self.eye(), self.centre, Vec3::Y),
            Projection::Perspective => look_at_mat4(self.eye(), self.centre, Vec3::Z),
        }
    }

    pub fn projection_matrix(&self, aspect: f32) -> Mat4 {
        let far = self.distance * 4.0 + 100.0;
        match self.projection {
            Projection::Top => {
                let h = self.half_height();
                opengl::orthographic(-h * aspect, h * aspect, -h, h, 0.01, far)
            }
            Projection::Perspective => opengl::perspective(self.fov_y, aspect, 0.05, far),
        }
    }

    pub fn view_projection(&self, aspect: f32) -> Mat4 {
        self.projection_matrix(aspect) * self.view()
    }

    /// Moves the centre so the ground follows the pointer: `delta` in pixels of a view
    /// `size` pixels big.
    pub fn pan_pixels(&mut self, delta: Vec2, size: Vec2) {
        let metres_per_pixel = 2.0 * self.half_height() / size.y.max(1.0);
        let (right, up) = match self.projection {
            Projection::Top => (Vec3::X, Vec3::Y),
            Projection::Perspective => {
                let (sy, cy) = self.yaw.sin_cos();
                (Vec3::new(cy, sy, 0.0), Vec3::new(-sy, cy, 0.0))
            }
        };
        self.centre += (-right * delta.x + up * delta.y) * metres_per_pixel;
    }

    /// Turns around the centre (perspective view).
    pub fn orbit(&mut self, d_yaw: f32, d_pitch: f32) {
        self.yaw = (self.yaw + d_yaw).rem_euclid(std::f32::consts::TAU);
        self.pitch = (self.pitch + d_pitch).clamp(0.05, std::f32::consts::FRAC_PI_2 - 0.01);
    }

    /// Multiplies the distance (`factor` < 1 zooms in).
    pub fn zoom(&mut self, factor: f32) {
        self.distance = (self.distance * factor).clamp(MIN_DISTANCE, MAX_DISTANCE);
    }

    pub fn toggle_projection(&mut self) {
        self.projection = match self.projection {
            Projection::Top => Projection::Perspective,
            Projection::Perspective => Projection::Top,
        };
    }

    /// The world-space ray under a point given in normalised device coordinates (-1..1, y up).
    pub fn ray(&self, ndc: Vec2, aspect: f32) -> (Vec3, Vec3) {
        let inverse = self.view_projection(aspect).inverse();
        let near = inverse * Vec4::new(ndc.x, ndc.y, -1.0, 1.0);
        let far = inverse * Vec4::new(ndc.x, ndc.y, 1.0, 1.0);
        let near = near.truncate() / near.w;
        let far = far.truncate() / far.w;
        (near, (far - near).normalize())
    }

    /// Where that ray meets the ground plane z = `height`.
    pub fn ground_point(&self, ndc: Vec2, aspect: f32, height: f32) -> Option<Vec3> {
        let (origin, dir) = self.ray(ndc, aspect);
        if dir.z.abs() < 1e-6 {
            return None;
        }
        let t = (height - origin.z) / dir.z;
        (t > 0.0).then(|| origin + dir * t)
    }

    /// Pixel position of a world point in a view of `size` pixels (origin top-left), or
    /// `None` when it is behind the camera.
    pub fn to_screen(&self, world: Vec3, size: Vec2) -> Option<Vec2> {
        let clip = self.view_projection(size.x / size.y.max(1.0)) * world.extend(1.0);
        if clip.w <= 0.0 {
            return None;
        }
        let ndc = clip.truncate() / clip.w;
        Some(Vec2::new(
            (ndc.x + 1.0) / 2.0 * size.x,
            (1.0 - ndc.y) / 2.0 * size.y,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_centre_is_under_the_middle_of_the_view_in_both_projections() {
        let mut camera = OrbitCamera {
            centre: Vec3::new(3.0, -2.0, 0.0),
            ..OrbitCamera::default()
        };
        for _ in 0..2 {
            let hit = camera.ground_point(Vec2::ZERO, 1.5, 0.0).unwrap();
            assert!(
                (hit - camera.centre).length() < 1e-3,
                "{:?}: {hit}",
                camera.projection
            );
            camera.toggle_projection();
        }
    }

    #[test]
    fn top_view_is_north_up_and_pans_with_the_pointer() {
        let mut camera = OrbitCamera::default();
        let size = Vec2::new(800.0, 600.0);
        let north = camera.to_screen(Vec3::new(0.0, 5.0, 0.0), size).unwrap();
        let east = camera.to_screen(Vec3::new(5.0, 0.0, 0.0), size).unwrap();
        assert!(north.y < 300.0 && (north.x - 400.0).abs() < 1e-3);
        assert!(east.x > 400.0 && (east.y - 300.0).abs() < 1e-3);

        let before = camera.to_screen(Vec3::new(1.0, 1.0, 0.0), size).unwrap();
        camera.pan_pixels(Vec2::new(40.0, -25.0), size);
        let after = camera.to_screen(Vec3::new(1.0, 1.0, 0.0), size).unwrap();
        assert!(
            (after - before - Vec2::new(40.0, -25.0)).length() < 1e-2,
            "{before} {after}"
        );
    }
}
