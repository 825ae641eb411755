//! The camera's own window: the newest frame as an egui texture, with its size, frame rate
//! and age. A separate native window (an immediate viewport) where the backend has them; a
//! window inside the main one otherwise (headless rendering, backends without viewports).
//! No OpenGL here: egui uploads the texture.

use std::borrow::Cow;
use std::time::{Duration, Instant};

use image::RgbaImage;
use image::imageops::FilterType;

use crate::camera::frames::CameraFrames;

/// How often an open window repaints to keep the age current while no frame comes.
const AGE_TICK: Duration = Duration::from_millis(250);

/// What a window shows: the picture (top row first), a number that changes with it, and a
/// line about it.
pub struct Picture<'a> {
    pub image: Option<&'a RgbaImage>,
    pub version: u64,
    pub summary: String,
}

/// The texture of one camera and which frame it holds.
#[derive(Default)]
pub struct CameraWindow {
    texture: Option<egui::TextureHandle>,
    uploaded_version: u64,
}

impl CameraWindow {
    /// Hands egui the newest picture if it is not the one already uploaded.
    fn upload(&mut self, ctx: &egui::Context, name: &str, image: Option<&RgbaImage>, version: u64) {
        let Some(image) = image else { return };
        if self.texture.is_some() && self.uploaded_version == version {
            return;
        }
        let max_side = ctx.input(|i| i.max_texture_side);
        let fitted = fit_within(image, max_side);
        let color = egui::ColorImage::from_rgba_unmultiplied(
            [fitted.width() as usize, fitted.height() as usize],
            fitted.as_raw(),
        );
        let options = egui::TextureOptions::LINEAR;
        match &mut self.texture {
            Some(texture) => texture.set(color, options),
            None => self.texture = Some(ctx.load_texture(name, color, options)),
        }
        self.uploaded_version = version;
    }

    /// Shows the window of a Player camera this pass. `open` turns false when the person
    /// closes it.
    pub fn show(
        &mut self,
        ctx: &egui::Context,
        id: &str,
        title: &str,
        frames: &CameraFrames,
        now: Instant,
        open: &mut bool,
    ) {
        let picture = Picture {
            image: frames.image().map(|i| &**i),
            version: frames.version(),
            summary: frames.summary(now),
        };
        self.show_picture(ctx, id, title, picture, open);
    }

    /// Shows the window of any picture (a virtual camera's, a filtered frame) this pass.
    pub fn show_picture(
        &mut self,
        ctx: &egui::Context,
        id: &str,
        title: &str,
        picture: Picture<'_>,
        open: &mut bool,
    ) {
        if !*open {
            return;
        }
        self.upload(ctx, id, picture.image, picture.version);
        let size = picture
            .image
            .map_or(egui::vec2(320.0, 240.0), |i| {
                egui::vec2(i.width() as f32, i.height() as f32)
            })
            .clamp(egui::vec2(300.0, 120.0), egui::vec2(1024.0, 768.0));
        let summary = picture.summary;
        let texture = self.texture.as_ref();
        let contents = |ui: &mut egui::Ui| {
            ui.label(&summary);
            if let Some(texture) = texture {
                ui.add(egui::Image::from_texture(texture).shrink_to_fit());
            }
        };
        if ctx.embed_viewports() {
            // No native windows (headless, or a backend without them): an egui window on the
            // right of the view, below the other cameras', with a close button.
            let slot = embedded_slot(ctx);
            let right_top = ctx.content_rect().right_top();
            let pos = right_top + egui::vec2(-12.0, 12.0 + slot as f32 * (size.y + 60.0));
            egui::Window::new(title)
                .id(egui::Id::unique(("pv3d-camera", id)))
                .open(open)
                .pivot(egui::Align2::RIGHT_TOP)
                .default_pos(pos)
                .default_size(size + egui::vec2(0.0, 30.0))
                .show(ctx, contents);
        } else {
            let builder = egui::ViewportBuilder::default()
                .with_title(title)
                .with_inner_size(size + egui::vec2(16.0, 40.0));
            let viewport = egui::ViewportId::from_hash_of(("pv3d-camera", id));
            let closed = ctx.show_viewport_immediate(viewport, builder, |ui, class| {
                if class == egui::ViewportClass::EmbeddedWindow {
                    contents(ui);
                } else {
                    egui::CentralPanel::default().show(ui, contents);
                }
                ui.input(|i| i.viewport().close_requested())
            });
            if closed {
                *open = false;
            }
        }
        ctx.request_repaint_after(AGE_TICK);
    }
}

/// Which of this pass's embedded camera windows this one is (0 for the first shown), so that
/// each first appears below the previous one instead of on top of it.
fn embedded_slot(ctx: &egui::Context) -> usize {
    let pass = ctx.cumulative_pass_nr();
    ctx.data_mut(|d| {
        let counter =
            d.get_temp_mut_or_default::<(u64, usize)>(egui::Id::unique("pv3d-camera-slots"));
        if counter.0 != pass {
            *counter = (pass, 0);
        }
        counter.1 += 1;
        counter.1 - 1
    })
}

/// The image scaled down (keeping its aspect) so that neither side exceeds `max_side`, the
/// largest texture the backend takes; borrowed as it is when it already fits.
pub fn fit_within(image: &RgbaImage, max_side: usize) -> Cow<'_, RgbaImage> {
    let (w, h) = (image.width() as usize, image.height() as usize);
    let longest = w.max(h);
    if longest <= max_side || max_side == 0 {
        return Cow::Borrowed(image);
    }
    let scale = max_side as f64 / longest as f64;
    let nw = ((w as f64 * scale).floor() as u32).clamp(1, max_side as u32);
    let nh = ((h as f64 * scale).floor() as u32).clamp(1, max_side as u32);
    Cow::Owned(image::imageops::resize(image, nw, nh, FilterType::Triangle))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_larger_than_a_texture_are_scaled_down_keeping_their_aspect() {
        let image = RgbaImage::new(4096, 1024);
        let fitted = fit_within(&image, 2048);
        assert_eq!((fitted.width(), fitted.height()), (2048, 512));
        let small = RgbaImage::new(640, 480);
        assert!(matches!(fit_within(&small, 2048), Cow::Borrowed(_)));
    }
}
