//! Drawing with no window and no X server, for `--headless` runs (recordings, scripts,
//! measurements), `--screenshot` on a machine without a display, and the tests: an EGL
//! context over an offscreen framebuffer ([`HeadlessGl`]), the viewer's egui UI painted into
//! it ([`HeadlessUi`]), the screenshot run that writes the last frame ([`write_screenshot`])
//! and the run that only runs ([`run_headless`]). The same UI code and renderer as the
//! window's draw the pixels.

mod gl;
mod run;
mod screenshot;
mod ui;

pub use gl::{HeadlessError, HeadlessGl};
pub use run::{HeadlessRun, HeadlessSummary, run_headless};
pub use screenshot::{ScreenshotError, ScreenshotRun, as_shown, write_screenshot};
pub use ui::HeadlessUi;
