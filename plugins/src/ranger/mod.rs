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

use player_proto::interfaces::kind::MessageKind;
use player_proto::interfaces::ranger::{Ranger, RangerConfig, RangerGeometry};
use player_proto::message::Body;
use player_proto::wire::Interface;

pub use shape::{RangerData, RangerShape, ranger_geometry};

use crate::laser::ScanStyle;
use crate::sonar::cone_params::{cone_style_from_config, cone_style_ui, write_cone_style};
use crate::sonar::cones::{ConeStyle, Transducer};
use framework::config::{ConfigValueError, PluginConfig};
use framework::device::{Awaited, DeviceAccess, LastTaken, RequestError, Stamped};
use framework::parent_link::ParentLink;
use framework::plugin::{Plugin, PluginContext};
use framework::registry::Metadata;
use framework::scene::pose::transform_of;
use framework::scene::{NodeId, Object3D, Scene};

pub struct RangerPlugin {
    config: PluginConfig,
    scan_style: ScanStyle,
    cone_style: ConeStyle,
    visible: bool,
    node: NodeId,
    parent: ParentLink,
    geometry_reply: Awaited<RangerGeometry>,
    config_reply: Awaited<RangerConfig>,
    /// Element poses in the node's frame (empty for a single-element device: its pose is part
    /// of the node's transform).
    elements: Vec<Transducer>,
    device_config: Option<RangerConfig>,
    ranges: Vec<f64>,
    intensities: Vec<f64>,
    shape: RangerShape,
    /// Every data message the ranger interface defines (ranges, intensities, either
    /// stamped, geometry), each with the sample of it taken last.
    taken: Vec<(MessageKind, LastTaken)>,
    received: Option<Instant>,
    redraw_needed: bool,
}

impl RangerPlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A ranger's readings: cones for a ring of sensors, points and free space for a scanner.",
    );

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
        let geometry_reply = Awaited::fetch(ctx.device, Ranger::REQ_GET_GEOM);
        let config_reply = Awaited::fetch(ctx.device, Ranger::REQ_GET_CONFIG);
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
            taken: MessageKind::data_of(Interface::RANGER)
                .map(|kind| (kind, LastTaken::default()))
                .collect(),
            received: None,
            redraw_needed: false,
        }))
    }

    fn take_replies(&mut self, scene: &mut Scene) {
        match self.geometry_reply.take() {
            Some(Ok(g)) => self.adopt_geometry(&g, scene),
            Some(Err(e)) => self.note_failure("geometry", &e),
            None => {}
        }
        match self.config_reply.take() {
            Some(Ok(c)) => {
                self.device_config = Some(c);
                self.redraw_needed = true;
            }
            Some(Err(e)) => self.note_failure("config", &e),
            None => {}
        }
    }

    fn note_failure(&self, what: &str, e: &RequestError) {
        tracing::info!(plugin = %self.config.id, "no ranger {what} ({e})");
    }

    /// Places the node at the device's pose (and a single element's pose), and keeps several
    /// elements' poses for their cones.
    fn adopt_geometry(&mut self, geometry: &RangerGeometry, scene: &mut Scene) {
        let mut transform = transform_of(&geometry.pose);
        self.elements.clear();
        match geometry.element_poses.as_slice() {
            [] => {}
            [single] => transform *= transform_of(single),
            several => self.elements.extend(several.iter().map(Transducer::from)),
        }
        if let Some(object) = scene.get_mut(self.node) {
            object.transform = transform;
        }
        self.redraw_needed = true;
    }

    /// Takes the data messages that came since the last update, oldest first.
    fn take_data(&mut self, device: &dyn DeviceAccess, scene: &mut Scene) {
        let mut new: Vec<Stamped> = Vec::new();
        for (kind, taken) in &mut self.taken {
            new.extend(taken.newest(Some(device), *kind));
        }
        new.sort_by_key(|s| s.received);
        for sample in new {
            self.take(&sample, scene);
        }
    }

    fn take(&mut self, sample: &Stamped, scene: &mut Scene) {
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

    fn redraw(&mut self, scene: &mut Scene) {
        let Some(object) = scene.get_mut(self.node) else {
            return;
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
    }
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

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.parent.attach(self.node, ctx);
        self.take_replies(ctx.scene);
        if let Some(device) = ctx.device {
            self.take_data(device, ctx.scene);
        }
        if self.redraw_needed {
            self.redraw_needed = false;
            self.redraw(ctx.scene);
        }
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

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.anchors.withdraw(self.node);
        ctx.scene.remove(self.node);
    }
}
