//! `libpv3d_image`: a picture file lying on the ground, optionally through a chain of
//! kernels, with a label under it — a floor plan under the robots, or one photograph under
//! several filters side by side (`configs/kernels.pv3d.xml`).
//!
//! Parameters: `file` (PNG or JPEG, relative to the composition; required); `centre` (`0 0`,
//! m); `width` (4 m; the height follows the picture's proportions); `height` (0 m above the
//! ground); `sampling` (`linear`, or `nearest` for sharp pixels); `label` (the chain's
//! kernels, or "original"; empty for none); any number of `<filter>` kernels
//! (`framework::scene::filter_config`), radii in pixels.

mod load;

use glam::{Affine3A, Vec2, Vec3};

use framework::config::{ConfigValueError, Param, PluginConfig};
use framework::plugin::{Plugin, PluginContext};
use framework::registry::Metadata;
use framework::scene::filter_config::read_filter_chain;
use framework::scene::{ImageQuad, NodeId, Object3D, Rgba, Sampling};

pub use load::{LoadError, load_picture};

/// How far below the picture its label's baseline sits, as a share of the picture's height:
/// labels are drawn above their point, so this leaves a line of text between.
const LABEL_GAP: f32 = 0.12;

pub struct ImagePlugin {
    config: PluginConfig,
    node: NodeId,
    summary: String,
}

impl ImagePlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A picture file on the ground, optionally through a chain of GLSL kernels (the paper's Fig. 6f).",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let fail = |message: String| ConfigValueError {
            origin: config
                .param("file")
                .map_or(config.origin.clone(), |p| p.origin.clone()),
            library: config.library.clone(),
            param: "file".into(),
            message,
        };
        let path = config
            .path("file")
            .ok_or_else(|| fail("a picture file is needed: <file>picture.png</file>".into()))?;
        let pixels = load_picture(&path).map_err(|e| fail(e.to_string()))?;
        let centre = config.numbers("centre", 2)?.unwrap_or(vec![0.0, 0.0]);
        let width = config.number("width", 4.0, 0.01..=10_000.0)? as f32;
        let height = config.number("height", 0.0, -100.0..=100.0)? as f32;
        let sampling = match config.text("sampling").unwrap_or("linear") {
            "linear" => Sampling::Linear,
            "nearest" => Sampling::Nearest,
            other => {
                let param = config.param("sampling").cloned().unwrap_or_default();
                return Err(sampling_error(&config, &param, other));
            }
        };
        let filters = read_filter_chain(&config, "filter", |pixels| pixels)?;

        let aspect = pixels.height() as f32 / pixels.width() as f32;
        let size = Vec2::new(width, width * aspect);
        let summary = format!(
            "{} × {} pixels, {:.2} × {:.2} m",
            pixels.width(),
            pixels.height(),
            size.x,
            size.y
        );
        let label = match config.param("label") {
            Some(p) => p.text.trim().to_string(),
            None if filters.is_empty() => "original".into(),
            None => filters.describe(),
        };
        let mut quad = ImageQuad::new(pixels, (-size / 2.0).extend(0.0), size, sampling);
        quad.filters = filters;
        let mut node = Object3D::new(config.titled("Image"));
        node.transform =
            Affine3A::from_translation(Vec3::new(centre[0] as f32, centre[1] as f32, height));
        if !label.is_empty() {
            let at = Vec3::new(-size.x / 2.0, -size.y / 2.0 * (1.0 + 2.0 * LABEL_GAP), 0.0);
            node.geometry.label(at, label, Rgba::WHITE);
        }
        node.geometry.images.push(quad);
        let node = ctx.scene.add(node);
        Ok(Box::new(ImagePlugin {
            config,
            node,
            summary,
        }))
    }
}

fn sampling_error(config: &PluginConfig, param: &Param, found: &str) -> ConfigValueError {
    ConfigValueError {
        origin: if param.origin.is_empty() {
            config.origin.clone()
        } else {
            param.origin.clone()
        },
        library: config.library.clone(),
        param: "sampling".into(),
        message: format!("expected linear or nearest, found {found:?}"),
    }
}

impl Plugin for ImagePlugin {
    fn save(&self) -> PluginConfig {
        self.config.clone()
    }

    fn title(&self) -> String {
        match (self.config.id.as_str(), self.config.text("file")) {
            ("", Some(file)) => format!("Image {file}"),
            (id, Some(file)) => format!("Image {id}: {file}"),
            (_, None) => "Image".into(),
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {
        ui.label(&self.summary);
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.remove(self.node);
    }
}
