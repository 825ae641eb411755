//! Mipmaps for grids where each coarser cell keeps the darkest of the cells below it, made on
//! the GPU one level from the one before. Zoomed out on a 4000 × 4000 map, a screen pixel
//! covers many cells; plain nearest sampling shows one of them at random (walls flicker and
//! vanish), averaging fades a wall into the free space; the minimum keeps every obstacle.
//! (Unknown space is darker than free, so it also wins over free at a distance: it is never
//! shown as free, which is the safe way to be wrong.)

use eframe::glow::{self, HasContext};

use super::gl_error::GlError;
use super::gl_state::SavedState;
use super::shader::{glsl_header, link_program};
use super::texture::{GpuTexture, level_count, set_sampling};

const LEVEL_VERTEX: &str = r#"
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
"#;

/// The darkest of the 3 × 3 cells from twice this pixel on: two would do, but a level of odd
/// size would then drop its last row and column, and a wall along the edge with them.
const LEVEL_FRAGMENT: &str = r#"
uniform sampler2D u_image;
out vec4 f_color;
void main() {
    ivec2 last = textureSize(u_image, 0) - ivec2(1);
    ivec2 at = ivec2(gl_FragCoord.xy) * 2;
    vec4 darkest = vec4(1.0);
    for (int dy = 0; dy <= 2; dy++) {
        for (int dx = 0; dx <= 2; dx++) {
            ivec2 p = min(at + ivec2(dx, dy), last);
            darkest = min(darkest, texelFetch(u_image, p, 0));
        }
    }
    f_color = darkest;
}
"#;

/// Fills the mipmap levels of grid textures.
pub struct GridMipmaps {
    program: glow::Program,
    vao: glow::VertexArray,
    framebuffer: glow::Framebuffer,
}

impl GridMipmaps {
    pub fn new(gl: &glow::Context) -> Result<GridMipmaps, GlError> {
        let header = glsl_header(gl);
        // SAFETY: object creation on the current context.
        unsafe {
            Ok(GridMipmaps {
                program: link_program(
                    gl,
                    &format!("{header}{LEVEL_VERTEX}"),
                    &format!("{header}{LEVEL_FRAGMENT}"),
                )?,
                vao: gl.create_vertex_array()?,
                framebuffer: gl.create_framebuffer()?,
            })
        }
    }

    /// Allocates and fills every level of `texture` below the first; returns it with its
    /// level count, or unchanged (one level) if a level could not be drawn into.
    pub fn fill(&self, gl: &glow::Context, texture: GpuTexture) -> GpuTexture {
        let levels = level_count(texture.width, texture.height);
        if levels <= 1 || texture.levels == levels {
            return texture;
        }
        let saved = SavedState::take(gl);
        let filled = self.draw_levels(gl, &texture, levels);
        let levels = if filled { levels } else { 1 };
        // SAFETY: parameters of the texture `draw_levels` left bound on unit 0.
        unsafe {
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_BASE_LEVEL, 0);
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAX_LEVEL, levels as i32 - 1);
        }
        set_sampling(gl, framework::scene::Sampling::Grid, levels);
        saved.restore(gl);
        if !filled {
            tracing::warn!("grid drawn without its coarse levels: a framebuffer was incomplete");
        }
        GpuTexture { levels, ..texture }
    }

    fn draw_levels(&self, gl: &glow::Context, texture: &GpuTexture, levels: u32) -> bool {
        // SAFETY: objects of this context. While level `i` is drawn only level `i - 1` can be
        // sampled (base = max = i - 1), so reading and writing one texture is no feedback loop;
        // texel fetches count levels from the base, so the shader reads its level 0.
        unsafe {
            gl.active_texture(glow::TEXTURE0);
            gl.bind_texture(glow::TEXTURE_2D, Some(texture.texture));
            let (internal, format) = (texture.internal_format, texture.format);
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(self.framebuffer));
            gl.disable(glow::SCISSOR_TEST);
            gl.disable(glow::BLEND);
            gl.disable(glow::DEPTH_TEST);
            gl.use_program(Some(self.program));
            gl.bind_vertex_array(Some(self.vao));
            gl.uniform_1_i32(gl.get_uniform_location(self.program, "u_image").as_ref(), 0);
            let mut ok = true;
            for level in 1..levels {
                let (w, h) = (
                    (texture.width >> level).max(1),
                    (texture.height >> level).max(1),
                );
                gl.tex_image_2d(
                    glow::TEXTURE_2D,
                    level as i32,
                    internal as i32,
                    w as i32,
                    h as i32,
                    0,
                    format,
                    glow::UNSIGNED_BYTE,
                    glow::PixelUnpackData::Slice(None),
                );
                gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_BASE_LEVEL, level as i32 - 1);
                gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAX_LEVEL, level as i32 - 1);
                gl.framebuffer_texture_2d(
                    glow::FRAMEBUFFER,
                    glow::COLOR_ATTACHMENT0,
                    glow::TEXTURE_2D,
                    Some(texture.texture),
                    level as i32,
                );
                if gl.check_framebuffer_status(glow::FRAMEBUFFER) != glow::FRAMEBUFFER_COMPLETE {
                    ok = false;
                    break;
                }
                gl.viewport(0, 0, w as i32, h as i32);
                gl.draw_arrays(glow::TRIANGLES, 0, 3);
            }
            gl.framebuffer_texture_2d(
                glow::FRAMEBUFFER,
                glow::COLOR_ATTACHMENT0,
                glow::TEXTURE_2D,
                None,
                0,
            );
            ok
        }
    }

    pub fn destroy(&self, gl: &glow::Context) {
        // SAFETY: objects of this context, not used afterwards.
        unsafe {
            gl.delete_program(self.program);
            gl.delete_vertex_array(self.vao);
            gl.delete_framebuffer(self.framebuffer);
        }
    }
}
