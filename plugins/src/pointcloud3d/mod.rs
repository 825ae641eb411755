//! `libpv3d_pointcloud3d`: a 3-D point cloud (Player's `pointcloud3d`), each point coloured by
//! its height — the paper's sparse 3-D reconstruction, whose shape reads from the colours
//! without lighting. A device's own point colours can be used instead.
//!
//! Parameters: `minHeight` (0 m) and `maxHeight` (2 m): the heights the colour ramp spans;
//! `useDeviceColors` (0); `maxPoints` (200 000: a cloud beyond it is thinned evenly, so that
//! one huge message cannot stall the viewer); `<parentNode interface="position2d"/>`
//! (optional: for a cloud in a robot's frame; without it the cloud is in the world's).

pub mod ramp;

use glam::Vec3;
use player_proto::interfaces::pointcloud3d::PointCloud3dData;

use framework::config::{ConfigValueError, PluginConfig};
use framework::device::LastTaken;
use framework::parent_link::ParentLink;
use framework::plugin::{Plugin, PluginContext};
use framework::registry::Metadata;
use framework::scene::{NodeId, Object3D, Rgba, Scene};
use ramp::HeightRange;

pub struct PointCloudPlugin {
    config: PluginConfig,
    range: HeightRange,
    device_colors: bool,
    max_points: usize,
    node: NodeId,
    parent: ParentLink,
    taken: LastTaken,
    cloud: Option<PointCloud3dData>,
    drawn: usize,
}

impl PointCloudPlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A 3-D point cloud, each point coloured by its height (a sparse reconstruction), or by its own colour.",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let low = config.number("minHeight", 0.0, -1e4..=1e4)? as f32;
        let high = config.number("maxHeight", 2.0, -1e4..=1e4)? as f32;
        if high <= low
            && let Some(p) = config.param("maxHeight").or(config.param("minHeight"))
        {
            return Err(ConfigValueError {
                origin: p.origin.clone(),
                library: config.library.clone(),
                param: p.name.clone(),
                message: format!("maxHeight ({high}) must be above minHeight ({low})"),
            });
        }
        let device_colors = config.bool("useDeviceColors", false)?;
        let max_points = config.number("maxPoints", 200_000.0, 1.0..=1e8)? as usize;
        let mut object = Object3D::new(config.titled("point cloud"));
        object.tags.push("pointcloud".into());
        let node = ctx.scene.add(object);
        Ok(Box::new(PointCloudPlugin {
            parent: ParentLink::from_config(&config),
            config,
            range: HeightRange { low, high },
            device_colors,
            max_points,
            node,
            taken: LastTaken::default(),
            cloud: None,
            drawn: 0,
        }))
    }

    fn redraw(&mut self, scene: &mut Scene) {
        let Some(cloud) = &self.cloud else { return };
        let Some(object) = scene.get_mut(self.node) else {
            return;
        };
        object.geometry.clear();
        let step = cloud.points.len().div_ceil(self.max_points).max(1);
        for element in cloud.points.iter().step_by(step) {
            let p = &element.point;
            let at = Vec3::new(p.px as f32, p.py as f32, p.pz as f32);
            let color = if self.device_colors {
                let c = &element.color;
                Rgba::rgb(c.red, c.green, c.blue)
            } else {
                self.range.color_of(at.z)
            };
            object.geometry.point(at, color);
        }
        self.drawn = object.geometry.points.len();
    }
}

impl Plugin for PointCloudPlugin {
    fn save(&self) -> PluginConfig {
        let mut config = self.config.clone();
        config.set("minHeight", format!("{}", self.range.low));
        config.set("maxHeight", format!("{}", self.range.high));
        config.set_bool("useDeviceColors", self.device_colors);
        config
    }

    fn title(&self) -> String {
        self.config.titled("Point cloud")
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.parent.attach(self.node, ctx);
        if let Some((cloud, _)) = self.taken.newest_of::<PointCloud3dData>(ctx.device) {
            self.cloud = Some(cloud);
            self.redraw(ctx.scene);
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, ctx: &mut PluginContext<'_>) {
        match &self.cloud {
            Some(cloud) if self.drawn < cloud.points.len() => {
                ui.label(format!("{} of {} points", self.drawn, cloud.points.len()));
            }
            Some(cloud) => {
                ui.label(format!("{} points", cloud.points.len()));
            }
            None => {
                ui.label("no cloud yet");
            }
        }
        let before = (self.range, self.device_colors);
        ui.checkbox(&mut self.device_colors, "the device's colours");
        ui.add(egui::Slider::new(&mut self.range.low, -5.0..=5.0).text("lowest m"));
        ui.add(egui::Slider::new(&mut self.range.high, -5.0..=10.0).text("highest m"));
        if (self.range, self.device_colors) != before {
            self.redraw(ctx.scene);
        }
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.remove(self.node);
    }
}
