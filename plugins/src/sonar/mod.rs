//! `libpv3d_sonar`: a sonar ring as one cone per transducer, each as long as its reading,
//! attached to its robot.
//!
//! Parameters (all optional): `<parentNode interface="position2d" index="0"/>` — the device
//! whose scene node the cones hang below (same server); `visible` (1); and the cone parameters
//! of [`cone_params`]. The transducers' poses come from the sonar geometry request (or pushed
//! geometry data); until it answers, or if it fails, they are assumed evenly spaced on a ring.

pub mod cone_params;
pub mod cones;

use std::time::Instant;

use player_proto::interfaces::common::Pose3d;
use player_proto::interfaces::sonar::{Sonar, SonarData, SonarGeometry};

use cone_params::{cone_style_from_config, cone_style_ui, write_cone_style};
use cones::{ConeStyle, Transducer, cone_geometry, evenly_spaced};
use framework::config::{ConfigValueError, PluginConfig};
use framework::device::{Awaited, LastTaken};
use framework::parent_link::ParentLink;
use framework::plugin::{Metadata, Plugin, PluginContext};
use framework::scene::{NodeId, Object3D, Scene};

/// Radius of the ring transducers are assumed on while their poses are unknown, m.
const ASSUMED_RING_RADIUS: f32 = 0.2;
/// Readings kept from one message: Player's own limit on sonar transducers.
const MAX_TRANSDUCERS: usize = 64;

/// Where the transducer poses came from, for the panel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum PoseSource {
    Assumed,
    Device,
}

pub struct SonarPlugin {
    config: PluginConfig,
    style: ConeStyle,
    visible: bool,
    node: NodeId,
    parent: ParentLink,
    geometry_reply: Awaited<SonarGeometry>,
    transducers: Vec<Transducer>,
    pose_source: PoseSource,
    ranges: Vec<f32>,
    ranges_taken: LastTaken,
    /// Geometry some drivers push as data.
    geometry_taken: LastTaken,
    received: Option<Instant>,
    redraw_needed: bool,
}

impl SonarPlugin {
    pub const METADATA: Metadata =
        crate::standard_metadata("A sonar ring's readings as cones around its robot.");

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let style = cone_style_from_config(&config)?;
        let visible = config.bool("visible", true)?;
        let parent = ParentLink::from_config(&config);
        let name = config.titled("sonar");
        let mut object = Object3D::new(name);
        object.tags.push("sonar".into());
        object.visible = visible;
        let node = ctx.scene.add(object);
        let geometry_reply = Awaited::fetch(ctx.device, Sonar::REQ_GET_GEOM);
        Ok(Box::new(SonarPlugin {
            config,
            style,
            visible,
            node,
            parent,
            geometry_reply,
            transducers: Vec::new(),
            pose_source: PoseSource::Assumed,
            ranges: Vec::new(),
            ranges_taken: LastTaken::default(),
            geometry_taken: LastTaken::default(),
            received: None,
            redraw_needed: false,
        }))
    }

    /// Takes the transducer poses from the geometry reply, once it has come.
    fn take_geometry_reply(&mut self) {
        let Some(outcome) = self.geometry_reply.take() else {
            return;
        };
        match outcome {
            Ok(g) => self.adopt_poses(&g.poses),
            Err(e) => {
                tracing::info!(plugin = %self.config.id, "no sonar geometry ({e}); transducers assumed evenly spaced");
            }
        }
    }

    fn adopt_poses(&mut self, poses: &[Pose3d]) {
        self.transducers = poses
            .iter()
            .take(MAX_TRANSDUCERS)
            .map(Transducer::from)
            .collect();
        self.pose_source = PoseSource::Device;
        self.redraw_needed = true;
    }

    fn take_ranges(&mut self, data: &SonarData, received: Instant) {
        self.ranges.clear();
        self.ranges
            .extend(data.ranges.iter().take(MAX_TRANSDUCERS).copied());
        self.received = Some(received);
        self.redraw_needed = true;
    }

    fn redraw(&mut self, scene: &mut Scene) {
        if self.pose_source == PoseSource::Assumed && self.transducers.len() != self.ranges.len() {
            self.transducers = evenly_spaced(self.ranges.len(), ASSUMED_RING_RADIUS);
        }
        let Some(object) = scene.get_mut(self.node) else {
            return;
        };
        cone_geometry(
            &self.transducers,
            &self.ranges,
            &self.style,
            &mut object.geometry,
        );
        object.visible = self.visible;
    }
}

impl Plugin for SonarPlugin {
    fn save(&self) -> PluginConfig {
        let mut config = self.config.clone();
        write_cone_style(&self.style, &mut config);
        config.set_bool("visible", self.visible);
        config
    }

    fn title(&self) -> String {
        self.config.titled("Sonar")
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.parent.attach(self.node, ctx);
        self.take_geometry_reply();
        if let Some((g, _)) = self.geometry_taken.newest_of::<SonarGeometry>(ctx.device) {
            self.adopt_poses(&g.poses);
        }
        if let Some((data, sample)) = self.ranges_taken.newest_of::<SonarData>(ctx.device) {
            self.take_ranges(&data, sample.received);
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
                    .min_by(f32::total_cmp);
                let nearest = nearest.map_or("no return".into(), |r| format!("nearest {r:.2} m"));
                ui.label(format!(
                    "{} transducers, {nearest}, {:.1} s old",
                    self.ranges.len(),
                    ctx.now.saturating_duration_since(at).as_secs_f32()
                ));
            }
            None => {
                ui.label("no readings yet");
            }
        }
        if self.pose_source == PoseSource::Assumed {
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
        ctx.anchors.withdraw(self.node);
        ctx.scene.remove(self.node);
    }
}
