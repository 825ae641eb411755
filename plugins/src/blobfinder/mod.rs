//! `libpv3d_blobfinder`: the colour blobs a blobfinder sees, as boxes in the blob colour on a
//! canvas the size of its image, in a window of their own, each with its id and range.
//!
//! Why its own window rather than drawing over the camera's: a blobfinder often has no camera
//! device beside it (Stage's has none), and where it has one, the two images need not match
//! in size or timing. A canvas of the blobfinder's own image size shows exactly what it
//! reports, with no coupling to another plugin.
//!
//! Parameters: `showWindow` (1); `canvasWidth` (320 px: the image is scaled to it, keeping its
//! aspect).

pub mod layout;

use egui::{Color32, Sense, Stroke, vec2};
use player_proto::interfaces::blobfinder::BlobfinderData;

use framework::config::{ConfigValueError, PluginConfig};
use framework::device::LastTaken;
use framework::plugin::{Plugin, PluginContext};
use framework::registry::Metadata;
use layout::blob_boxes;

/// The canvas's backdrop, and the width of a blob's outline.
const BACKDROP: Color32 = Color32::from_gray(24);
const OUTLINE: f32 = 2.0;
/// The canvas's aspect while no image size is known (4:3).
const DEFAULT_ASPECT: f32 = 0.75;

pub struct BlobfinderPlugin {
    config: PluginConfig,
    show_window: bool,
    canvas_width: f32,
    taken: LastTaken,
    blobs: Option<BlobfinderData>,
}

impl BlobfinderPlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A blobfinder's colour blobs as boxes over an image-sized canvas, with their ids and ranges, in a window of their own.",
    );

    pub fn create(
        config: PluginConfig,
        _ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        Ok(Box::new(BlobfinderPlugin {
            show_window: config.bool("showWindow", true)?,
            canvas_width: config.number("canvasWidth", 320.0, 40.0..=4096.0)? as f32,
            config,
            taken: LastTaken::default(),
            blobs: None,
        }))
    }

    /// The blobs last received (for tests and the panel).
    fn summary(&self) -> String {
        match &self.blobs {
            Some(d) => {
                let n = d.blobs.len();
                let noun = if n == 1 { "blob" } else { "blobs" };
                format!("{n} {noun} in {} × {} px", d.width, d.height)
            }
            None => "no blobs yet".into(),
        }
    }

    /// The canvas with its blobs, in all of `ui`'s width up to the configured one.
    fn canvas(&self, ui: &mut egui::Ui) {
        let aspect = match &self.blobs {
            Some(d) if d.width > 0 => d.height as f32 / d.width as f32,
            _ => DEFAULT_ASPECT,
        };
        let size = vec2(self.canvas_width, self.canvas_width * aspect);
        let (rect, _) = ui.allocate_exact_size(size, Sense::hover());
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, BACKDROP);
        let Some(data) = &self.blobs else { return };
        for blob in blob_boxes(data, rect) {
            painter.rect_stroke(
                blob.rect,
                0.0,
                Stroke::new(OUTLINE, blob.color),
                egui::StrokeKind::Inside,
            );
            painter.circle_filled(blob.centroid, OUTLINE, blob.color);
            painter.text(
                blob.rect.left_top(),
                egui::Align2::LEFT_BOTTOM,
                blob.caption,
                egui::FontId::proportional(11.0),
                blob.color,
            );
        }
    }
}

impl Plugin for BlobfinderPlugin {
    fn save(&self) -> PluginConfig {
        let mut config = self.config.clone();
        config.set_bool("showWindow", self.show_window);
        config
    }

    fn title(&self) -> String {
        self.config.titled("Blobfinder")
    }

    /// Takes the newest blobs; the scene does not change, they live in their window.
    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        if let Some((data, _)) = self.taken.newest_of::<BlobfinderData>(ctx.device) {
            self.blobs = Some(data);
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {
        ui.label(self.summary());
        ui.checkbox(&mut self.show_window, "show blob window");
    }

    fn windows(&mut self, egui_ctx: &egui::Context, _ctx: &mut PluginContext<'_>) {
        if !self.show_window {
            return;
        }
        let mut open = true;
        egui::Window::new(self.title())
            .id(egui::Id::unique((
                "pv3d-blobfinder",
                &self.config.id,
                &self.config.origin,
            )))
            .open(&mut open)
            .resizable(false)
            // Beside the view's right edge, clear of the item tree on the left.
            .pivot(egui::Align2::RIGHT_TOP)
            .default_pos(egui_ctx.content_rect().right_top() + egui::vec2(-12.0, 12.0))
            .show(egui_ctx, |ui| {
                ui.label(self.summary());
                self.canvas(ui);
            });
        self.show_window = open;
    }

    fn clean(&mut self, _ctx: &mut PluginContext<'_>) {}
}
