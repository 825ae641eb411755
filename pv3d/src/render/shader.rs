//! Compiling and linking a GLSL program, shared by the scene's, the pictures' and the
//! kernels' shaders: one place that knows which `#version` the context speaks.

use eframe::glow::{self, HasContext};

use super::gl_error::GlError;

/// The first lines of every shader: GLSL 330 core on desktop GL (Mesa's llvmpipe included),
/// 300 es on GLES.
pub fn glsl_header(gl: &glow::Context) -> &'static str {
    if gl.version().is_embedded {
        "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
    } else {
        "#version 330 core\n"
    }
}

/// Compiles `vertex` and `fragment` (each already starting with the header) and links them.
/// The error is the driver's log, prefixed with the stage that failed.
///
/// # Safety
/// The caller holds a current context.
pub unsafe fn link_program(
    gl: &glow::Context,
    vertex: &str,
    fragment: &str,
) -> Result<glow::Program, GlError> {
    // SAFETY: the caller holds a current context; every object made here is deleted on error.
    unsafe {
        let program = gl.create_program()?;
        let mut shaders = Vec::new();
        for (kind, stage, source) in [
            (glow::VERTEX_SHADER, "vertex shader", vertex),
            (glow::FRAGMENT_SHADER, "fragment shader", fragment),
        ] {
            let shader = gl.create_shader(kind)?;
            gl.shader_source(shader, source);
            gl.compile_shader(shader);
            if !gl.get_shader_compile_status(shader) {
                let log = gl.get_shader_info_log(shader);
                gl.delete_shader(shader);
                for s in shaders {
                    gl.delete_shader(s);
                }
                gl.delete_program(program);
                return Err(GlError::Compile {
                    stage,
                    log: log.trim().to_string(),
                });
            }
            gl.attach_shader(program, shader);
            shaders.push(shader);
        }
        gl.link_program(program);
        let linked = gl.get_program_link_status(program);
        for shader in shaders {
            gl.detach_shader(program, shader);
            gl.delete_shader(shader);
        }
        if !linked {
            let log = gl.get_program_info_log(program);
            gl.delete_program(program);
            return Err(GlError::Link(log.trim().to_string()));
        }
        Ok(program)
    }
}
