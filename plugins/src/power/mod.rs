//! `libpv3d_power`: a robot's battery. A gauge stands above the robot — its length the charge,
//! green, amber when low, red when nearly empty — with the percentage (or the voltage, for
//! batteries that report only that) beside it; the item tree lists every figure the device
//! sends and says, in words, when the battery is low. Crossing into low is logged once, so a
//! person watching many robots finds which one to bring home.
//!
//! Parameters: `<parentNode interface="position2d"/>` (the robot it stands on); `lowPercent`
//! (20); `lowVolts` (0: not used; e.g. 11.5 for a 12 V lead-acid pack that reports no
//! percentage); `height` (0.6 m above the robot's origin).

mod charge;

use glam::Vec3;
use player_proto::interfaces::power::PowerData;

use framework::config::{ConfigValueError, PluginConfig};
use framework::device::LastTaken;
use framework::parent_link::ParentLink;
use framework::plugin::{Plugin, PluginContext};
use framework::registry::Metadata;
use framework::scene::{NodeId, Object3D, Rgba, Scene};

pub use charge::{Charge, Level};

/// `lowPercent` when the composition gives none; the status panel, which sees no plugin's
/// parameters, warns by it too.
pub const DEFAULT_LOW_PERCENT: f32 = 20.0;

/// The status panel's note on a reading: the warning when the battery is low by the default
/// thresholds, else nothing.
pub fn low_note(data: &PowerData) -> Option<String> {
    let thresholds = charge::Thresholds {
        low_percent: DEFAULT_LOW_PERCENT,
        low_volts: 0.0,
    };
    let charge = Charge::read(data, &thresholds);
    (charge.level != Level::Fine).then(|| charge.warning())
}

/// The gauge's size when full, m.
const GAUGE: Vec3 = Vec3::new(0.4, 0.06, 0.06);

pub struct PowerPlugin {
    config: PluginConfig,
    thresholds: charge::Thresholds,
    height: f32,
    /// The gauge, below the robot's node once the robot is there.
    node: NodeId,
    parent: ParentLink,
    taken: LastTaken,
    /// The newest reading, for the item tree.
    charge: Option<Charge>,
}

impl PowerPlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A robot's battery: a gauge above the robot and every figure the device reports, with a warning when it runs low.",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let thresholds = charge::Thresholds {
            low_percent: config.number("lowPercent", f64::from(DEFAULT_LOW_PERCENT), 0.0..=100.0)?
                as f32,
            low_volts: config.number("lowVolts", 0.0, 0.0..=1000.0)? as f32,
        };
        let height = config.number("height", 0.6, -10.0..=10.0)? as f32;
        let node = ctx
            .scene
            .add(Object3D::new(format!("battery {}", config.id)));
        Ok(Box::new(PowerPlugin {
            parent: ParentLink::from_config(&config),
            config,
            thresholds,
            height,
            node,
            taken: LastTaken::default(),
            charge: None,
        }))
    }

    /// Redraws the gauge for `charge`.
    fn draw(&self, charge: &Charge, scene: &mut Scene) {
        let Some(gauge) = scene.get_mut(self.node) else {
            return;
        };
        let colour = match charge.level {
            Level::Fine => Rgba::rgb(80, 200, 90),
            Level::Low => Rgba::rgb(240, 170, 40),
            Level::Empty => Rgba::rgb(230, 60, 50),
        };
        let centre = Vec3::new(0.0, 0.0, self.height);
        gauge.geometry.clear();
        // The whole gauge's outline, so an empty battery still shows where full would be,
        // then the charge from the left.
        let (dx, dz) = (GAUGE.x / 2.0, GAUGE.z / 2.0);
        let corners = [(-dx, -dz), (dx, -dz), (dx, dz), (-dx, dz)]
            .map(|(x, z)| centre + Vec3::new(x, 0.0, z));
        gauge
            .geometry
            .polygon_outline(&corners, Rgba::rgb(150, 150, 150));
        if let Some(fraction) = charge.fraction() {
            let filled = Vec3::new(GAUGE.x * fraction, GAUGE.y, GAUGE.z);
            let left = centre - Vec3::X * (GAUGE.x - filled.x) / 2.0;
            gauge.geometry.cuboid(left, filled, colour);
        }
        let label_at = centre + Vec3::new(GAUGE.x / 2.0 + 0.05, 0.0, 0.0);
        gauge.geometry.label(label_at, charge.short_text(), colour);
    }
}

impl Plugin for PowerPlugin {
    fn save(&self) -> PluginConfig {
        self.config.clone()
    }

    fn title(&self) -> String {
        self.config.titled("Battery")
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.parent.attach(self.node, ctx);
        let Some((data, _)) = self.taken.newest_of::<PowerData>(ctx.device) else {
            return;
        };
        let charge = Charge::read(&data, &self.thresholds);
        let was = self.charge.as_ref().map(|c| c.level);
        if charge.level != Level::Fine && was.is_some_and(|w| w == Level::Fine) {
            tracing::warn!(plugin = %self.config.id, "battery low: {}", charge.short_text());
        }
        self.draw(&charge, ctx.scene);
        self.charge = Some(charge);
    }

    fn ui(&mut self, ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {
        let Some(charge) = &self.charge else {
            ui.label("no reading yet");
            return;
        };
        if charge.level != Level::Fine {
            ui.colored_label(egui::Color32::from_rgb(230, 80, 60), charge.warning());
        }
        for line in charge.figures() {
            ui.label(line);
        }
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.remove(self.node);
    }
}
