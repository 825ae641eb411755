//! `libpv3d_sonar`: a sonar ring as one cone per transducer, each as long as its reading,
//! attached to its robot.
//!
//! Parameters (all optional): `<parentNode interface="position2d" index="0"/>` — the device
//! whose scene node the cones hang below (same server); `visible` (1); and the cone parameters
//! of [`cone_params`]. The transducers' poses come from the sonar geometry request (or pushed
//! geometry data); until it answers, or if it fails, they are assumed evenly spaced on a ring.

pub mod cone_params;
pub mod cones;
pub mod ring;

use player_proto::interfaces::sonar::{Sonar, SonarData, SonarGeometry};

use cone_params::cone_style_from_config;
use framework::config::{ConfigValueError, PluginConfig};
use framework::device::{Awaited, LastTaken};
use framework::parent_link::ParentLink;
use framework::plugin::{Plugin, PluginContext};
use framework::registry::Metadata;
use framework::scene::{NodeId, Object3D};
use ring::ConeRing;

/// Readings kept from one message: Player's own limit on sonar transducers.
const MAX_TRANSDUCERS: usize = 64;

pub struct SonarPlugin {
    config: PluginConfig,
    ring: ConeRing,
    node: NodeId,
    parent: ParentLink,
    geometry_reply: Awaited<SonarGeometry>,
    ranges_taken: LastTaken,
    /// Geometry some drivers push as data.
    geometry_taken: LastTaken,
}

impl SonarPlugin {
    pub const METADATA: Metadata =
        crate::standard_metadata("A sonar ring's readings as cones around its robot.");

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let ring = ConeRing::new(cone_style_from_config(&config)?, &config, MAX_TRANSDUCERS)?;
        let mut object = Object3D::new(config.titled("sonar"));
        object.tags.push("sonar".into());
        object.visible = ring.visible();
        let node = ctx.scene.add(object);
        Ok(Box::new(SonarPlugin {
            parent: ParentLink::from_config(&config),
            geometry_reply: Awaited::fetch(ctx.device, Sonar::REQ_GET_GEOM),
            config,
            ring,
            node,
            ranges_taken: LastTaken::default(),
            geometry_taken: LastTaken::default(),
        }))
    }

    /// Takes the transducer poses from the geometry reply, once it has come.
    fn take_geometry_reply(&mut self) {
        match self.geometry_reply.take() {
            Some(Ok(g)) => self.ring.adopt_poses(&g.poses),
            Some(Err(e)) => {
                tracing::info!(plugin = %self.config.id, "no sonar geometry ({e}); transducers assumed evenly spaced");
            }
            None => {}
        }
    }
}

impl Plugin for SonarPlugin {
    fn save(&self) -> PluginConfig {
        let mut config = self.config.clone();
        self.ring.save_into(&mut config);
        config
    }

    fn title(&self) -> String {
        self.config.titled("Sonar")
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.parent.attach(self.node, ctx);
        self.take_geometry_reply();
        if let Some((g, _)) = self.geometry_taken.newest_of::<SonarGeometry>(ctx.device) {
            self.ring.adopt_poses(&g.poses);
        }
        if let Some((data, sample)) = self.ranges_taken.newest_of::<SonarData>(ctx.device) {
            self.ring.take_ranges(&data.ranges, sample.received);
        }
        self.ring.redraw_if_needed(ctx.scene, self.node);
    }

    fn ui(&mut self, ui: &mut egui::Ui, ctx: &mut PluginContext<'_>) {
        self.ring.ui(ui, ctx.now, "transducers");
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.anchors.withdraw(self.node);
        ctx.scene.remove(self.node);
    }
}
