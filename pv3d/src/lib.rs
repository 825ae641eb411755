//! Player Viewer 3D: the application composer and viewer.
//!
//! * [`composition`] — XML compositions: loading, includes, device masks, instantiation,
//!   writing back.
//! * [`render`] — camera, scene batching, the glow renderer.
//! * [`headless`] — drawing with no window: offscreen GL, the UI painted into it, screenshots.
//! * [`app`] — building the viewer from a composition, and its window.

pub mod app;
pub mod commands;
pub mod composition;
pub mod demo;
pub mod embedded_world;
pub mod headless;
pub mod render;
pub mod robots;
pub mod zenoh_robots;
