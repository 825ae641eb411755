//! Translucent fills drawn at half the view's resolution when they pile up, then laid over it
//! in one pass.
//!
//! A thousand robots' free space covers the view several times over, and Mesa's software
//! rasteriser pays for every covered pixel of every layer: at 1 024 robots the fills alone
//! took about a quarter of the process's CPU. Drawn into a layer of a quarter of the pixels,
//! they cost a quarter as much, and the outlines and returns drawn over them at full
//! resolution keep the picture sharp. The layer holds premultiplied colour, so laying it over
//! the view gives the same blend as drawing every fill there. It is not depth-tested: it goes
//! on the ground and the pictures, under the bodies, lines and points drawn after it.

use eframe::glow::{self, HasContext};

use super::gl_error::{GlError, RendererError};
use super::gl_state::SavedState;
use super::shader::{glsl_header, link_program};

/// One triangle that covers the viewport, its texture coordinates from the vertex index.
const OVER_VIEW_VERTEX: &str = r#"
out vec2 v_uv;
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    v_uv = corner;
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
"#;

const OVER_VIEW_FRAGMENT: &str = r#"
in vec2 v_uv;
uniform sampler2D u_layer;
out vec4 f_color;
void main() { f_color = texture(u_layer, v_uv); }
"#;

/// The layer's GL objects; the texture follows the viewport's size.
pub struct FillLayer {
    program: glow::Program,
    vao: glow::VertexArray,
    framebuffer: glow::Framebuffer,
    texture: glow::Texture,
    size: (i32, i32),
}

impl FillLayer {
    pub fn new(gl: &glow::Context) -> Result<FillLayer, RendererError> {
        let header = glsl_header(gl);
        // SAFETY: plain object creation on the current context.
        unsafe {
            let program = link_program(
                gl,
                &format!("{header}{OVER_VIEW_VERTEX}"),
                &format!("{header}{OVER_VIEW_FRAGMENT}"),
            )
            .map_err(RendererError)?;
            Ok(FillLayer {
                program,
                vao: gl.create_vertex_array().map_err(GlError::from)?,
                framebuffer: gl.create_framebuffer().map_err(GlError::from)?,
                texture: gl.create_texture().map_err(GlError::from)?,
                size: (0, 0),
            })
        }
    }

    /// Runs `draw_fills` (which draws with the caller's program, its blending set here) into
    /// the layer at half the current viewport's size, then lays the layer over the viewport.
    /// The caller's framebuffer, viewport, scissor, program and bindings are as they were
    /// afterwards; blending is left at straight alpha, as the scene draws.
    ///
    /// # Safety
    /// The caller holds a current context, the one this layer was made on.
    pub unsafe fn draw(&mut self, gl: &glow::Context, draw_fills: impl FnOnce()) {
        let saved = SavedState::take(gl);
        let [_, _, width, height] = saved.viewport();
        let size = ((width + 1) / 2, (height + 1) / 2);
        // SAFETY: the caller holds the current context; objects are this layer's own.
        unsafe {
            if size.0 < 1 || size.1 < 1 || !self.fit(gl, size) {
                saved.restore(gl);
                draw_fills(); // no layer to be had: straight onto the view
                return;
            }
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(self.framebuffer));
            gl.viewport(0, 0, size.0, size.1);
            gl.disable(glow::SCISSOR_TEST);
            gl.disable(glow::DEPTH_TEST);
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            gl.clear(glow::COLOR_BUFFER_BIT);
            gl.enable(glow::BLEND);
            // Colour blended as on the view; alpha accumulated for laying the layer over it.
            gl.blend_func_separate(
                glow::SRC_ALPHA,
                glow::ONE_MINUS_SRC_ALPHA,
                glow::ONE,
                glow::ONE_MINUS_SRC_ALPHA,
            );
            draw_fills();
            saved.restore(gl);

            gl.disable(glow::DEPTH_TEST);
            gl.enable(glow::BLEND);
            gl.blend_func(glow::ONE, glow::ONE_MINUS_SRC_ALPHA);
            gl.use_program(Some(self.program));
            gl.uniform_1_i32(gl.get_uniform_location(self.program, "u_layer").as_ref(), 0);
            gl.active_texture(glow::TEXTURE0);
            gl.bind_texture(glow::TEXTURE_2D, Some(self.texture));
            gl.bind_vertex_array(Some(self.vao));
            gl.draw_arrays(glow::TRIANGLES, 0, 3);
            gl.blend_func(glow::SRC_ALPHA, glow::ONE_MINUS_SRC_ALPHA);
            saved.restore(gl);
        }
    }

    /// Gives the texture `size` (kept while the view keeps its size); false if the
    /// framebuffer cannot be completed with it.
    unsafe fn fit(&mut self, gl: &glow::Context, size: (i32, i32)) -> bool {
        if self.size == size {
            return true;
        }
        // SAFETY: the caller holds the current context; texture and framebuffer are ours.
        unsafe {
            gl.bind_texture(glow::TEXTURE_2D, Some(self.texture));
            gl.tex_image_2d(
                glow::TEXTURE_2D,
                0,
                glow::RGBA8 as i32,
                size.0,
                size.1,
                0,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                glow::PixelUnpackData::Slice(None),
            );
            for (parameter, value) in [
                (glow::TEXTURE_MIN_FILTER, glow::LINEAR),
                (glow::TEXTURE_MAG_FILTER, glow::LINEAR),
                (glow::TEXTURE_WRAP_S, glow::CLAMP_TO_EDGE),
                (glow::TEXTURE_WRAP_T, glow::CLAMP_TO_EDGE),
            ] {
                gl.tex_parameter_i32(glow::TEXTURE_2D, parameter, value as i32);
            }
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(self.framebuffer));
            gl.framebuffer_texture_2d(
                glow::FRAMEBUFFER,
                glow::COLOR_ATTACHMENT0,
                glow::TEXTURE_2D,
                Some(self.texture),
                0,
            );
            let complete =
                gl.check_framebuffer_status(glow::FRAMEBUFFER) == glow::FRAMEBUFFER_COMPLETE;
            self.size = if complete { size } else { (0, 0) };
            complete
        }
    }

    /// Frees the GL objects.
    pub fn destroy(&mut self, gl: &glow::Context) {
        // SAFETY: the objects belong to this context and are not used afterwards.
        unsafe {
            gl.delete_program(self.program);
            gl.delete_vertex_array(self.vao);
            gl.delete_framebuffer(self.framebuffer);
            gl.delete_texture(self.texture);
        }
    }
}
