//! The application: building the viewer from a composition, the world window's contents, the
//! 3D view widget, and running the UI in a window. (Offscreen: [`crate::headless`].)

pub mod builder;
pub mod command_line;
mod device_gone;
pub mod formula_textures;
pub mod frame_count;
pub mod frame_times;
pub mod framing;
pub mod listing;
pub mod status_panel;
pub mod timeline;
pub mod view3d;
pub mod viewer;
pub mod window;

pub use builder::{ViewerBuilder, ViewerParts};
pub use frame_count::FrameCount;
pub use view3d::{View3d, ViewInput};
pub use viewer::{EditError, Viewer};
pub use window::{RedrawPolicy, ScreenshotRequest, UiWaker, WindowOptions, run_window};
