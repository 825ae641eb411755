//! Drawing with no window and no X server, for `--screenshot` on a machine without a display
//! and for the tests: an EGL context over an offscreen framebuffer ([`HeadlessGl`]), the
//! viewer's egui UI painted into it ([`HeadlessUi`]), and the screenshot run that writes the
//! last frame ([`write_screenshot`]). The same UI code and renderer as the window's draw the
//! pixels.

mod gl;
mod screenshot;
mod ui;

pub use gl::{HeadlessError, HeadlessGl};
pub use screenshot::{ScreenshotError, ScreenshotRun, write_screenshot};
pub use ui::HeadlessUi;
