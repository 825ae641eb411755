//! Render to texture: the scene drawn through each virtual camera into an off-screen
//! framebuffer of the camera's size, read back and handed to the plugin that asked for it. The
//! same renderer that draws the main view draws these, so a virtual camera sees exactly what the
//! viewer shows, lit the same way.
//!
//! The caller's framebuffer, viewport and scissor are restored afterwards, so this can run
//! inside egui's paint callback just before the main view is drawn.

use eframe::glow::{self, HasContext};
use framework::scene::{PixelFormat, Pixels, VirtualView};
use glam::camera::rh::{proj::opengl, view::look_at_mat4};
use glam::{Affine3A, Mat4};

use super::batch::BatchedView;
use super::gl_error::GlError;
use super::gl_renderer::{RendererError, SceneRenderer};

/// RGBA, one byte a channel: what a read-back pixel takes.
const BYTES_PER_PIXEL: usize = 4;

/// The clip-space matrix of a camera at `camera_to_world`, looking along its x with z up;
/// the projection whose pixels [`VirtualView::pixel_of`] predicts.
pub fn view_projection(view: &VirtualView, camera_to_world: Affine3A) -> Mat4 {
    let eye = camera_to_world.transform_point3(glam::Vec3::ZERO);
    let forward = camera_to_world.transform_vector3(glam::Vec3::X);
    let up = camera_to_world.transform_vector3(glam::Vec3::Z);
    let projection = opengl::perspective(view.fov_y, view.aspect(), view.near, view.far);
    projection * look_at_mat4(eye, eye + forward, up)
}

/// A colour and depth target of one size.
struct Target {
    width: u32,
    height: u32,
    framebuffer: glow::Framebuffer,
    color: glow::Renderbuffer,
    depth: glow::Renderbuffer,
}

/// The off-screen targets of the virtual cameras, one per size in use, kept between frames.
#[derive(Default)]
pub struct ViewTargets {
    targets: Vec<Target>,
}

/// What the caller had bound, to be put back.
struct SavedState {
    framebuffer: Option<glow::Framebuffer>,
    viewport: [i32; 4],
    scissor: bool,
}

impl ViewTargets {
    pub fn new() -> ViewTargets {
        ViewTargets::default()
    }

    /// Draws the uploaded scene through every view and delivers each picture to its output.
    /// A view whose description is impossible is skipped with a warning, not drawn.
    pub fn render(
        &mut self,
        gl: &glow::Context,
        renderer: &SceneRenderer,
        views: &[BatchedView],
    ) -> Result<(), RendererError> {
        if views.is_empty() {
            return Ok(());
        }
        // SAFETY: the caller holds a current context; everything changed is restored below.
        let saved = unsafe { save(gl) };
        let result = self.render_all(gl, renderer, views);
        // SAFETY: as above; the saved framebuffer belongs to this context.
        unsafe { restore(gl, &saved) };
        result
    }

    fn render_all(
        &mut self,
        gl: &glow::Context,
        renderer: &SceneRenderer,
        views: &[BatchedView],
    ) -> Result<(), RendererError> {
        for batched in views {
            let view = &batched.view;
            if let Err(e) = view.validate() {
                tracing::warn!("virtual camera not drawn: {e}");
                continue;
            }
            let target = self.target(gl, view.width, view.height)?;
            let mut bytes = vec![0u8; view.width as usize * view.height as usize * BYTES_PER_PIXEL];
            // SAFETY: the target belongs to this context; `bytes` holds exactly its pixels.
            unsafe {
                gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.framebuffer));
                gl.viewport(0, 0, view.width as i32, view.height as i32);
                gl.disable(glow::SCISSOR_TEST);
                renderer.draw_every_pixel(gl, view_projection(view, batched.camera_to_world));
                gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
                gl.read_pixels(
                    0,
                    0,
                    view.width as i32,
                    view.height as i32,
                    glow::RGBA,
                    glow::UNSIGNED_BYTE,
                    glow::PixelPackData::Slice(Some(&mut bytes)),
                );
            }
            // GL reads rows bottom-up, the order pictures keep.
            match Pixels::new(view.width, view.height, PixelFormat::Rgba8, bytes) {
                Ok(pixels) => view.output.deliver(pixels),
                Err(e) => tracing::warn!("virtual camera picture refused: {e}"),
            }
        }
        Ok(())
    }

    /// The target of this size, made on first use.
    fn target(
        &mut self,
        gl: &glow::Context,
        width: u32,
        height: u32,
    ) -> Result<&Target, RendererError> {
        let found = self
            .targets
            .iter()
            .position(|t| t.width == width && t.height == height);
        let index = match found {
            Some(index) => index,
            None => {
                // SAFETY: the caller holds a current context.
                let target = unsafe { create_target(gl, width, height)? };
                self.targets.push(target);
                self.targets.len() - 1
            }
        };
        Ok(&self.targets[index])
    }

    /// Frees the GL objects.
    pub fn destroy(&mut self, gl: &glow::Context) {
        for t in self.targets.drain(..) {
            // SAFETY: the objects belong to this context and are not used afterwards.
            unsafe {
                gl.delete_framebuffer(t.framebuffer);
                gl.delete_renderbuffer(t.color);
                gl.delete_renderbuffer(t.depth);
            }
        }
    }
}

unsafe fn save(gl: &glow::Context) -> SavedState {
    let mut viewport = [0i32; 4];
    // SAFETY: the caller holds a current context.
    unsafe {
        gl.get_parameter_i32_slice(glow::VIEWPORT, &mut viewport);
        SavedState {
            framebuffer: gl.get_parameter_framebuffer(glow::DRAW_FRAMEBUFFER_BINDING),
            viewport,
            scissor: gl.is_enabled(glow::SCISSOR_TEST),
        }
    }
}

unsafe fn restore(gl: &glow::Context, saved: &SavedState) {
    // SAFETY: the caller holds a current context.
    unsafe {
        gl.bind_framebuffer(glow::FRAMEBUFFER, saved.framebuffer);
        let [x, y, w, h] = saved.viewport;
        gl.viewport(x, y, w, h);
        if saved.scissor {
            gl.enable(glow::SCISSOR_TEST);
        } else {
            gl.disable(glow::SCISSOR_TEST);
        }
    }
}

unsafe fn create_target(
    gl: &glow::Context,
    width: u32,
    height: u32,
) -> Result<Target, RendererError> {
    // SAFETY: the caller holds a current context; sizes were validated as 1..=MAX_IMAGE_SIDE.
    unsafe {
        let framebuffer = gl.create_framebuffer().map_err(GlError::from)?;
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(framebuffer));
        let storage = |format: u32, attachment: u32| -> Result<_, RendererError> {
            let buffer = gl.create_renderbuffer().map_err(GlError::from)?;
            gl.bind_renderbuffer(glow::RENDERBUFFER, Some(buffer));
            gl.renderbuffer_storage(glow::RENDERBUFFER, format, width as i32, height as i32);
            gl.framebuffer_renderbuffer(
                glow::FRAMEBUFFER,
                attachment,
                glow::RENDERBUFFER,
                Some(buffer),
            );
            Ok(buffer)
        };
        let color = storage(glow::RGBA8, glow::COLOR_ATTACHMENT0)?;
        let depth = storage(glow::DEPTH_COMPONENT24, glow::DEPTH_ATTACHMENT)?;
        gl.bind_renderbuffer(glow::RENDERBUFFER, None);
        let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
        if status != glow::FRAMEBUFFER_COMPLETE {
            gl.delete_framebuffer(framebuffer);
            gl.delete_renderbuffer(color);
            gl.delete_renderbuffer(depth);
            return Err(RendererError(GlError::Incomplete {
                what: "virtual camera target",
                width,
                height,
                status,
            }));
        }
        Ok(Target {
            width,
            height,
            framebuffer,
            color,
            depth,
        })
    }
}
