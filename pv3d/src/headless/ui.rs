//! Running the viewer's egui UI offscreen: the same UI code and renderer as the window, painted
//! by egui_glow into a headless framebuffer and read back as an image.

use eframe::egui;
use eframe::egui_glow;
use image::RgbaImage;

use super::gl::{HeadlessError, HeadlessGl};

/// An offscreen egui screen of a fixed size.
pub struct HeadlessUi {
    gl: HeadlessGl,
    painter: egui_glow::Painter,
    ctx: egui::Context,
    start: std::time::Instant,
}

impl HeadlessUi {
    pub fn new(width: u32, height: u32) -> Result<HeadlessUi, HeadlessError> {
        let gl = HeadlessGl::new(width, height)?;
        let painter = egui_glow::Painter::new(gl.gl.clone(), "", None, false)
            .map_err(|e| HeadlessError::Egl(format!("egui painter: {e}")))?;
        Ok(HeadlessUi {
            gl,
            painter,
            ctx: egui::Context::default(),
            start: std::time::Instant::now(),
        })
    }

    pub fn context(&self) -> &egui::Context {
        &self.ctx
    }

    /// Runs one UI pass and paints it. egui lays some widgets out over two passes, so call
    /// this at least twice before reading a picture that should be settled.
    pub fn run(&mut self, mut ui_fn: impl FnMut(&mut egui::Ui)) {
        let (w, h) = self.gl.size();
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(w as f32, h as f32),
            )),
            time: Some(self.start.elapsed().as_secs_f64()),
            focused: true,
            ..Default::default()
        };
        let mut output = self.ctx.run_ui(input, |ui| ui_fn(ui));
        let primitives = self
            .ctx
            .tessellate(std::mem::take(&mut output.shapes), output.pixels_per_point);
        self.gl.bind();
        self.painter.clear([w, h], [0.0, 0.0, 0.0, 1.0]);
        self.painter.paint_and_update_textures(
            [w, h],
            output.pixels_per_point,
            &primitives,
            &mut output.textures_delta,
        );
    }

    /// Waits until everything painted so far is drawn (for timing).
    pub fn finish(&self) {
        // SAFETY: the context is current on this thread.
        unsafe { eframe::glow::HasContext::finish(&*self.gl.gl) };
    }

    /// The last painted frame.
    pub fn read_pixels(&self) -> RgbaImage {
        self.gl.read_pixels()
    }
}

impl Drop for HeadlessUi {
    fn drop(&mut self) {
        self.painter.destroy();
    }
}
