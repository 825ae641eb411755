//! Drawing: the orbit camera, the scene flattened into vertex batches (with detail finer than
//! a pixel merged), and our glow renderer, with the scene's pictures as textured quads and
//! their filter chains run as GPU kernels. Drawing with no window lives in [`crate::headless`].

pub mod batch;
pub mod billboard;
pub mod camera;
pub mod fill_layer;
pub mod filtered_pictures;
mod gl_buffers;
pub mod gl_error;
pub mod gl_renderer;
pub mod gl_state;
pub mod gpu_vertex;
pub mod grid_mipmaps;
pub mod image_quads;
pub mod kernels;
pub mod screen_detail;
pub mod shader;
pub mod texture;
pub mod virtual_views;

pub use batch::{BatchedImage, BatchedView, SceneBatch};
pub use billboard::BillboardAxes;
pub use camera::{OrbitCamera, Projection};
pub use filtered_pictures::PictureFilters;
pub use gl_renderer::{FILLS_IN_LAYER_FROM, Lighting, POINT_SIZE_PX, SceneRenderer};
pub use screen_detail::{ScreenDetail, Simplifier};
pub use virtual_views::{ViewTargets, view_projection};
