//! Our own glow renderer of the scene batch: one program for flat-coloured lines, points and
//! triangles, one for lit meshes; one vertex buffer per primitive kind, re-uploaded only when
//! the scene changed.

use std::sync::Arc;

use eframe::glow::{self, HasContext};
use glam::{Mat4, Vec3};

use super::batch::SceneBatch;
use super::billboard::BillboardAxes;
use super::fill_layer::FillLayer;
use super::gl_buffers::{Buffer, draw_buffer, fill, flat_buffer, mesh_buffer};
pub use super::gl_error::RendererError;
use super::image_quads::ImageRenderer;
use super::shader::{glsl_header, link_program};

const FLAT_VERTEX: &str = r#"
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec4 a_color;
uniform mat4 u_view_proj;
uniform float u_point_size;
out vec4 v_color;
void main() {
    gl_Position = u_view_proj * vec4(a_pos, 1.0);
    gl_PointSize = u_point_size;
    v_color = a_color;
}
"#;

const FLAT_FRAGMENT: &str = r#"
in vec4 v_color;
out vec4 f_color;
void main() { f_color = v_color; }
"#;

const LIT_VERTEX: &str = r#"
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_color;
uniform mat4 u_view_proj;
out vec4 v_color;
out vec3 v_normal;
void main() {
    gl_Position = u_view_proj * vec4(a_pos, 1.0);
    v_color = a_color;
    v_normal = a_normal;
}
"#;

const LIT_FRAGMENT: &str = r#"
in vec4 v_color;
in vec3 v_normal;
uniform vec3 u_light_dir;
uniform float u_ambient;
out vec4 f_color;
void main() {
    float diffuse = max(dot(normalize(v_normal), normalize(u_light_dir)), 0.0);
    f_color = vec4(v_color.rgb * (u_ambient + (1.0 - u_ambient) * diffuse), v_color.a);
}
"#;

/// How wide points are drawn unless told otherwise, pixels.
pub const POINT_SIZE_PX: f32 = 3.0;

/// From how many times over translucent fills cover the view on, they are drawn at half
/// resolution ([`FillLayer`]): below it a few robots' fills stay pixel-exact and depth-tested
/// (the extra pass would cost more than it saves, as measured at 1.5 times).
pub const FILLS_IN_LAYER_FROM: f32 = 2.0;

/// How the view is lit and cleared; the lights plugin sets these.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lighting {
    pub direction: Vec3,
    pub ambient: f32,
    pub background: [f32; 4],
}

impl Default for Lighting {
    fn default() -> Self {
        Lighting {
            direction: Vec3::new(0.4, -0.3, 1.0),
            ambient: 0.35,
            background: [0.11, 0.12, 0.14, 1.0],
        }
    }
}

/// Draws a [`SceneBatch`] with glow.
pub struct SceneRenderer {
    flat: glow::Program,
    lit: glow::Program,
    lines: Buffer,
    points: Buffer,
    triangles: Buffer,
    translucent: Buffer,
    mesh: Buffer,
    images: ImageRenderer,
    /// Where crowded fills are drawn; `None` if the context could not make one.
    fill_layer: Option<FillLayer>,
    /// The uploaded batch's fills cover the view [`FILLS_IN_LAYER_FROM`] times or more.
    crowded_fills: bool,
    /// Batch revision last uploaded; `None` forces an upload.
    uploaded: Option<u64>,
    pub point_size: f32,
    pub lighting: Lighting,
}

impl SceneRenderer {
    /// Compiles the shaders (GLSL 330 core, or 300 es on GLES) and creates the buffers.
    pub fn new(gl: &glow::Context) -> Result<SceneRenderer, RendererError> {
        let header = glsl_header(gl);
        // SAFETY: plain GL object creation on the current context.
        unsafe {
            let flat = program(gl, header, FLAT_VERTEX, FLAT_FRAGMENT)?;
            let lit = program(gl, header, LIT_VERTEX, LIT_FRAGMENT)?;
            Ok(SceneRenderer {
                flat,
                lit,
                lines: flat_buffer(gl)?,
                points: flat_buffer(gl)?,
                triangles: flat_buffer(gl)?,
                translucent: flat_buffer(gl)?,
                mesh: mesh_buffer(gl)?,
                images: ImageRenderer::new(gl).map_err(RendererError)?,
                fill_layer: FillLayer::new(gl)
                    .inspect_err(|e| tracing::warn!("fills drawn at full resolution: {e}"))
                    .ok(),
                crowded_fills: false,
                uploaded: None,
                point_size: POINT_SIZE_PX,
                lighting: Lighting::default(),
            })
        }
    }

    /// Uploads the batch unless `revision` (a number that changes whenever the batch is
    /// rebuilt) was the last one uploaded.
    pub fn upload(&mut self, gl: &glow::Context, batch: &SceneBatch, revision: u64) {
        if self.uploaded == Some(revision) {
            return;
        }
        // SAFETY: buffers were created on this context; slices are plain old data.
        unsafe {
            fill(
                gl,
                &mut self.lines,
                bytemuck::cast_slice(&batch.lines),
                batch.lines.len(),
            );
            fill(
                gl,
                &mut self.points,
                bytemuck::cast_slice(&batch.points),
                batch.points.len(),
            );
            fill(
                gl,
                &mut self.triangles,
                bytemuck::cast_slice(&batch.triangles),
                batch.triangles.len(),
            );
            fill(
                gl,
                &mut self.translucent,
                bytemuck::cast_slice(&batch.translucent),
                batch.translucent.len(),
            );
            fill(
                gl,
                &mut self.mesh,
                bytemuck::cast_slice(&batch.mesh),
                batch.mesh.len(),
            );
        }
        self.images.upload(gl, &batch.images);
        self.crowded_fills = batch.translucent_cover >= FILLS_IN_LAYER_FROM;
        self.uploaded = Some(revision);
    }

    /// Forgets what was uploaded (e.g. after a context change).
    pub fn invalidate(&mut self) {
        self.uploaded = None;
    }

    /// Clears the current viewport (colour and depth, within the scissor box the caller set)
    /// and draws everything uploaded — crowded fills at half resolution ([`FillLayer`]).
    pub fn draw(&mut self, gl: &glow::Context, view_proj: Mat4) {
        let mut layer = match self.crowded_fills {
            true => self.fill_layer.take(),
            false => None,
        };
        self.draw_scene(gl, view_proj, layer.as_mut());
        if layer.is_some() {
            self.fill_layer = layer;
        }
    }

    /// [`SceneRenderer::draw`] with every fill at full resolution (a virtual camera's view,
    /// which the batch's crowding was not measured for).
    pub fn draw_every_pixel(&self, gl: &glow::Context, view_proj: Mat4) {
        self.draw_scene(gl, view_proj, None);
    }

    fn draw_scene(&self, gl: &glow::Context, view_proj: Mat4, layer: Option<&mut FillLayer>) {
        let matrix = view_proj.to_cols_array();
        let bg = self.lighting.background;
        // SAFETY: programs and buffers belong to this context; uniforms match the shaders.
        unsafe {
            gl.clear_color(bg[0], bg[1], bg[2], bg[3]);
            gl.clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(glow::LEQUAL);
            gl.depth_mask(true);
            gl.disable(glow::CULL_FACE);
            gl.enable(glow::BLEND);
            gl.blend_func(glow::SRC_ALPHA, glow::ONE_MINUS_SRC_ALPHA);
            if !gl.version().is_embedded {
                gl.enable(glow::PROGRAM_POINT_SIZE);
            }

            let layered = layer.is_some();
            if !layered {
                self.draw_meshes(gl, &matrix);
            }
            self.use_flat(gl, &matrix);
            draw_buffer(gl, &self.triangles, glow::TRIANGLES);
            // Pictures lie on the ground among the opaque fills.
            self.images
                .draw(gl, &matrix, BillboardAxes::facing(&view_proj));
            gl.use_program(Some(self.flat));
            // Translucent fills after everything opaque and without writing depth, so that
            // neither an opaque fill drawn later nor the lines on them are hidden. Crowded,
            // they go in the half-resolution layer, on the ground and under the bodies.
            gl.depth_mask(false);
            match layer {
                Some(layer) => {
                    let translucent = &self.translucent;
                    layer.draw(gl, || draw_buffer(gl, translucent, glow::TRIANGLES));
                }
                None => draw_buffer(gl, &self.translucent, glow::TRIANGLES),
            }
            gl.depth_mask(true);
            if layered {
                self.draw_meshes(gl, &matrix);
                self.use_flat(gl, &matrix);
            }
            draw_buffer(gl, &self.lines, glow::LINES);
            draw_buffer(gl, &self.points, glow::POINTS);

            gl.bind_vertex_array(None);
            gl.use_program(None);
            gl.disable(glow::DEPTH_TEST);
        }
    }

    /// Draws the lit meshes (bodies, walls, skins).
    ///
    /// # Safety
    /// The caller holds the current context.
    unsafe fn draw_meshes(&self, gl: &glow::Context, matrix: &[f32; 16]) {
        // SAFETY: the program and buffer belong to this context; uniforms match the shader.
        unsafe {
            gl.use_program(Some(self.lit));
            gl.uniform_matrix_4_f32_slice(
                gl.get_uniform_location(self.lit, "u_view_proj").as_ref(),
                false,
                matrix,
            );
            let light = self.lighting.direction.normalize_or_zero();
            gl.uniform_3_f32(
                gl.get_uniform_location(self.lit, "u_light_dir").as_ref(),
                light.x,
                light.y,
                light.z,
            );
            gl.uniform_1_f32(
                gl.get_uniform_location(self.lit, "u_ambient").as_ref(),
                self.lighting.ambient,
            );
            draw_buffer(gl, &self.mesh, glow::TRIANGLES);
        }
    }

    /// Binds the flat program for lines, points and fills, with its uniforms.
    ///
    /// # Safety
    /// The caller holds the current context.
    unsafe fn use_flat(&self, gl: &glow::Context, matrix: &[f32; 16]) {
        // SAFETY: the program belongs to this context; uniforms match the shader.
        unsafe {
            gl.use_program(Some(self.flat));
            gl.uniform_matrix_4_f32_slice(
                gl.get_uniform_location(self.flat, "u_view_proj").as_ref(),
                false,
                matrix,
            );
            gl.uniform_1_f32(
                gl.get_uniform_location(self.flat, "u_point_size").as_ref(),
                self.point_size,
            );
        }
    }

    /// Frees the GL objects.
    pub fn destroy(&mut self, gl: &glow::Context) {
        self.images.destroy(gl);
        if let Some(layer) = self.fill_layer.as_mut() {
            layer.destroy(gl);
        }
        // SAFETY: objects belong to this context and are not used afterwards.
        unsafe {
            gl.delete_program(self.flat);
            gl.delete_program(self.lit);
            for b in [
                &self.lines,
                &self.points,
                &self.triangles,
                &self.translucent,
                &self.mesh,
            ] {
                gl.delete_vertex_array(b.vao);
                gl.delete_buffer(b.vbo);
            }
        }
    }
}

unsafe fn program(
    gl: &glow::Context,
    header: &str,
    vertex: &str,
    fragment: &str,
) -> Result<glow::Program, RendererError> {
    // SAFETY: the caller holds a current context.
    unsafe {
        link_program(
            gl,
            &format!("{header}{vertex}"),
            &format!("{header}{fragment}"),
        )
        .map_err(RendererError)
    }
}

/// Shares the renderer between the UI thread's paint callbacks.
pub type SharedRenderer = Arc<std::sync::Mutex<Option<SceneRenderer>>>;
