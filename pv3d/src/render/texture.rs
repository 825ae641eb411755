//! A scene picture as a GL texture. Grey pictures are uploaded as one byte per pixel and read
//! back as grey by the texture's swizzle, so a 4000 × 4000 map costs 16 MB, not 64, and every
//! shader (quads, kernels) sees RGBA either way.

use eframe::glow::{self, HasContext};
use framework::scene::{PixelFormat, Pixels, Sampling};

/// Why a picture could not become a texture.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum TextureError {
    #[error("a {width}×{height} picture is larger than this GL's {max}-pixel textures")]
    TooLarge { width: u32, height: u32, max: u32 },
    #[error("creating a texture: {0}")]
    Create(String),
}

/// A texture and the size of the picture in it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GpuTexture {
    pub texture: glow::Texture,
    pub width: u32,
    pub height: u32,
    /// Mipmap levels filled (1: only the picture itself).
    pub levels: u32,
    /// How its texels are stored (`R8`, `RGBA8`) and the matching pixel format (`RED`,
    /// `RGBA`), for making its coarser levels alike.
    pub internal_format: u32,
    pub format: u32,
}

/// The largest texture side this context takes.
pub fn max_texture_side(gl: &glow::Context) -> u32 {
    // SAFETY: a plain query on the current context.
    let side = unsafe { gl.get_parameter_i32(glow::MAX_TEXTURE_SIZE) };
    u32::try_from(side).unwrap_or(0)
}

/// Uploads `pixels` into a new texture (bound to `TEXTURE_2D` on the active unit afterwards).
pub fn upload(gl: &glow::Context, pixels: &Pixels) -> Result<GpuTexture, TextureError> {
    let (width, height) = (pixels.width(), pixels.height());
    let max = max_texture_side(gl);
    if width > max || height > max {
        return Err(TextureError::TooLarge { width, height, max });
    }
    let (internal, format) = match pixels.format() {
        PixelFormat::Rgba8 => (glow::RGBA8, glow::RGBA),
        PixelFormat::Gray8 => (glow::R8, glow::RED),
    };
    // SAFETY: the byte count matches width × height × format (checked by `Pixels::new`); rows
    // are tightly packed, which UNPACK_ALIGNMENT 1 says, and the old alignment is put back.
    unsafe {
        let texture = gl.create_texture().map_err(TextureError::Create)?;
        gl.bind_texture(glow::TEXTURE_2D, Some(texture));
        let alignment = gl.get_parameter_i32(glow::UNPACK_ALIGNMENT);
        gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
        gl.tex_image_2d(
            glow::TEXTURE_2D,
            0,
            internal as i32,
            width as i32,
            height as i32,
            0,
            format,
            glow::UNSIGNED_BYTE,
            glow::PixelUnpackData::Slice(Some(pixels.bytes())),
        );
        gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, alignment);
        if pixels.format() == PixelFormat::Gray8 {
            for channel in [
                glow::TEXTURE_SWIZZLE_R,
                glow::TEXTURE_SWIZZLE_G,
                glow::TEXTURE_SWIZZLE_B,
            ] {
                gl.tex_parameter_i32(glow::TEXTURE_2D, channel, glow::RED as i32);
            }
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_SWIZZLE_A, glow::ONE as i32);
        }
        set_sampling(gl, Sampling::Nearest, 1);
        for wrap in [glow::TEXTURE_WRAP_S, glow::TEXTURE_WRAP_T] {
            gl.tex_parameter_i32(glow::TEXTURE_2D, wrap, glow::CLAMP_TO_EDGE as i32);
        }
        Ok(GpuTexture {
            texture,
            width,
            height,
            levels: 1,
            internal_format: internal,
            format,
        })
    }
}

/// An empty RGBA texture for a kernel pass to draw into.
pub fn render_target(
    gl: &glow::Context,
    width: u32,
    height: u32,
) -> Result<GpuTexture, TextureError> {
    // SAFETY: no data is read; the size was accepted for the picture already.
    unsafe {
        let texture = gl.create_texture().map_err(TextureError::Create)?;
        gl.bind_texture(glow::TEXTURE_2D, Some(texture));
        gl.tex_image_2d(
            glow::TEXTURE_2D,
            0,
            glow::RGBA8 as i32,
            width as i32,
            height as i32,
            0,
            glow::RGBA,
            glow::UNSIGNED_BYTE,
            glow::PixelUnpackData::Slice(None),
        );
        set_sampling(gl, Sampling::Nearest, 1);
        for wrap in [glow::TEXTURE_WRAP_S, glow::TEXTURE_WRAP_T] {
            gl.tex_parameter_i32(glow::TEXTURE_2D, wrap, glow::CLAMP_TO_EDGE as i32);
        }
        Ok(GpuTexture {
            texture,
            width,
            height,
            levels: 1,
            internal_format: glow::RGBA8,
            format: glow::RGBA,
        })
    }
}

/// Sets how the texture bound to `TEXTURE_2D`, with `levels` mipmap levels filled, is
/// sampled. Only grids use mipmaps, and only the darkest-cell ones [`super::grid_mipmaps`]
/// makes: averaged levels would fade a thin wall into the free space around it.
pub fn set_sampling(gl: &glow::Context, sampling: Sampling, levels: u32) {
    let (min, mag) = match sampling {
        Sampling::Nearest => (glow::NEAREST, glow::NEAREST),
        Sampling::Linear => (glow::LINEAR, glow::LINEAR),
        Sampling::Grid if levels > 1 => (glow::NEAREST_MIPMAP_NEAREST, glow::NEAREST),
        Sampling::Grid => (glow::NEAREST, glow::NEAREST),
    };
    // SAFETY: parameters of the bound texture.
    unsafe {
        gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MIN_FILTER, min as i32);
        gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAG_FILTER, mag as i32);
    }
}

/// How many mipmap levels a `width` × `height` texture has, down to 1 × 1.
pub fn level_count(width: u32, height: u32) -> u32 {
    u32::BITS - width.max(height).max(1).leading_zeros()
}
