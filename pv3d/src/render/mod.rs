//! Drawing: the orbit camera, the scene flattened into vertex batches (with detail finer than
//! a pixel merged), and our glow renderer. Drawing with no window lives in [`crate::headless`].

pub mod batch;
pub mod camera;
pub mod gl_renderer;
pub mod screen_detail;

pub use batch::SceneBatch;
pub use camera::{OrbitCamera, Projection};
pub use gl_renderer::{Lighting, POINT_SIZE_PX, SceneRenderer};
pub use screen_detail::{ScreenDetail, Simplifier};
