//! The scene renderer's vertex buffers: one per primitive kind, laid out for the flat program
//! (`GpuVertex`) or the lit one (`GpuMeshVertex`), filled when the scene changed and drawn
//! whole.

use eframe::glow::{self, HasContext};

use super::gl_error::{GlError, RendererError};
use super::gpu_vertex::{GpuMeshVertex, GpuVertex};

/// A vertex buffer and its layout.
pub(super) struct Buffer {
    pub(super) vao: glow::VertexArray,
    pub(super) vbo: glow::Buffer,
    pub(super) count: i32,
}

pub(super) unsafe fn new_buffer(gl: &glow::Context) -> Result<Buffer, RendererError> {
    // SAFETY: the caller holds a current context.
    unsafe {
        let vao = gl.create_vertex_array().map_err(GlError::from)?;
        let vbo = gl.create_buffer().map_err(GlError::from)?;
        gl.bind_vertex_array(Some(vao));
        gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
        Ok(Buffer { vao, vbo, count: 0 })
    }
}

pub(super) unsafe fn flat_buffer(gl: &glow::Context) -> Result<Buffer, RendererError> {
    // SAFETY: the caller holds a current context; the layout matches GpuVertex.
    unsafe {
        let buffer = new_buffer(gl)?;
        let stride = std::mem::size_of::<GpuVertex>() as i32;
        gl.enable_vertex_attrib_array(0);
        gl.vertex_attrib_pointer_f32(0, 3, glow::FLOAT, false, stride, 0);
        gl.enable_vertex_attrib_array(1);
        gl.vertex_attrib_pointer_f32(1, 4, glow::UNSIGNED_BYTE, true, stride, 12);
        gl.bind_vertex_array(None);
        Ok(buffer)
    }
}

pub(super) unsafe fn mesh_buffer(gl: &glow::Context) -> Result<Buffer, RendererError> {
    // SAFETY: the caller holds a current context; the layout matches GpuMeshVertex.
    unsafe {
        let buffer = new_buffer(gl)?;
        let stride = std::mem::size_of::<GpuMeshVertex>() as i32;
        gl.enable_vertex_attrib_array(0);
        gl.vertex_attrib_pointer_f32(0, 3, glow::FLOAT, false, stride, 0);
        gl.enable_vertex_attrib_array(1);
        gl.vertex_attrib_pointer_f32(1, 3, glow::FLOAT, false, stride, 12);
        gl.enable_vertex_attrib_array(2);
        gl.vertex_attrib_pointer_f32(2, 4, glow::UNSIGNED_BYTE, true, stride, 24);
        gl.bind_vertex_array(None);
        Ok(buffer)
    }
}

pub(super) unsafe fn fill(gl: &glow::Context, buffer: &mut Buffer, bytes: &[u8], count: usize) {
    // SAFETY: the caller holds a current context and the buffer belongs to it.
    unsafe {
        gl.bind_buffer(glow::ARRAY_BUFFER, Some(buffer.vbo));
        gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, bytes, glow::DYNAMIC_DRAW);
        gl.bind_buffer(glow::ARRAY_BUFFER, None);
    }
    buffer.count = i32::try_from(count).unwrap_or(i32::MAX);
}

pub(super) unsafe fn draw_buffer(gl: &glow::Context, buffer: &Buffer, mode: u32) {
    if buffer.count == 0 {
        return;
    }
    // SAFETY: the caller holds a current context with the matching program bound.
    unsafe {
        gl.bind_vertex_array(Some(buffer.vao));
        gl.draw_arrays(mode, 0, buffer.count);
    }
}
