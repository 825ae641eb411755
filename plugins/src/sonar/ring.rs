//! A ring of range sensors drawn as cones — what the sonar and the infrared components share:
//! the sensors' poses (from the device, else assumed evenly spaced), the newest readings, the
//! cone style and visibility, the redraw when any of them changed, and the panel.

use std::time::Instant;

use framework::config::{ConfigValueError, PluginConfig};
use framework::scene::{NodeId, Scene};
use player_proto::interfaces::common::Pose3d;

use super::cone_params::{cone_style_ui, write_cone_style};
use super::cones::{ConeStyle, Transducer, cone_geometry, evenly_spaced};

/// Radius of the ring sensors are assumed on while their poses are unknown, m.
const ASSUMED_RING_RADIUS: f32 = 0.2;

pub struct ConeRing {
    style: ConeStyle,
    visible: bool,
    /// At most this many sensors are kept from one message (Player's limit for the interface).
    max_sensors: usize,
    sensors: Vec<Transducer>,
    /// Whether the poses came from the device (else assumed).
    poses_known: bool,
    ranges: Vec<f32>,
    received: Option<Instant>,
    redraw_needed: bool,
}

impl ConeRing {
    pub fn new(
        style: ConeStyle,
        config: &PluginConfig,
        max_sensors: usize,
    ) -> Result<ConeRing, ConfigValueError> {
        Ok(ConeRing {
            style,
            visible: config.bool("visible", true)?,
            max_sensors,
            sensors: Vec::new(),
            poses_known: false,
            ranges: Vec::new(),
            received: None,
            redraw_needed: false,
        })
    }

    pub fn visible(&self) -> bool {
        self.visible
    }

    /// The sensors' poses as the device reports them.
    pub fn adopt_poses(&mut self, poses: &[Pose3d]) {
        self.sensors = poses
            .iter()
            .take(self.max_sensors)
            .map(Transducer::from)
            .collect();
        self.poses_known = true;
        self.redraw_needed = true;
    }

    /// A new reading of every sensor.
    pub fn take_ranges(&mut self, ranges: &[f32], received: Instant) {
        self.ranges.clear();
        self.ranges
            .extend(ranges.iter().take(self.max_sensors).copied());
        self.received = Some(received);
        self.redraw_needed = true;
    }

    /// Redraws the cones on `node` if anything changed since the last time.
    pub fn redraw_if_needed(&mut self, scene: &mut Scene, node: NodeId) {
        if !std::mem::take(&mut self.redraw_needed) {
            return;
        }
        if !self.poses_known && self.sensors.len() != self.ranges.len() {
            self.sensors = evenly_spaced(self.ranges.len(), ASSUMED_RING_RADIUS);
        }
        let Some(object) = scene.get_mut(node) else {
            return;
        };
        cone_geometry(
            &self.sensors,
            &self.ranges,
            &self.style,
            &mut object.geometry,
        );
        object.visible = self.visible;
    }

    /// Writes the style and visibility into `config`.
    pub fn save_into(&self, config: &mut PluginConfig) {
        write_cone_style(&self.style, config);
        config.set_bool("visible", self.visible);
    }

    /// The panel: how many `sensors` (the word for them), the nearest return and its age, and
    /// the style's controls.
    pub fn ui(&mut self, ui: &mut egui::Ui, now: Instant, sensors: &str) {
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
                    "{} {sensors}, {nearest}, {:.1} s old",
                    self.ranges.len(),
                    now.saturating_duration_since(at).as_secs_f32()
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
}
