//! Player Viewer 3D: the application composer and viewer.
//!
//! * [`composition`] — XML compositions: loading, includes, device masks, instantiation,
//!   writing back.
//! * [`render`] — camera, scene batching, the glow renderer, headless GL.

pub mod app;
pub mod composition;
pub mod demo;
pub mod embedded_world;
pub mod render;
pub mod robots;
