//! Drawing: the orbit camera, the scene flattened into vertex batches (with detail finer than
//! a pixel merged), our glow renderer, and an offscreen (headless) GL context for screenshots.

pub mod batch;
pub mod camera;
pub mod gl_renderer;
pub mod headless;
pub mod screen_detail;

pub use batch::SceneBatch;
pub use camera::{OrbitCamera, Projection};
pub use gl_renderer::{Lighting, POINT_SIZE_PX, SceneRenderer};
pub use headless::{HeadlessError, HeadlessGl};
pub use screen_detail::{ScreenDetail, Simplifier};
