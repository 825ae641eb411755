//! Running a chain's passes: programs compiled once per shader, one framebuffer, two
//! ping-pong textures per run. It runs inside the 3D view's paint callback, so every piece of
//! GL state it changes (framebuffer, viewport, scissor, blending, depth test, program, vertex
//! array, bound texture) is put back as it found it.

use std::collections::HashMap;

use eframe::glow::{self, HasContext};
use framework::scene::FilterChain;

use super::{KernelError, Pass, ShaderKey, Uniform, kernel_source, passes_of, sources};
use crate::render::gl_error::GlError;
use crate::render::gl_state::SavedState;
use crate::render::shader::{glsl_header, link_program};
use crate::render::texture::{GpuTexture, render_target};

/// Compiles and runs kernel passes on one GL context.
pub struct KernelRunner {
    header: &'static str,
    programs: HashMap<ShaderKey, glow::Program>,
    /// Core profiles draw nothing without a vertex array bound, even with no attributes.
    vao: glow::VertexArray,
    framebuffer: glow::Framebuffer,
}

impl KernelRunner {
    pub fn new(gl: &glow::Context) -> Result<KernelRunner, GlError> {
        // SAFETY: plain object creation on the current context.
        unsafe {
            Ok(KernelRunner {
                header: glsl_header(gl),
                programs: HashMap::new(),
                vao: gl.create_vertex_array()?,
                framebuffer: gl.create_framebuffer()?,
            })
        }
    }

    /// Runs `chain` over `source` and returns a new texture of the result, which the caller
    /// owns; `None` when the chain changes nothing (empty, or radii of 0). A kernel that does
    /// not compile is an error before anything is drawn.
    pub fn run(
        &mut self,
        gl: &glow::Context,
        source: &GpuTexture,
        chain: &FilterChain,
    ) -> Result<Option<GpuTexture>, KernelError> {
        let passes: Vec<Pass> = chain.kernels().iter().flat_map(passes_of).collect();
        if passes.is_empty() {
            return Ok(None);
        }
        for pass in &passes {
            self.program(gl, pass)?;
        }
        let saved = SavedState::take(gl);
        let result = self.run_passes(gl, source, &passes);
        saved.restore(gl);
        result.map(Some)
    }

    /// The program of `pass`'s shader, compiled the first time it is asked for.
    fn program(&mut self, gl: &glow::Context, pass: &Pass) -> Result<glow::Program, KernelError> {
        if let Some(&program) = self.programs.get(&pass.shader) {
            return Ok(program);
        }
        let vertex = format!("{}{}", self.header, sources::PASS_VERTEX);
        let fragment = sources::fragment(self.header, &kernel_source(&pass.shader));
        // SAFETY: the context is current.
        let program = unsafe { link_program(gl, &vertex, &fragment) }.map_err(|source| {
            KernelError::Compile {
                kernel: pass.kernel.clone(),
                source,
            }
        })?;
        self.programs.insert(pass.shader.clone(), program);
        Ok(program)
    }

    fn run_passes(
        &mut self,
        gl: &glow::Context,
        source: &GpuTexture,
        passes: &[Pass],
    ) -> Result<GpuTexture, KernelError> {
        let (w, h) = (source.width, source.height);
        let mut targets: [Option<GpuTexture>; 2] = [None, None];
        let mut input = source.texture;
        let outcome = (|| {
            // SAFETY: every object belongs to this context; the viewport is the target's size.
            unsafe {
                gl.bind_framebuffer(glow::FRAMEBUFFER, Some(self.framebuffer));
                gl.viewport(0, 0, w as i32, h as i32);
                gl.disable(glow::SCISSOR_TEST);
                gl.disable(glow::BLEND);
                gl.disable(glow::DEPTH_TEST);
                gl.bind_vertex_array(Some(self.vao));
                gl.active_texture(glow::TEXTURE0);
            }
            for (i, pass) in passes.iter().enumerate() {
                let slot = i % 2;
                let target = match targets[slot] {
                    Some(t) => t,
                    None => {
                        let t = render_target(gl, w, h).map_err(|source| KernelError::Texture {
                            kernel: pass.kernel.clone(),
                            source,
                        })?;
                        targets[slot] = Some(t);
                        t
                    }
                };
                let program = self.program(gl, pass)?;
                // SAFETY: as above; the input texture is never the one drawn into.
                unsafe {
                    gl.framebuffer_texture_2d(
                        glow::FRAMEBUFFER,
                        glow::COLOR_ATTACHMENT0,
                        glow::TEXTURE_2D,
                        Some(target.texture),
                        0,
                    );
                    let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
                    if status != glow::FRAMEBUFFER_COMPLETE {
                        return Err(KernelError::Gl {
                            kernel: pass.kernel.clone(),
                            source: GlError::Incomplete {
                                what: "framebuffer",
                                width: target.width,
                                height: target.height,
                                status,
                            },
                        });
                    }
                    gl.use_program(Some(program));
                    set_uniforms(gl, program, &pass.uniforms);
                    gl.bind_texture(glow::TEXTURE_2D, Some(input));
                    gl.draw_arrays(glow::TRIANGLES, 0, 3);
                }
                input = target.texture;
            }
            Ok((passes.len() - 1) % 2)
        })();
        // SAFETY: detaching, and deleting textures nobody else holds.
        unsafe {
            gl.framebuffer_texture_2d(
                glow::FRAMEBUFFER,
                glow::COLOR_ATTACHMENT0,
                glow::TEXTURE_2D,
                None,
                0,
            );
            let kept = outcome.as_ref().ok().copied();
            for (slot, target) in targets.iter().enumerate() {
                if let Some(t) = target
                    && Some(slot) != kept
                {
                    gl.delete_texture(t.texture);
                }
            }
        }
        outcome.map(|slot| targets[slot].expect("the last pass drew into it"))
    }

    /// Frees the programs and GL objects.
    pub fn destroy(&self, gl: &glow::Context) {
        // SAFETY: objects of this context, not used afterwards.
        unsafe {
            for &program in self.programs.values() {
                gl.delete_program(program);
            }
            gl.delete_vertex_array(self.vao);
            gl.delete_framebuffer(self.framebuffer);
        }
    }
}

/// # Safety
/// `program` is current.
unsafe fn set_uniforms(gl: &glow::Context, program: glow::Program, uniforms: &[(String, Uniform)]) {
    // SAFETY: the caller made `program` current; a name the shader lacks has no location and
    // is skipped by GL.
    unsafe {
        gl.uniform_1_i32(gl.get_uniform_location(program, "u_image").as_ref(), 0);
        for (name, value) in uniforms {
            let at = gl.get_uniform_location(program, name);
            match *value {
                Uniform::Int(v) => gl.uniform_1_i32(at.as_ref(), v),
                Uniform::Step([x, y]) => gl.uniform_2_i32(at.as_ref(), x, y),
                Uniform::Float(v) => gl.uniform_1_f32(at.as_ref(), v),
            }
        }
    }
}
