//! The application: the world window's contents, the 3D view widget, and running the UI in a
//! window or offscreen.

pub mod composer;
pub mod headless_ui;
pub mod plugin_config;
pub mod status_panel;
pub mod view3d;
pub mod viewer;
pub mod window;

pub use composer::Composer;
pub use headless_ui::HeadlessUi;
pub use view3d::{View3d, ViewInput};
pub use viewer::Viewer;
pub use window::{
    RedrawPolicy, ScreenshotRequest, UiWaker, WindowOptions, headless_screenshot, run_window,
};
