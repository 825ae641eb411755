//! `--screenshot` with no window: the viewer runs offscreen for a while, as it would in a
//! window, and its last frame is written as a PNG. (A window takes its own screenshot, in
//! [`crate::app::window`].)

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use image::RgbaImage;

use super::gl::HeadlessError;
use super::run::paint_until;
use super::ui::HeadlessUi;
use crate::app::Viewer;

/// How the offscreen run that ends in a screenshot goes.
#[derive(Debug, Clone, Copy)]
pub struct ScreenshotRun {
    /// The picture's size in pixels.
    pub size: (u32, u32),
    /// How long the composition runs before the picture is taken.
    pub after: Duration,
    /// How often the viewer takes new data meanwhile, as a window's redraw interval.
    pub interval: Duration,
}

/// Why no screenshot was written.
#[derive(Debug, thiserror::Error)]
pub enum ScreenshotError {
    #[error(transparent)]
    Gl(#[from] HeadlessError),
    #[error("writing {path}: {source}")]
    Write {
        path: PathBuf,
        source: image::ImageError,
    },
}

/// Runs the viewer offscreen as `run` says and returns the last frame.
fn render_after(viewer: &mut Viewer, run: &ScreenshotRun) -> Result<RgbaImage, HeadlessError> {
    let mut ui = HeadlessUi::new(run.size.0, run.size.1)?;
    paint_until(
        viewer,
        &mut ui,
        Instant::now(),
        Some(run.after),
        run.interval,
    );
    // Two more passes so that layouts settle with the final data.
    ui.run(|ui| viewer.ui(ui));
    ui.run(|ui| viewer.ui(ui));
    Ok(ui.read_pixels())
}

/// Makes RGBA pixels opaque, as a window shows its framebuffer: what blending left in the
/// alpha channel is no part of the picture (a PNG keeping it looks washed out over white).
pub fn as_shown(rgba: &mut [u8]) {
    for pixel in rgba.chunks_exact_mut(4) {
        pixel[3] = u8::MAX;
    }
}

/// Runs the viewer offscreen as `run` says and writes its last frame to `path` (PNG).
pub fn write_screenshot(
    viewer: &mut Viewer,
    run: &ScreenshotRun,
    path: &Path,
) -> Result<(), ScreenshotError> {
    let mut image = render_after(viewer, run)?;
    as_shown(&mut image);
    image.save(path).map_err(|source| ScreenshotError::Write {
        path: path.to_path_buf(),
        source,
    })
}
