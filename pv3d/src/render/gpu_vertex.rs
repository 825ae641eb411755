//! The vertices as the GPU reads them, apart from the batch that fills them so that the
//! simplifying of lines ([`super::screen_detail`]), which the batch calls, can use them too.

use bytemuck::{Pod, Zeroable};

/// A coloured vertex as the GPU reads it: 16 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Pod, Zeroable)]
pub struct GpuVertex {
    pub pos: [f32; 3],
    pub color: [u8; 4],
}

/// A lit vertex as the GPU reads it: 28 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Pod, Zeroable)]
pub struct GpuMeshVertex {
    pub pos: [f32; 3],
    pub normal: [f32; 3],
    pub color: [u8; 4],
}
