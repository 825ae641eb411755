//! Drawing: the orbit camera, the scene flattened into vertex batches, our glow renderer, and
//! an offscreen (headless) GL context for screenshots.

pub mod batch;
pub mod camera;
pub mod gl_renderer;
pub mod headless;

pub use batch::SceneBatch;
pub use camera::{OrbitCamera, Projection};
pub use gl_renderer::{Lighting, SceneRenderer};
pub use headless::{HeadlessError, HeadlessGl};
