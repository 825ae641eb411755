//! `libpv3d_camera`: a camera's image in its own window (raw formats and JPEG), with its frame
//! rate and age.
//!
//! Parameters (all optional): `showWindow` (1) — whether the window is open; the person can
//! close and reopen it from the plugin's panel, and the choice is written back on save;
//! `<filter>` kernels (radii in pixels) — the window shows the frame through them ([`filtered`]).
//! Frames are decoded in [`Plugin::update`] only when a new one arrives ([`frames`]); the
//! window is drawn by [`Plugin::windows`] through egui, never OpenGL.

pub mod filtered;
pub mod frames;
pub mod window;

use filtered::FrameFilter;
use frames::{CameraFrames, Offered};
use framework::config::{ConfigValueError, PluginConfig};
use framework::plugin::{Plugin, PluginContext};
use framework::registry::Metadata;
use player_proto::interfaces::camera::Camera;
use window::{CameraWindow, Picture};

pub struct CameraPlugin {
    config: PluginConfig,
    frames: CameraFrames,
    window: CameraWindow,
    show_window: bool,
    filter: Option<FrameFilter>,
}

impl CameraPlugin {
    pub const METADATA: Metadata =
        crate::standard_metadata("A camera's images, raw or JPEG, in a window of their own.");

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let show_window = config.bool("showWindow", true)?;
        let filter = FrameFilter::from_config(&config, ctx)?;
        Ok(Box::new(CameraPlugin {
            config,
            frames: CameraFrames::default(),
            window: CameraWindow::default(),
            show_window,
            filter,
        }))
    }

    /// The frames received so far (for the panel and for tests).
    pub fn frames(&self) -> &CameraFrames {
        &self.frames
    }
}

impl Plugin for CameraPlugin {
    fn save(&self) -> PluginConfig {
        let mut config = self.config.clone();
        config.set_bool("showWindow", self.show_window);
        config
    }

    fn title(&self) -> String {
        self.config.titled("Camera")
    }

    /// Takes the newest frame. The scene does not change: the image lives in its window.
    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        let Some(sample) = ctx.device.and_then(|d| d.latest(Camera::DATA_STATE.kind())) else {
            return;
        };
        match self.frames.offer(&sample) {
            Offered::Failed(reason) => {
                tracing::debug!(plugin = %self.config.id, "camera frame not shown: {reason}");
            }
            Offered::Decoded => {
                if let (Some(filter), Some(image)) = (&self.filter, self.frames.image()) {
                    filter.offer(image, ctx);
                }
            }
            _ => {}
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, ctx: &mut PluginContext<'_>) {
        ui.label(self.frames.summary(ctx.now));
        ui.checkbox(&mut self.show_window, "show image window");
    }

    fn windows(&mut self, egui_ctx: &egui::Context, ctx: &mut PluginContext<'_>) {
        let id = format!("{}#{}", self.config.id, self.config.origin);
        let title = self.title();
        if let Some(filter) = &mut self.filter {
            let filtered = filter.latest();
            let picture = Picture {
                image: filtered.as_ref().map(|(_, image)| &**image),
                version: filtered.as_ref().map_or(0, |(generation, _)| *generation),
                summary: format!("{} — {}", self.frames.summary(ctx.now), filter.describe()),
            };
            self.window
                .show_picture(egui_ctx, &id, &title, picture, &mut self.show_window);
            return;
        }
        self.window.show(
            egui_ctx,
            &id,
            &title,
            &self.frames,
            ctx.now,
            &mut self.show_window,
        );
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        if let Some(filter) = &self.filter {
            ctx.scene.remove(filter.node());
        }
    }
}
