//! `libpv3d_laser`: a laser scanner's scans, attached to its robot.
//!
//! Parameters (all optional): `<parentNode interface="position2d" index="0"/>` — the device
//! whose scene node the laser hangs below (same server); `drawPoints` (1), `drawLines` (0),
//! `fillLaserCspace` (0), `drawLaserCspace` (0) — the free-space polygon filled and outlined;
//! `color` (#ff5a3c); `shadeIntensity` (1) — returns shaded by intensity when the device sends
//! intensities; `skinFile` — an OBJ model of the scanner drawn at its pose, fitted to the size
//! its geometry reports (see [`framework::skin`]). The laser's pose on the robot comes from its
//! geometry request. Scans are drawn from whichever of the three data messages the driver
//! sends (plain, with the pose it was taken at, with a bearing per reading), newest first.

mod readings;
mod scan_geometry;

use std::time::Instant;

use glam::{Affine3A, Vec3};
use player_proto::interfaces::kind::MessageKind;
use player_proto::interfaces::laser::{Laser, LaserGeometry};
use player_proto::message::Body;
use player_proto::wire::Interface;

pub use readings::{Bearings, Readings};
pub use scan_geometry::{ScanStyle, endpoints, scan_geometry};

use framework::config::{ConfigValueError, PluginConfig};
use framework::device::{Awaited, LastTaken, Stamped};
use framework::parent_link::ParentLink;
use framework::plugin::{Plugin, PluginContext};
use framework::registry::Metadata;
use framework::scene::pose::transform_of;
use framework::scene::{NodeId, Object3D, Rgba};
use framework::skin::{Skin, fit_into};

/// The scanner's size until its geometry says otherwise (a SICK LMS200's), m.
const DEFAULT_SIZE: Vec3 = Vec3::new(0.156, 0.155, 0.19);

pub struct LaserPlugin {
    config: PluginConfig,
    style: ScanStyle,
    node: NodeId,
    parent: ParentLink,
    geometry: Awaited<LaserGeometry>,
    /// The scan forms the laser interface defines (plain, with pose, with angles), each with
    /// the sample of it drawn last.
    drawn: Vec<(MessageKind, LastTaken)>,
    /// Readings in the newest scan, and the nearest return.
    summary: Option<(usize, Option<f32>, Instant)>,
    skin: Skin,
    /// The skin's node, below the scan's (the scan node's geometry is redrawn every scan).
    skin_node: Option<NodeId>,
}

impl LaserPlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A laser scan as points and the free space it sees, hung below its robot.",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let style = ScanStyle::from_config(&config)?;
        let parent = ParentLink::from_config(&config);
        let name = config.titled("laser");
        let mut object = Object3D::new(name);
        object.tags.push("laser".into());
        let node = ctx.scene.add(object);
        let skin = Skin::from_config(&config);
        let skin_node = skin.mesh.as_ref().map(|_| {
            let mut body = Object3D::new(format!("{} skin", config.id));
            body.parent = Some(node);
            ctx.scene.add(body)
        });
        let geometry = Awaited::fetch(ctx.device, Laser::REQ_GET_GEOM);
        let plugin = Box::new(LaserPlugin {
            config,
            style,
            node,
            parent,
            geometry,
            drawn: MessageKind::data_of(Interface::LASER)
                .map(|kind| (kind, LastTaken::default()))
                .collect(),
            summary: None,
            skin,
            skin_node,
        });
        plugin.draw_skin(ctx, DEFAULT_SIZE);
        Ok(plugin)
    }

    /// Draws the skin, if worn, centred on the scanner's origin at `size`.
    fn draw_skin(&self, ctx: &mut PluginContext<'_>, size: Vec3) {
        let (Some(mesh), Some(node)) = (&self.skin.mesh, self.skin_node) else {
            return;
        };
        if let Some(body) = ctx.scene.get_mut(node) {
            body.geometry.clear();
            fit_into(&mut body.geometry, mesh, size, Rgba::rgb(70, 80, 110));
            body.transform = Affine3A::from_translation(Vec3::new(0.0, 0.0, -size.z / 2.0));
        }
    }

    fn place_from_geometry(&mut self, ctx: &mut PluginContext<'_>) {
        let Some(outcome) = self.geometry.take() else {
            return;
        };
        match outcome {
            Ok(g) => {
                if let Some(node) = ctx.scene.get_mut(self.node) {
                    node.transform = transform_of(&g.pose);
                }
                let size = Vec3::new(g.size.sl as f32, g.size.sw as f32, g.size.sh as f32);
                if size.min_element() > 0.0 && size.is_finite() {
                    self.draw_skin(ctx, size);
                }
            }
            Err(e) => {
                tracing::info!(plugin = %self.config.id, "no laser geometry ({e}); drawing at the robot's origin");
            }
        }
    }

    fn redraw(&mut self, sample: &Stamped, ctx: &mut PluginContext<'_>) {
        let scan = match &sample.message.body {
            Body::Laser(Laser::Scan(scan)) => Readings::from_scan(scan),
            Body::Laser(Laser::ScanPose(with_pose)) => Readings::from_scan(&with_pose.scan),
            Body::Laser(Laser::ScanAngle(with_angles)) => Readings::from_scan_angle(with_angles),
            _ => return,
        };
        let scan = &scan;
        let nearest = endpoints(scan)
            .filter(|(_, hit)| *hit)
            .map(|(p, _)| p.length())
            .min_by(f32::total_cmp);
        self.summary = Some((scan.ranges.len(), nearest, sample.received));
        let Some(node) = ctx.scene.get_mut(self.node) else {
            return;
        };
        scan_geometry(scan, &self.style, &mut node.geometry);
    }
}

impl Plugin for LaserPlugin {
    fn save(&self) -> PluginConfig {
        let mut config = self.config.clone();
        self.style.write(&mut config);
        config
    }

    fn title(&self) -> String {
        self.config.titled("Laser")
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.place_from_geometry(ctx);
        self.parent.attach(self.node, ctx);
        let newest = ctx.device.and_then(|d| {
            (0..self.drawn.len())
                .filter_map(|i| Some((i, d.latest(self.drawn[i].0)?)))
                .max_by_key(|(_, sample)| sample.received)
        });
        if let Some((i, sample)) = newest
            && self.drawn[i].1.is_new(&sample)
        {
            self.redraw(&sample, ctx);
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, ctx: &mut PluginContext<'_>) {
        match self.summary {
            Some((n, nearest, at)) => {
                let nearest = nearest.map_or("no return".into(), |r| format!("nearest {r:.2} m"));
                ui.label(format!(
                    "{n} readings, {nearest}, {:.1} s old",
                    ctx.now.saturating_duration_since(at).as_secs_f32()
                ));
            }
            None => {
                ui.label("no scan yet");
            }
        }
        self.skin.ui(ui);
        if self.style.ui(ui) {
            // Redraw the newest scan in the new style.
            self.drawn.iter_mut().for_each(|(_, taken)| taken.forget());
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
