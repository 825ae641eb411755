//! The application: the world window's contents, the 3D view widget, and running the UI in a
//! window or offscreen.

pub mod headless_ui;
pub mod status_panel;
pub mod timeline;
pub mod view3d;
pub mod viewer;
pub mod window;

pub use headless_ui::HeadlessUi;
pub use view3d::{View3d, ViewInput};
pub use viewer::Viewer;
pub use window::{
    RedrawPolicy, ScreenshotRequest, UiWaker, WindowOptions, headless_screenshot, run_window,
};
