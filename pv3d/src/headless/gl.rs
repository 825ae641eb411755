//! An OpenGL context with no window and no X server: Mesa's EGL device, a surfaceless context,
//! and a framebuffer object we draw into and read back. Used for `--screenshot` and the tests;
//! the pixels are the same as the window's because the same UI and renderer draw them.

use std::sync::Arc;

use eframe::glow::{self, HasContext};
use glutin::api::egl::{context::PossiblyCurrentContext, device::Device, display::Display};
use glutin::config::{Api, ConfigSurfaceTypes, ConfigTemplateBuilder};
use glutin::context::{ContextApi, ContextAttributesBuilder, Version};
use glutin::display::GlDisplay;
use image::RgbaImage;

/// Why no headless context could be made.
#[derive(Debug, thiserror::Error)]
pub enum HeadlessError {
    #[error("no EGL device found (install libegl1, libegl-mesa0 and libgl1-mesa-dri): {0}")]
    NoDevice(String),
    #[error("EGL setup failed: {0}")]
    Egl(String),
    #[error("framebuffer setup failed: {0}")]
    Framebuffer(String),
}

/// A current GL context drawing into an offscreen colour + depth framebuffer.
pub struct HeadlessGl {
    pub gl: Arc<glow::Context>,
    width: u32,
    height: u32,
    framebuffer: glow::Framebuffer,
    renderbuffers: [glow::Renderbuffer; 2],
    // Kept alive for as long as `gl` is used.
    _context: PossiblyCurrentContext,
    _display: Display,
}

impl HeadlessGl {
    /// Creates the context and a `width`×`height` framebuffer, bound for drawing.
    pub fn new(width: u32, height: u32) -> Result<HeadlessGl, HeadlessError> {
        let devices: Vec<Device> = Device::query_devices()
            .map_err(|e| HeadlessError::NoDevice(e.to_string()))?
            .collect();
        // Prefer Mesa's software device: it exists everywhere and renders identically.
        let device = devices
            .iter()
            .find(|d| d.extensions().contains("EGL_MESA_device_software"))
            .or_else(|| devices.first())
            .ok_or_else(|| HeadlessError::NoDevice("the EGL driver lists no devices".into()))?;
        // SAFETY: no native display handle is passed.
        let display = unsafe { Display::with_device(device, None) }
            .map_err(|e| HeadlessError::Egl(format!("display: {e}")))?;
        let template = ConfigTemplateBuilder::new()
            .with_surface_type(ConfigSurfaceTypes::empty())
            .with_api(Api::OPENGL)
            .build();
        // SAFETY: the display is valid.
        let config = unsafe { display.find_configs(template) }
            .map_err(|e| HeadlessError::Egl(format!("configs: {e}")))?
            .next()
            .ok_or_else(|| HeadlessError::Egl("no surfaceless OpenGL config".into()))?;
        let attributes = ContextAttributesBuilder::new()
            .with_context_api(ContextApi::OpenGl(Some(Version::new(3, 3))))
            .build(None);
        // SAFETY: config comes from this display.
        let context = unsafe { display.create_context(&config, &attributes) }
            .map_err(|e| HeadlessError::Egl(format!("context: {e}")))?
            .make_current_surfaceless()
            .map_err(|e| HeadlessError::Egl(format!("make current: {e}")))?;
        // SAFETY: the context is current on this thread.
        let gl = unsafe {
            glow::Context::from_loader_function_cstr(|name| display.get_proc_address(name))
        };
        let (framebuffer, renderbuffers) = create_framebuffer(&gl, width, height)?;
        Ok(HeadlessGl {
            gl: Arc::new(gl),
            width,
            height,
            framebuffer,
            renderbuffers,
            _context: context,
            _display: display,
        })
    }

    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// Binds the offscreen framebuffer and sets the viewport to all of it.
    pub fn bind(&self) {
        // SAFETY: the framebuffer belongs to this current context.
        unsafe {
            self.gl
                .bind_framebuffer(glow::FRAMEBUFFER, Some(self.framebuffer));
            self.gl
                .viewport(0, 0, self.width as i32, self.height as i32);
        }
    }

    /// Reads the framebuffer back, top row first.
    pub fn read_pixels(&self) -> RgbaImage {
        let (w, h) = (self.width, self.height);
        let mut pixels = vec![0u8; (w * h * 4) as usize];
        // SAFETY: the buffer holds exactly w*h RGBA pixels.
        unsafe {
            self.gl
                .bind_framebuffer(glow::READ_FRAMEBUFFER, Some(self.framebuffer));
            self.gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            self.gl.read_pixels(
                0,
                0,
                w as i32,
                h as i32,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                glow::PixelPackData::Slice(Some(&mut pixels)),
            );
        }
        // GL's rows go bottom-up.
        let row = (w * 4) as usize;
        let mut flipped = Vec::with_capacity(pixels.len());
        for y in (0..h as usize).rev() {
            flipped.extend_from_slice(&pixels[y * row..(y + 1) * row]);
        }
        RgbaImage::from_raw(w, h, flipped).expect("exact size")
    }
}

impl Drop for HeadlessGl {
    fn drop(&mut self) {
        // SAFETY: the objects belong to this context, which is still current.
        unsafe {
            self.gl.delete_framebuffer(self.framebuffer);
            for rb in self.renderbuffers {
                self.gl.delete_renderbuffer(rb);
            }
        }
    }
}

fn create_framebuffer(
    gl: &glow::Context,
    width: u32,
    height: u32,
) -> Result<(glow::Framebuffer, [glow::Renderbuffer; 2]), HeadlessError> {
    // SAFETY: the context is current; sizes are positive.
    unsafe {
        let framebuffer = gl
            .create_framebuffer()
            .map_err(HeadlessError::Framebuffer)?;
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(framebuffer));
        let color = gl
            .create_renderbuffer()
            .map_err(HeadlessError::Framebuffer)?;
        gl.bind_renderbuffer(glow::RENDERBUFFER, Some(color));
        gl.renderbuffer_storage(glow::RENDERBUFFER, glow::RGBA8, width as i32, height as i32);
        gl.framebuffer_renderbuffer(
            glow::FRAMEBUFFER,
            glow::COLOR_ATTACHMENT0,
            glow::RENDERBUFFER,
            Some(color),
        );
        let depth = gl
            .create_renderbuffer()
            .map_err(HeadlessError::Framebuffer)?;
        gl.bind_renderbuffer(glow::RENDERBUFFER, Some(depth));
        gl.renderbuffer_storage(
            glow::RENDERBUFFER,
            glow::DEPTH_COMPONENT24,
            width as i32,
            height as i32,
        );
        gl.framebuffer_renderbuffer(
            glow::FRAMEBUFFER,
            glow::DEPTH_ATTACHMENT,
            glow::RENDERBUFFER,
            Some(depth),
        );
        let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
        if status != glow::FRAMEBUFFER_COMPLETE {
            return Err(HeadlessError::Framebuffer(format!(
                "incomplete (status 0x{status:x})"
            )));
        }
        gl.viewport(0, 0, width as i32, height as i32);
        Ok((framebuffer, [color, depth]))
    }
}
