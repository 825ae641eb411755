//! `libpv3d_formula`: a LaTeX formula floating next to a robot, turned towards the viewer
//! however the robot turns, so that a class reads `$v = \omega r$` beside the robot it
//! describes from any side.
//!
//! Parameters: `text` (the formula between dollar signs; required), `parentNode` (the robot
//! it follows, when made in a robot's device handler; none = fixed), `offset` (`x y z`, m from
//! the robot or the world's origin; `0.4 0.4 0.6`), `style` (`picture`: a billboard in the
//! world, `pixelSize` m a typeset pixel spans (0.008), at `dpi` (180), growing as the camera
//! comes closer; `label`: a scene label the viewer typesets at the size of its text, the same
//! on screen at any distance), `color` (white), `title` (the item tree's; `Formula` and the
//! text).

use framework::config::{ConfigValueError, PluginConfig};
use framework::plugin::{AnchorKey, Plugin, PluginContext};
use framework::registry::Metadata;
use framework::scene::{ImageQuad, NodeId, Object3D, Rgba, Sampling};
use glam::{Affine3A, Vec2, Vec3};

use super::typeset::{DEFAULT_DPI, MAX_DPI, typeset};

const DEFAULT_OFFSET: [f64; 3] = [0.4, 0.4, 0.6];
const DEFAULT_PIXEL_SIZE_M: f64 = 0.008;
/// A robot moving less than this keeps its label where it is: no redraw for jitter, m.
const FOLLOW_TOLERANCE_M: f32 = 1e-4;

pub struct FormulaPlugin {
    config: PluginConfig,
    node: NodeId,
    follow: Option<AnchorKey>,
    offset: Vec3,
}

impl FormulaPlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A LaTeX formula next to a robot or in the world, typeset without a TeX install.",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let error = |param: &str, message: String| ConfigValueError {
            origin: config
                .param(param)
                .map_or(config.origin.clone(), |p| p.origin.clone()),
            library: config.library.clone(),
            param: param.into(),
            message,
        };
        let text = config.text("text").ok_or_else(|| {
            error(
                "text",
                r"a formula is needed: <text>$v = \omega r$</text>".into(),
            )
        })?;
        let offset = config
            .numbers("offset", DEFAULT_OFFSET.len())?
            .unwrap_or(DEFAULT_OFFSET.to_vec());
        let pixel_size = config.number("pixelSize", DEFAULT_PIXEL_SIZE_M, 1e-5..=1.0)? as f32;
        let dpi = config.number("dpi", f64::from(DEFAULT_DPI), 1.0..=f64::from(MAX_DPI))? as u32;
        let colour = config.color("color", Rgba::WHITE)?;
        let as_label = match config.text("style").unwrap_or("picture") {
            "picture" => false,
            "label" => true,
            other => {
                return Err(error(
                    "style",
                    format!("expected picture or label, found {other:?}"),
                ));
            }
        };
        // Typeset here even for a label, so that a formula that does not parse stops the
        // plugin with the typesetter's message rather than showing as raw text.
        let pixels = typeset(text, colour, dpi).map_err(|e| error("text", e.to_string()))?;

        let offset = Vec3::new(offset[0] as f32, offset[1] as f32, offset[2] as f32);
        let mut object = Object3D::new(format!("Formula {text}"));
        object.tags.push("formula".into());
        object.transform = Affine3A::from_translation(offset);
        if as_label {
            object.geometry.label(Vec3::ZERO, text, colour);
        } else {
            // Its lower left corner at the node: the formula reads to the right of its point.
            let size = Vec2::new(pixels.width() as f32, pixels.height() as f32) * pixel_size;
            object.geometry.images.push(ImageQuad::billboard(
                pixels,
                Vec3::ZERO,
                Vec2::ZERO,
                size,
                Sampling::Linear,
            ));
        }
        let node = ctx.scene.add(object);
        let follow = match (config.param("parentNode"), &config.device) {
            (Some(p), Some(device)) => Some(AnchorKey {
                host: device.host.clone(),
                port: device.port,
                interface: p.attr("interface").unwrap_or("position2d").to_string(),
                index: p.attr("index").and_then(|i| i.parse().ok()).unwrap_or(0),
            }),
            _ => None,
        };
        Ok(Box::new(FormulaPlugin {
            config,
            node,
            follow,
            offset,
        }))
    }
}

impl Plugin for FormulaPlugin {
    fn save(&self) -> PluginConfig {
        self.config.clone()
    }

    /// `Formula $…$`: the item tree typesets the math at its end.
    fn title(&self) -> String {
        match self.config.text("title") {
            Some(title) => title.to_string(),
            None => format!("Formula {}", self.config.text("text").unwrap_or_default()),
        }
    }

    /// Follows the robot's position but not its heading: the renderer turns the formula to
    /// the viewer, the robot's heading must not.
    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        let Some(robot) = self.follow.as_ref().and_then(|k| ctx.anchors.find(k)) else {
            return;
        };
        let at = ctx
            .scene
            .world_transform(robot)
            .transform_point3(Vec3::ZERO)
            + self.offset;
        let current = ctx
            .scene
            .get(self.node)
            .map(|o| Vec3::from(o.transform.translation));
        if current.is_some_and(|c| c.distance(at) > FOLLOW_TOLERANCE_M)
            && let Some(object) = ctx.scene.get_mut(self.node)
        {
            object.transform = Affine3A::from_translation(at);
        }
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.remove(self.node);
    }
}
