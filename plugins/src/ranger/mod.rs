//! `libpv3d_ranger`: a ranger device — what Stage 4 serves for lasers and sonar rings —
//! drawn laser-like (a scan) or sonar-like (a cone per element), attached to its robot.
//!
//! Parameters (all optional): `<parentNode interface="position2d" index="0"/>`; `visible` (1);
//! the laser plugin's `drawPoints` (1), `drawLines` (0), `fillLaserCspace` (0),
//! `drawLaserCspace` (0), `color` (#ff5a3c for scans); and the cone parameters of
//! [`crate::sonar::cone_params`]. The device's pose and its elements' poses come from the
//! geometry request, the angles and maximum range from the config request — or from the data
//! when a driver sends them there (stamped ranges, geometry data). A scan's returns are shaded
//! by the intensities the device sends (`shadeIntensity`, 1), as Stage does after each scan.

mod shape;

use std::time::Instant;

use glam::{Affine3A, Quat, Vec3};
use player_proto::interfaces::common::Pose3d;
use player_proto::interfaces::ranger::{self, Ranger, RangerConfig, RangerGeometry};
use player_proto::message::Body;

pub use shape::{RangerData, RangerShape, ranger_geometry};

use crate::laser::ScanStyle;
use crate::sonar::cone_params::{cone_style_from_config, cone_style_ui, write_cone_style};
use crate::sonar::cones::{ConeStyle, Transducer};
use framework::config::{ConfigValueError, PluginConfig};
use framework::device::{DeviceAccess, LastTaken, ReplyOutcome, ReplyTicket, Sample};
use framework::parent_link::ParentLink;
use framework::plugin::{Anchors, Plugin, PluginContext};
use framework::scene::{NodeId, Object3D, Scene};

/// Data subtypes: `PLAYER_RANGER_DATA_RANGE`, `_RANGESTAMPED`, `_INTNS`, `_INTNSSTAMPED`,
/// `_GEOM`.
const DATA_SUBTYPES: [u8; 5] = [1, 2, 3, 4, 5];

pub struct RangerPlugin {
    config: PluginConfig,
    scan_style: ScanStyle,
    cone_style: ConeStyle,
    visible: bool,
    node: NodeId,
    parent: ParentLink,
    geometry_reply: Option<ReplyTicket>,
    config_reply: Option<ReplyTicket>,
    /// Element poses in the node's frame (empty for a single-element device: its pose is part
    /// of the node's transform).
    elements: Vec<Transducer>,
    device_config: Option<RangerConfig>,
    ranges: Vec<f64>,
    intensities: Vec<f64>,
    shape: RangerShape,
    /// The last message taken, per data subtype.
    taken: [LastTaken; DATA_SUBTYPES.len()],
    received: Option<Instant>,
    redraw_needed: bool,
}

impl RangerPlugin {
    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let scan_style = ScanStyle::from_config(&config)?;
        let cone_style = cone_style_from_config(&config)?;
        let visible = config.bool("visible", true)?;
        let parent = ParentLink::from_config(&config);
        let name = config.titled("ranger");
        let mut object = Object3D::new(name);
        object.tags.push("ranger".into());
        object.visible = visible;
        let node = ctx.scene.add(object);
        let (geometry_reply, config_reply) = match ctx.device {
            Some(d) => (
                Some(d.request(ranger::REQ_GET_GEOM, Body::Empty)),
                Some(d.request(ranger::REQ_GET_CONFIG, Body::Empty)),
            ),
            None => (None, None),
        };
        Ok(Box::new(RangerPlugin {
            config,
            scan_style,
            cone_style,
            visible,
            node,
            parent,
            geometry_reply,
            config_reply,
            elements: Vec::new(),
            device_config: None,
            ranges: Vec::new(),
            intensities: Vec::new(),
            shape: RangerShape::Empty,
            taken: [LastTaken::default(); DATA_SUBTYPES.len()],
            received: None,
            redraw_needed: false,
        }))
    }

    fn take_replies(&mut self, scene: &mut Scene) {
        if let Some(outcome) = take(&mut self.geometry_reply) {
            match body_of(outcome) {
                Ok(Body::Ranger(Ranger::Geometry(g))) => self.adopt_geometry(&g, scene),
                other => self.note_failure("geometry", other),
            }
        }
        if let Some(outcome) = take(&mut self.config_reply) {
            match body_of(outcome) {
                Ok(Body::Ranger(Ranger::Config(c))) => {
                    self.device_config = Some(c);
                    self.redraw_needed = true;
                }
                other => self.note_failure("config", other),
            }
        }
    }

    fn note_failure(&self, what: &str, outcome: Result<Body, String>) {
        match outcome {
            Ok(body) => {
                tracing::warn!(plugin = %self.config.id, "ranger {what} reply has an unexpected body: {body:?}");
            }
            Err(e) => tracing::info!(plugin = %self.config.id, "no ranger {what} ({e})"),
        }
    }

    /// Places the node at the device's pose (and a single element's pose), and keeps several
    /// elements' poses for their cones.
    fn adopt_geometry(&mut self, geometry: &RangerGeometry, scene: &mut Scene) {
        let mut transform = pose_transform(&geometry.pose);
        self.elements.clear();
        match geometry.element_poses.as_slice() {
            [] => {}
            [single] => transform *= pose_transform(single),
            several => self.elements.extend(several.iter().map(Transducer::from)),
        }
        if let Some(object) = scene.get_mut(self.node) {
            object.transform = transform;
        }
        self.redraw_needed = true;
    }

    /// Takes the data messages that came since the last update, oldest first.
    fn take_data(&mut self, device: &dyn DeviceAccess, scene: &mut Scene) {
        let mut new: Vec<Sample> = Vec::new();
        for (taken, subtype) in self.taken.iter_mut().zip(DATA_SUBTYPES) {
            new.extend(taken.newest(Some(device), subtype));
        }
        new.sort_by_key(|s| s.received);
        for sample in new {
            self.take(&sample, scene);
        }
    }

    fn take(&mut self, sample: &Sample, scene: &mut Scene) {
        let Body::Ranger(message) = &sample.message.body else {
            return;
        };
        match message {
            Ranger::Ranges(data) => self.take_ranges(&data.ranges, sample.received),
            Ranger::RangesStamped(stamped) => {
                self.take_ranges(&stamped.data.ranges, sample.received);
                if stamped.have_geom != 0 {
                    self.adopt_geometry(&stamped.geom, scene);
                }
                if stamped.have_config != 0 {
                    self.device_config = Some(stamped.config);
                }
            }
            Ranger::Intensities(data) => self.intensities.clone_from(&data.intensities),
            Ranger::IntensitiesStamped(stamped) => {
                self.intensities.clone_from(&stamped.data.intensities);
            }
            Ranger::GeometryData(geometry) => self.adopt_geometry(geometry, scene),
            _ => return,
        }
        self.redraw_needed = true;
    }

    fn take_ranges(&mut self, ranges: &[f64], received: Instant) {
        self.ranges.clear();
        self.ranges.extend_from_slice(ranges);
        self.received = Some(received);
    }

    fn redraw(&mut self, scene: &mut Scene) -> bool {
        let Some(object) = scene.get_mut(self.node) else {
            return false;
        };
        let data = RangerData {
            ranges: &self.ranges,
            intensities: &self.intensities,
            elements: &self.elements,
            config: self.device_config.as_ref(),
        };
        self.shape = ranger_geometry(
            &data,
            &self.scan_style,
            &self.cone_style,
            &mut object.geometry,
        );
        object.visible = self.visible;
        true
    }
}

fn take(ticket: &mut Option<ReplyTicket>) -> Option<ReplyOutcome> {
    let outcome = ticket.as_ref()?.try_take()?;
    *ticket = None;
    Some(outcome)
}

fn body_of(outcome: ReplyOutcome) -> Result<Body, String> {
    outcome.map(|m| m.body.clone()).map_err(|e| e.to_string())
}

/// A Player pose as a transform (roll, pitch and yaw applied in that order).
fn pose_transform(pose: &Pose3d) -> Affine3A {
    Affine3A::from_rotation_translation(
        Quat::from_euler(
            glam::EulerRot::ZYX,
            pose.pyaw as f32,
            pose.ppitch as f32,
            pose.proll as f32,
        ),
        Vec3::new(pose.px as f32, pose.py as f32, pose.pz as f32),
    )
}

impl Plugin for RangerPlugin {
    fn save(&self) -> PluginConfig {
        let mut config = self.config.clone();
        self.scan_style.write(&mut config);
        write_cone_style(&self.cone_style, &mut config);
        config.set_bool("visible", self.visible);
        config
    }

    fn title(&self) -> String {
        self.config.titled("Ranger")
    }

    fn update(&mut self, ctx: &mut PluginContext<'_>) -> bool {
        let mut changed = self.parent.attach(self.node, ctx);
        self.take_replies(ctx.scene);
        if let Some(device) = ctx.device {
            self.take_data(device, ctx.scene);
        }
        if self.redraw_needed {
            self.redraw_needed = false;
            changed |= self.redraw(ctx.scene);
        }
        changed
    }

    fn ui(&mut self, ui: &mut egui::Ui, ctx: &mut PluginContext<'_>) {
        let age = self.received.map_or(String::new(), |at| {
            format!(
                ", {:.1} s old",
                ctx.now.saturating_duration_since(at).as_secs_f32()
            )
        });
        let what = match self.shape {
            RangerShape::Cones => format!("{} readings as cones{age}", self.ranges.len()),
            RangerShape::Scan => format!("{} readings as a scan{age}", self.ranges.len()),
            RangerShape::WaitingForConfig => "waiting for the ranger's angles (config)".into(),
            RangerShape::Empty => "no readings yet".into(),
        };
        ui.label(what);
        let mut changed = ui.checkbox(&mut self.visible, "visible").changed();
        changed |= match self.shape {
            RangerShape::Cones => cone_style_ui(ui, &mut self.cone_style),
            _ => self.scan_style.ui(ui),
        };
        if changed {
            self.redraw_needed = true;
        }
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn detach(&mut self, scene: &mut Scene, anchors: &mut Anchors) {
        anchors.withdraw(self.node);
        scene.remove(self.node);
    }
}
