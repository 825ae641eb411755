//! `libpv3d_ir`: infrared rangers as narrow cones around their robot, each as long as its
//! reading — the sonar's drawing ([`crate::sonar::cones`]) with an infrared beam's defaults.
//!
//! Parameters: `<parentNode interface="position2d"/>` (the robot); `visible` (1); the cone
//! parameters of [`crate::sonar::cone_params`], with an infrared's defaults where absent:
//! `color` #e6783c, `coneAngle` 5°, `maxConeLength` 2 m. The rangers' poses come from the
//! `ir` pose request; until it answers (or if it fails) they are assumed evenly spaced on a
//! ring, as the sonar's are.

use std::time::Instant;

use player_proto::interfaces::ir::{Ir, IrData, IrPose};

use crate::sonar::cone_params::{cone_style_from_config, cone_style_ui, write_cone_style};
use crate::sonar::cones::{ConeStyle, Transducer, cone_geometry, evenly_spaced};
use framework::config::{ConfigValueError, PluginConfig};
use framework::device::{Awaited, LastTaken};
use framework::parent_link::ParentLink;
use framework::plugin::{Metadata, Plugin, PluginContext};
use framework::scene::{NodeId, Object3D, Rgba, Scene};

/// An infrared beam's look where the composition does not say.
const IR_COLOR: Rgba = Rgba::rgb(230, 120, 60);
const IR_CONE_DEGREES: f32 = 5.0;
const IR_MAX_LENGTH: f32 = 2.0;
/// Radius of the ring the rangers are assumed on while their poses are unknown, m.
const ASSUMED_RING_RADIUS: f32 = 0.2;
/// Readings kept from one message: Player's own limit on infrared rangers.
const MAX_RANGERS: usize = 32;

/// The cone parameters, with an infrared's defaults for those the composition leaves out.
fn ir_cone_style(config: &PluginConfig) -> Result<ConeStyle, ConfigValueError> {
    let mut style = cone_style_from_config(config)?;
    if config.param("color").is_none() {
        style.color = IR_COLOR;
    }
    if config.param("coneAngle").is_none() {
        style.width = IR_CONE_DEGREES.to_radians();
    }
    if config.param("maxConeLength").is_none() {
        style.max_length = IR_MAX_LENGTH;
    }
    Ok(style)
}

pub struct IrPlugin {
    config: PluginConfig,
    style: ConeStyle,
    visible: bool,
    node: NodeId,
    parent: ParentLink,
    poses_reply: Awaited<IrPose>,
    /// Whether the poses came from the device (else assumed).
    poses_known: bool,
    rangers: Vec<Transducer>,
    ranges: Vec<f32>,
    taken: LastTaken,
    received: Option<Instant>,
    redraw_needed: bool,
}

impl IrPlugin {
    pub const METADATA: Metadata =
        crate::standard_metadata("Infrared rangers' readings as narrow cones around their robot.");

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let style = ir_cone_style(&config)?;
        let visible = config.bool("visible", true)?;
        let mut object = Object3D::new(config.titled("ir"));
        object.tags.push("ir".into());
        object.visible = visible;
        let node = ctx.scene.add(object);
        Ok(Box::new(IrPlugin {
            parent: ParentLink::from_config(&config),
            poses_reply: Awaited::fetch(ctx.device, Ir::REQ_POSE),
            config,
            style,
            visible,
            node,
            poses_known: false,
            rangers: Vec::new(),
            ranges: Vec::new(),
            taken: LastTaken::default(),
            received: None,
            redraw_needed: false,
        }))
    }

    fn take_poses(&mut self) {
        match self.poses_reply.take() {
            Some(Ok(reply)) => {
                self.rangers = reply
                    .poses
                    .iter()
                    .take(MAX_RANGERS)
                    .map(Transducer::from)
                    .collect();
                self.poses_known = true;
                self.redraw_needed = true;
            }
            Some(Err(e)) => {
                tracing::info!(plugin = %self.config.id, "no ir poses ({e}); assumed evenly spaced");
            }
            None => {}
        }
    }

    fn redraw(&mut self, scene: &mut Scene) {
        if !self.poses_known && self.rangers.len() != self.ranges.len() {
            self.rangers = evenly_spaced(self.ranges.len(), ASSUMED_RING_RADIUS);
        }
        let Some(object) = scene.get_mut(self.node) else {
            return;
        };
        cone_geometry(
            &self.rangers,
            &self.ranges,
            &self.style,
            &mut object.geometry,
        );
        object.visible = self.visible;
    }
}

impl Plugin for IrPlugin {
    fn save(&self) -> PluginConfig {
        let mut config = self.config.clone();
        write_cone_style(&self.style, &mut config);
        config.set_bool("visible", self.visible);
        config
    }

    fn title(&self) -> String {
        self.config.titled("IR")
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.parent.attach(self.node, ctx);
        self.take_poses();
        if let Some((data, sample)) = self.taken.newest_of::<IrData>(ctx.device) {
            self.ranges = data.ranges.iter().take(MAX_RANGERS).copied().collect();
            self.received = Some(sample.received);
            self.redraw_needed = true;
        }
        if self.redraw_needed {
            self.redraw_needed = false;
            self.redraw(ctx.scene);
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, ctx: &mut PluginContext<'_>) {
        match self.received {
            Some(at) => {
                let nearest = self
                    .ranges
                    .iter()
                    .copied()
                    .filter(|r| r.is_finite() && *r > 0.0)
                    .min_by(f32::total_cmp)
                    .map_or("no return".into(), |r| format!("nearest {r:.2} m"));
                ui.label(format!(
                    "{} rangers, {nearest}, {:.1} s old",
                    self.ranges.len(),
                    ctx.now.saturating_duration_since(at).as_secs_f32()
                ));
            }
            None => {
                ui.label("no readings yet");
            }
        }
        if !self.poses_known {
            ui.label("poses unknown: drawn evenly spaced");
        }
        let visible_before = self.visible;
        ui.checkbox(&mut self.visible, "visible");
        if cone_style_ui(ui, &mut self.style) || visible_before != self.visible {
            self.redraw_needed = true;
        }
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.remove(self.node);
    }
}
