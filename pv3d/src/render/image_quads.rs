//! Drawing the scene's pictures: one textured quad each, depth-tested with the rest of the
//! scene. Textures are kept by the picture's generation and re-uploaded only when a plugin
//! hands over new pixels; a filtered picture is kept by generation and chain, so the kernels
//! run once, not every frame, and one picture under six chains is uploaded once.

use std::collections::HashMap;

use bytemuck::{Pod, Zeroable};
use eframe::glow::{self, HasContext};
use framework::scene::{FilterChain, Pixels, Sampling};

use super::batch::BatchedImage;
use super::billboard::BillboardAxes;
use super::gl_error::GlError;
use super::grid_mipmaps::GridMipmaps;
use super::kernels::KernelRunner;
use super::shader::{glsl_header, link_program};
use super::texture::{self, GpuTexture};

const QUAD_VERTEX: &str = r#"
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec2 a_uv;
layout(location = 2) in vec2 a_offset;
uniform mat4 u_view_proj;
uniform vec3 u_right;
uniform vec3 u_up;
out vec2 v_uv;
void main() {
    // A billboard's corners sit on its anchor and are pushed out along the viewer's axes.
    vec3 pos = a_pos + u_right * a_offset.x + u_up * a_offset.y;
    gl_Position = u_view_proj * vec4(pos, 1.0);
    v_uv = a_uv;
}
"#;

const QUAD_FRAGMENT: &str = r#"
in vec2 v_uv;
uniform sampler2D u_image;
out vec4 f_color;
void main() {
    vec4 c = texture(u_image, v_uv);
    if (c.a <= 0.0) discard;
    f_color = c;
}
"#;

/// A picture's vertex: 28 bytes. `offset` is zero but for billboards (see
/// [`BatchedImage`]).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Pod, Zeroable)]
struct ImageVertex {
    pos: [f32; 3],
    uv: [f32; 2],
    offset: [f32; 2],
}

/// Two triangles per quad.
const VERTICES_PER_QUAD: usize = 6;
const QUAD_TRIANGLES: [usize; VERTICES_PER_QUAD] = [0, 1, 2, 0, 2, 3];

/// How far pictures are pushed back in depth (glPolygonOffset factor and units): a map lies
/// on the ground plane with the grid and trails drawn on it, and those must stay on top.
const BEHIND_LINES: (f32, f32) = (1.0, 1.0);

/// A filtered picture, or the error its chain gave (kept, so it is logged once).
struct Filtered {
    generation: u64,
    chain: FilterChain,
    outcome: Result<Option<GpuTexture>, ()>,
}

/// What one quad draws with.
struct QuadDraw {
    texture: GpuTexture,
    sampling: Sampling,
}

/// The pictures' GL side.
pub struct ImageRenderer {
    program: glow::Program,
    vao: glow::VertexArray,
    vbo: glow::Buffer,
    /// Uploaded pictures by generation; `None` for one that could not be (logged once).
    sources: HashMap<u64, Option<GpuTexture>>,
    filtered: Vec<Filtered>,
    runner: Option<KernelRunner>,
    mipmaps: Option<GridMipmaps>,
    draws: Vec<QuadDraw>,
}

impl ImageRenderer {
    pub fn new(gl: &glow::Context) -> Result<ImageRenderer, GlError> {
        let header = glsl_header(gl);
        // SAFETY: object creation on the current context; the layout matches ImageVertex.
        unsafe {
            let program = link_program(
                gl,
                &format!("{header}{QUAD_VERTEX}"),
                &format!("{header}{QUAD_FRAGMENT}"),
            )?;
            let vao = gl.create_vertex_array()?;
            let vbo = gl.create_buffer()?;
            gl.bind_vertex_array(Some(vao));
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
            let stride = std::mem::size_of::<ImageVertex>() as i32;
            gl.enable_vertex_attrib_array(0);
            gl.vertex_attrib_pointer_f32(0, 3, glow::FLOAT, false, stride, 0);
            gl.enable_vertex_attrib_array(1);
            gl.vertex_attrib_pointer_f32(1, 2, glow::FLOAT, false, stride, 12);
            gl.enable_vertex_attrib_array(2);
            gl.vertex_attrib_pointer_f32(2, 2, glow::FLOAT, false, stride, 20);
            gl.bind_vertex_array(None);
            gl.bind_buffer(glow::ARRAY_BUFFER, None);
            Ok(ImageRenderer {
                program,
                vao,
                vbo,
                sources: HashMap::new(),
                filtered: Vec::new(),
                runner: None,
                mipmaps: None,
                draws: Vec::new(),
            })
        }
    }

    /// Makes the textures `images` need (uploading and filtering only what is new), frees
    /// those no longer drawn, and fills the vertex buffer.
    pub fn upload(&mut self, gl: &glow::Context, images: &[BatchedImage]) {
        self.draws.clear();
        let mut vertices = Vec::with_capacity(images.len() * VERTICES_PER_QUAD);
        for image in images {
            let Some(source) = self.source(gl, &image.pixels) else {
                continue;
            };
            let texture = if image.filters.is_empty() {
                source
            } else {
                self.filtered(gl, image, &source).unwrap_or(source)
            };
            let texture = if image.sampling == Sampling::Grid {
                self.with_mipmaps(gl, image, texture)
            } else {
                texture
            };
            self.draws.push(QuadDraw {
                texture,
                sampling: image.sampling,
            });
            vertices.extend(QUAD_TRIANGLES.map(|i| ImageVertex {
                pos: image.corners[i].0,
                uv: image.corners[i].1,
                offset: image.offsets[i],
            }));
        }
        self.evict(gl, images);
        // SAFETY: the buffer belongs to this context; the slice is plain old data.
        unsafe {
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(self.vbo));
            gl.buffer_data_u8_slice(
                glow::ARRAY_BUFFER,
                bytemuck::cast_slice(&vertices),
                glow::DYNAMIC_DRAW,
            );
            gl.bind_buffer(glow::ARRAY_BUFFER, None);
        }
    }

    /// The texture of `pixels`, uploaded the first time.
    fn source(&mut self, gl: &glow::Context, pixels: &Pixels) -> Option<GpuTexture> {
        *self.sources.entry(pixels.generation()).or_insert_with(|| {
            match texture::upload(gl, pixels) {
                Ok(t) => Some(t),
                Err(e) => {
                    tracing::error!("picture not drawn: {e}");
                    None
                }
            }
        })
    }

    /// `image` through its chain, run the first time; `None` draws it unfiltered (a chain
    /// that changes nothing, or one that failed, logged once).
    fn filtered(
        &mut self,
        gl: &glow::Context,
        image: &BatchedImage,
        source: &GpuTexture,
    ) -> Option<GpuTexture> {
        let generation = image.pixels.generation();
        let known = self
            .filtered
            .iter()
            .find(|f| f.generation == generation && f.chain == image.filters);
        if let Some(known) = known {
            return known.outcome.ok().flatten();
        }
        let outcome: Result<Option<GpuTexture>, ()> = match self.runner(gl) {
            Some(runner) => runner.run(gl, source, &image.filters).map_err(|e| {
                tracing::error!("filter chain {} not applied: {e}", image.filters.describe());
            }),
            None => Err(()),
        };
        self.filtered.push(Filtered {
            generation,
            chain: image.filters.clone(),
            outcome,
        });
        outcome.ok().flatten()
    }

    /// `texture` with its darkest-cell levels, made the first time and kept with it.
    fn with_mipmaps(
        &mut self,
        gl: &glow::Context,
        image: &BatchedImage,
        texture: GpuTexture,
    ) -> GpuTexture {
        if texture.levels > 1 {
            return texture;
        }
        if self.mipmaps.is_none() {
            match GridMipmaps::new(gl) {
                Ok(m) => self.mipmaps = Some(m),
                Err(e) => {
                    tracing::error!("grids drawn without coarse levels: {e}");
                    return texture;
                }
            }
        }
        let Some(mipmaps) = &self.mipmaps else {
            return texture;
        };
        let filled = mipmaps.fill(gl, texture);
        // Keep the levels with whichever texture this was: the filtered one or the source.
        let generation = image.pixels.generation();
        if let Some(f) = self
            .filtered
            .iter_mut()
            .find(|f| f.generation == generation && f.chain == image.filters)
            && let Ok(Some(t)) = &mut f.outcome
            && t.texture == filled.texture
        {
            *t = filled;
        } else if let Some(Some(t)) = self.sources.get_mut(&generation)
            && t.texture == filled.texture
        {
            *t = filled;
        }
        filled
    }

    fn runner(&mut self, gl: &glow::Context) -> Option<&mut KernelRunner> {
        if self.runner.is_none() {
            match KernelRunner::new(gl) {
                Ok(r) => self.runner = Some(r),
                Err(e) => tracing::error!("filters disabled: {e}"),
            }
        }
        self.runner.as_mut()
    }

    /// Deletes the textures of pictures and chains `images` no longer holds.
    fn evict(&mut self, gl: &glow::Context, images: &[BatchedImage]) {
        let drawn = |generation: u64| images.iter().any(|i| i.pixels.generation() == generation);
        let mut gone = Vec::new();
        self.sources.retain(|&generation, texture| {
            let keep = drawn(generation);
            if !keep && let Some(t) = texture {
                gone.push(t.texture);
            }
            keep
        });
        self.filtered.retain(|f| {
            let keep = images
                .iter()
                .any(|i| i.pixels.generation() == f.generation && i.filters == f.chain);
            if !keep && let Ok(Some(t)) = f.outcome {
                gone.push(t.texture);
            }
            keep
        });
        // SAFETY: textures of this context that no draw refers to any more.
        unsafe {
            for texture in gone {
                gl.delete_texture(texture);
            }
        }
    }

    /// Draws every quad uploaded, with depth test and writes as the caller set them;
    /// billboards turned along `axes`, those of the camera `view_proj` draws for.
    pub fn draw(&self, gl: &glow::Context, view_proj: &[f32; 16], axes: BillboardAxes) {
        if self.draws.is_empty() {
            return;
        }
        // SAFETY: program, buffer and textures belong to this context.
        unsafe {
            gl.use_program(Some(self.program));
            gl.uniform_matrix_4_f32_slice(
                gl.get_uniform_location(self.program, "u_view_proj")
                    .as_ref(),
                false,
                view_proj,
            );
            let (right, up) = (axes.right, axes.up);
            let right_at = gl.get_uniform_location(self.program, "u_right");
            gl.uniform_3_f32(right_at.as_ref(), right.x, right.y, right.z);
            let up_at = gl.get_uniform_location(self.program, "u_up");
            gl.uniform_3_f32(up_at.as_ref(), up.x, up.y, up.z);
            gl.uniform_1_i32(gl.get_uniform_location(self.program, "u_image").as_ref(), 0);
            gl.active_texture(glow::TEXTURE0);
            gl.enable(glow::POLYGON_OFFSET_FILL);
            gl.polygon_offset(BEHIND_LINES.0, BEHIND_LINES.1);
            gl.bind_vertex_array(Some(self.vao));
            for (i, draw) in self.draws.iter().enumerate() {
                gl.bind_texture(glow::TEXTURE_2D, Some(draw.texture.texture));
                texture::set_sampling(gl, draw.sampling, draw.texture.levels);
                gl.draw_arrays(
                    glow::TRIANGLES,
                    (i * VERTICES_PER_QUAD) as i32,
                    VERTICES_PER_QUAD as i32,
                );
            }
            gl.disable(glow::POLYGON_OFFSET_FILL);
            gl.bind_texture(glow::TEXTURE_2D, None);
        }
    }

    /// Frees every GL object.
    pub fn destroy(&mut self, gl: &glow::Context) {
        self.evict(gl, &[]);
        // SAFETY: objects of this context, not used afterwards.
        unsafe {
            gl.delete_program(self.program);
            gl.delete_vertex_array(self.vao);
            gl.delete_buffer(self.vbo);
        }
        if let Some(runner) = &self.runner {
            runner.destroy(gl);
        }
        if let Some(mipmaps) = &self.mipmaps {
            mipmaps.destroy(gl);
        }
    }
}
