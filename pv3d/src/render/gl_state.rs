//! The GL state an offscreen pass changes (framebuffer, viewport, scissor, blending, depth
//! test, program, vertex array, bound texture), taken before and put back after: the kernel
//! and mipmap passes run inside egui's paint callback, which expects its state unchanged.

use eframe::glow::{self, HasContext};

/// The GL state a pass changes, to put back.
pub struct SavedState {
    draw_framebuffer: Option<glow::Framebuffer>,
    read_framebuffer: Option<glow::Framebuffer>,
    viewport: [i32; 4],
    scissor: bool,
    blend: bool,
    depth_test: bool,
    program: Option<glow::Program>,
    vao: Option<glow::VertexArray>,
    active_texture: u32,
    texture: Option<glow::Texture>,
}

impl SavedState {
    pub fn take(gl: &glow::Context) -> SavedState {
        // SAFETY: queries on the current context.
        unsafe {
            let mut viewport = [0; 4];
            gl.get_parameter_i32_slice(glow::VIEWPORT, &mut viewport);
            let active_texture = gl.get_parameter_i32(glow::ACTIVE_TEXTURE) as u32;
            gl.active_texture(glow::TEXTURE0);
            SavedState {
                draw_framebuffer: gl.get_parameter_framebuffer(glow::DRAW_FRAMEBUFFER_BINDING),
                read_framebuffer: gl.get_parameter_framebuffer(glow::READ_FRAMEBUFFER_BINDING),
                viewport,
                scissor: gl.is_enabled(glow::SCISSOR_TEST),
                blend: gl.is_enabled(glow::BLEND),
                depth_test: gl.is_enabled(glow::DEPTH_TEST),
                program: gl.get_parameter_program(glow::CURRENT_PROGRAM),
                vao: gl.get_parameter_vertex_array(glow::VERTEX_ARRAY_BINDING),
                active_texture,
                texture: gl.get_parameter_texture(glow::TEXTURE_BINDING_2D),
            }
        }
    }

    /// The viewport that was set: x, y, width, height.
    pub fn viewport(&self) -> [i32; 4] {
        self.viewport
    }

    pub fn restore(&self, gl: &glow::Context) {
        let enable = |cap: u32, on: bool| {
            // SAFETY: toggling a capability on the current context.
            unsafe {
                if on {
                    gl.enable(cap);
                } else {
                    gl.disable(cap);
                }
            }
        };
        enable(glow::SCISSOR_TEST, self.scissor);
        enable(glow::BLEND, self.blend);
        enable(glow::DEPTH_TEST, self.depth_test);
        // SAFETY: these objects were bound before the run and still exist.
        unsafe {
            gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, self.draw_framebuffer);
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, self.read_framebuffer);
            let [x, y, w, h] = self.viewport;
            gl.viewport(x, y, w, h);
            gl.use_program(self.program);
            gl.bind_vertex_array(self.vao);
            gl.active_texture(glow::TEXTURE0);
            gl.bind_texture(glow::TEXTURE_2D, self.texture);
            gl.active_texture(self.active_texture);
        }
    }
}
