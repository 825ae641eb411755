//! Filtering pictures for plugins' windows: a camera frame goes through its chain on the GPU
//! (the same kernel passes as pictures in the world) and comes back as pixels, so the camera's
//! egui window shows the filtered frame without the plugin knowing any OpenGL. Each picture is
//! filtered once: a frame that has not changed is not filtered again.

use eframe::glow::{self, HasContext};
use framework::scene::{FilteredPicture, ImageError, PixelFormat, Pixels};

use super::gl_error::GlError;
use super::kernels::{KernelError, KernelRunner};
use super::texture::{self, GpuTexture, TextureError};

/// RGBA: what a filtered picture is read back as.
const BYTES_PER_PIXEL: usize = 4;

/// Why a window's picture was not filtered: which step failed.
#[derive(Debug, thiserror::Error)]
enum FilterError {
    #[error(transparent)]
    Gl(#[from] GlError),
    #[error("uploading the picture: {0}")]
    Upload(#[from] TextureError),
    #[error(transparent)]
    Kernel(#[from] KernelError),
    #[error("reading the filtered picture back: {0}")]
    ReadBack(#[from] ImageError),
}

/// The kernel runner for window pictures, and which pictures it has filtered.
#[derive(Default)]
pub struct PictureFilters {
    runner: Option<KernelRunner>,
    /// Generations of the pictures already filtered and delivered.
    done: Vec<u64>,
}

impl PictureFilters {
    pub fn new() -> PictureFilters {
        PictureFilters::default()
    }

    /// Filters every request not filtered yet and delivers the results; a request that fails
    /// is logged and skipped, and the window keeps its unfiltered frame.
    pub fn run(&mut self, gl: &glow::Context, requests: &[FilteredPicture]) {
        self.done
            .retain(|g| requests.iter().any(|r| r.pixels.generation() == *g));
        for request in requests {
            let generation = request.pixels.generation();
            if self.done.contains(&generation) {
                continue;
            }
            self.done.push(generation);
            match self.filter(gl, request) {
                Ok(pixels) => request.output.deliver(pixels),
                Err(e) => tracing::warn!("picture not filtered for its window: {e}"),
            }
        }
    }

    fn filter(
        &mut self,
        gl: &glow::Context,
        request: &FilteredPicture,
    ) -> Result<Pixels, FilterError> {
        let runner = match &mut self.runner {
            Some(runner) => runner,
            None => self.runner.insert(KernelRunner::new(gl)?),
        };
        let source = texture::upload(gl, &request.pixels)?;
        let result = runner.run(gl, &source, &request.filters);
        let pixels = match result {
            Ok(Some(filtered)) => {
                let read = read_back(gl, &filtered);
                // SAFETY: the texture belongs to this context and is not used afterwards.
                unsafe { gl.delete_texture(filtered.texture) };
                read
            }
            Ok(None) => read_back(gl, &source),
            Err(e) => Err(e.into()),
        };
        // SAFETY: as above.
        unsafe { gl.delete_texture(source.texture) };
        pixels
    }

    /// Frees the GL objects.
    pub fn destroy(&mut self, gl: &glow::Context) {
        if let Some(runner) = self.runner.take() {
            runner.destroy(gl);
        }
    }
}

/// The texture's pixels, RGBA, rows bottom-up, read through a temporary framebuffer.
fn read_back(gl: &glow::Context, texture: &GpuTexture) -> Result<Pixels, FilterError> {
    let (w, h) = (texture.width, texture.height);
    let mut bytes = vec![0u8; w as usize * h as usize * BYTES_PER_PIXEL];
    // SAFETY: the texture belongs to this current context; `bytes` holds exactly its pixels;
    // the caller's read framebuffer is put back.
    unsafe {
        let saved = gl.get_parameter_framebuffer(glow::READ_FRAMEBUFFER_BINDING);
        let framebuffer = gl.create_framebuffer().map_err(GlError::from)?;
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(framebuffer));
        gl.framebuffer_texture_2d(
            glow::READ_FRAMEBUFFER,
            glow::COLOR_ATTACHMENT0,
            glow::TEXTURE_2D,
            Some(texture.texture),
            0,
        );
        gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
        gl.read_pixels(
            0,
            0,
            w as i32,
            h as i32,
            glow::RGBA,
            glow::UNSIGNED_BYTE,
            glow::PixelPackData::Slice(Some(&mut bytes)),
        );
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, saved);
        gl.delete_framebuffer(framebuffer);
    }
    Ok(Pixels::new(w, h, PixelFormat::Rgba8, bytes)?)
}
