//! A camera inside the simulated world: a plugin puts a [`VirtualView`] on a node (a robot, or
//! a fixed post) and the viewer renders the scene as that camera would see it, off screen,
//! handing the pixels back through the view's [`ViewOutput`] for the plugin to read on its next
//! frame. Plugins describe the camera; only the viewer knows how it is drawn.
//!
//! The camera looks along its node's +x with +z up, as a robot's sensors do in Player, so a view
//! on a robot's node sees what lies ahead of the robot.

use std::sync::{Arc, Mutex, PoisonError};

use glam::{Affine3A, Vec2, Vec3};

use super::image::{MAX_IMAGE_SIDE, Pixels};

/// Nearest distance drawn by default, m: closer than a robot's own body would be.
pub const DEFAULT_NEAR: f32 = 0.05;
/// Farthest distance drawn by default, m: the far side of a large Stage world.
pub const DEFAULT_FAR: f32 = 100.0;

/// Why a view's description cannot be rendered.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ViewError {
    #[error("a {width}×{height} view must be 1 to {MAX_IMAGE_SIDE} pixels on a side")]
    BadSize { width: u32, height: u32 },
    #[error("a field of view of {degrees}° is not between 0° and 180°")]
    BadFieldOfView { degrees: f32 },
    #[error("near {near} m and far {far} m must satisfy 0 < near < far")]
    BadDepthRange { near: f32, far: f32 },
}

/// Where the viewer leaves the last rendered picture of a view. The plugin keeps one clone and
/// the scene another; two outputs are equal when they are the same mailbox.
#[derive(Debug, Clone, Default)]
pub struct ViewOutput(Arc<Mutex<Option<Pixels>>>);

impl ViewOutput {
    pub fn new() -> ViewOutput {
        ViewOutput::default()
    }

    /// The viewer's side: replaces the picture with a newer one.
    pub fn deliver(&self, pixels: Pixels) {
        *self.0.lock().unwrap_or_else(PoisonError::into_inner) = Some(pixels);
    }

    /// The plugin's side: the latest picture, if any was rendered yet. Rows run bottom-up.
    pub fn latest(&self) -> Option<Pixels> {
        self.0
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .clone()
    }
}

impl PartialEq for ViewOutput {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

/// A pinhole camera the viewer renders the scene through, in its node's frame.
#[derive(Debug, Clone, PartialEq)]
pub struct VirtualView {
    /// The camera's pose relative to its node: looking along x, z up.
    pub pose: Affine3A,
    /// Vertical field of view, radians.
    pub fov_y: f32,
    pub width: u32,
    pub height: u32,
    pub near: f32,
    pub far: f32,
    pub output: ViewOutput,
}

impl VirtualView {
    /// A `width` × `height` camera at `pose` with a vertical field of view `fov_y` (radians),
    /// drawing from [`DEFAULT_NEAR`] to [`DEFAULT_FAR`]; checked so the viewer never meets a
    /// camera it cannot draw.
    pub fn new(pose: Affine3A, fov_y: f32, width: u32, height: u32) -> Result<Self, ViewError> {
        let view = VirtualView {
            pose,
            fov_y,
            width,
            height,
            near: DEFAULT_NEAR,
            far: DEFAULT_FAR,
            output: ViewOutput::new(),
        };
        view.validate()?;
        Ok(view)
    }

    /// Checks size, field of view and depth range.
    pub fn validate(&self) -> Result<(), ViewError> {
        let side_ok = |s: u32| (1..=MAX_IMAGE_SIDE).contains(&s);
        if !side_ok(self.width) || !side_ok(self.height) {
            return Err(ViewError::BadSize {
                width: self.width,
                height: self.height,
            });
        }
        if !(self.fov_y > 0.0 && self.fov_y < std::f32::consts::PI) {
            return Err(ViewError::BadFieldOfView {
                degrees: self.fov_y.to_degrees(),
            });
        }
        if !(self.near > 0.0 && self.near < self.far && self.far.is_finite()) {
            return Err(ViewError::BadDepthRange {
                near: self.near,
                far: self.far,
            });
        }
        Ok(())
    }

    pub fn aspect(&self) -> f32 {
        self.width as f32 / self.height as f32
    }

    /// Focal length in pixels: how far from the image a pinhole sits for this field of view.
    pub fn focal_px(&self) -> f32 {
        self.height as f32 / 2.0 / (self.fov_y / 2.0).tan()
    }

    /// Where a world point lands in the picture, in pixels from the lower-left corner (the
    /// picture's row 0), given the camera's world pose; `None` behind the camera or outside
    /// the picture. The intrinsics written out, for tests and for laying pictures on the world.
    pub fn pixel_of(&self, camera_to_world: Affine3A, world: Vec3) -> Option<Vec2> {
        let local = camera_to_world.inverse().transform_point3(world);
        let depth = local.x;
        if depth < self.near || depth > self.far {
            return None;
        }
        let f = self.focal_px();
        let pixel = Vec2::new(
            self.width as f32 / 2.0 - f * local.y / depth,
            self.height as f32 / 2.0 + f * local.z / depth,
        );
        let inside = (0.0..self.width as f32).contains(&pixel.x)
            && (0.0..self.height as f32).contains(&pixel.y);
        inside.then_some(pixel)
    }

    /// The direction, in the camera's frame, through a picture point (pixels from the lower
    /// left): the inverse of [`VirtualView::pixel_of`] up to distance.
    pub fn ray_through(&self, pixel: Vec2) -> Vec3 {
        let f = self.focal_px();
        Vec3::new(
            f,
            self.width as f32 / 2.0 - pixel.x,
            pixel.y - self.height as f32 / 2.0,
        )
        .normalize()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> VirtualView {
        VirtualView::new(Affine3A::IDENTITY, 90f32.to_radians(), 200, 100).unwrap()
    }

    #[test]
    fn a_point_ahead_lands_in_the_middle_and_left_is_left() {
        let view = camera();
        let centre = view.pixel_of(Affine3A::IDENTITY, Vec3::new(3.0, 0.0, 0.0));
        assert_eq!(centre, Some(Vec2::new(100.0, 50.0)));
        let left = view
            .pixel_of(Affine3A::IDENTITY, Vec3::new(3.0, 1.0, 0.0))
            .unwrap();
        assert!(left.x < 100.0, "+y is the camera's left: {left}");
        let up = view
            .pixel_of(Affine3A::IDENTITY, Vec3::new(3.0, 0.0, 1.0))
            .unwrap();
        assert!(up.y > 50.0, "+z is up, rows count from the bottom: {up}");
        assert_eq!(
            view.pixel_of(Affine3A::IDENTITY, Vec3::new(-3.0, 0.0, 0.0)),
            None
        );
    }

    #[test]
    fn rays_and_pixels_agree() {
        let view = camera();
        let pixel = Vec2::new(30.0, 80.0);
        let point = view.ray_through(pixel) * 4.0;
        let back = view.pixel_of(Affine3A::IDENTITY, point).unwrap();
        assert!((back - pixel).length() < 1e-3, "{back}");
    }

    #[test]
    fn impossible_cameras_are_refused() {
        let pose = Affine3A::IDENTITY;
        assert!(matches!(
            VirtualView::new(pose, 1.0, 0, 10),
            Err(ViewError::BadSize { .. })
        ));
        assert!(matches!(
            VirtualView::new(pose, 4.0, 10, 10),
            Err(ViewError::BadFieldOfView { .. })
        ));
        let mut view = camera();
        view.near = 0.0;
        assert!(matches!(
            view.validate(),
            Err(ViewError::BadDepthRange { .. })
        ));
    }

    #[test]
    fn the_plugin_reads_what_the_viewer_delivers() {
        let view = camera();
        let plugin_side = view.output.clone();
        assert!(plugin_side.latest().is_none());
        let pixels = Pixels::new(1, 1, super::super::image::PixelFormat::Gray8, vec![9u8]).unwrap();
        view.output.deliver(pixels.clone());
        assert_eq!(plugin_side.latest(), Some(pixels));
        assert_eq!(view.clone().output, plugin_side);
        assert_ne!(ViewOutput::new(), plugin_side);
    }
}
