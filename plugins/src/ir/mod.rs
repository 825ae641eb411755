//! `libpv3d_ir`: infrared rangers as narrow cones around their robot, each as long as its
//! reading — the sonar's drawing ([`crate::sonar::cones`]) with an infrared beam's defaults.
//!
//! Parameters: `<parentNode interface="position2d"/>` (the robot); `visible` (1); the cone
//! parameters of [`crate::sonar::cone_params`], with an infrared's defaults where absent:
//! `color` #e6783c, `coneAngle` 5°, `maxConeLength` 2 m. The rangers' poses come from the
//! `ir` pose request; until it answers (or if it fails) they are assumed evenly spaced on a
//! ring, as the sonar's are.

use player_proto::interfaces::ir::{Ir, IrData, IrPose};

use crate::sonar::cone_params::cone_style_from_config;
use crate::sonar::cones::ConeStyle;
use crate::sonar::ring::ConeRing;
use framework::config::{ConfigValueError, PluginConfig};
use framework::device::{Awaited, LastTaken};
use framework::parent_link::ParentLink;
use framework::plugin::{Plugin, PluginContext};
use framework::registry::Metadata;
use framework::scene::{NodeId, Object3D, Rgba};

/// An infrared beam's look where the composition does not say.
const IR_COLOR: Rgba = Rgba::rgb(230, 120, 60);
const IR_CONE_DEGREES: f32 = 5.0;
const IR_MAX_LENGTH: f32 = 2.0;
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
    ring: ConeRing,
    node: NodeId,
    parent: ParentLink,
    poses_reply: Awaited<IrPose>,
    taken: LastTaken,
}

impl IrPlugin {
    pub const METADATA: Metadata =
        crate::standard_metadata("Infrared rangers' readings as narrow cones around their robot.");

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let ring = ConeRing::new(ir_cone_style(&config)?, &config, MAX_RANGERS)?;
        let mut object = Object3D::new(config.titled("ir"));
        object.tags.push("ir".into());
        object.visible = ring.visible();
        let node = ctx.scene.add(object);
        Ok(Box::new(IrPlugin {
            parent: ParentLink::from_config(&config),
            poses_reply: Awaited::fetch(ctx.device, Ir::REQ_POSE),
            config,
            ring,
            node,
            taken: LastTaken::default(),
        }))
    }

    fn take_poses(&mut self) {
        match self.poses_reply.take() {
            Some(Ok(reply)) => self.ring.adopt_poses(&reply.poses),
            Some(Err(e)) => {
                tracing::info!(plugin = %self.config.id, "no ir poses ({e}); assumed evenly spaced");
            }
            None => {}
        }
    }
}

impl Plugin for IrPlugin {
    fn save(&self) -> PluginConfig {
        let mut config = self.config.clone();
        self.ring.save_into(&mut config);
        config
    }

    fn title(&self) -> String {
        self.config.titled("IR")
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.parent.attach(self.node, ctx);
        self.take_poses();
        if let Some((data, sample)) = self.taken.newest_of::<IrData>(ctx.device) {
            self.ring.take_ranges(&data.ranges, sample.received);
        }
        self.ring.redraw_if_needed(ctx.scene, self.node);
    }

    fn ui(&mut self, ui: &mut egui::Ui, ctx: &mut PluginContext<'_>) {
        self.ring.ui(ui, ctx.now, "rangers");
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.remove(self.node);
    }
}
