//! `libpv3d_fiducial`: the markers a fiducial finder detects, drawn where it sees them with
//! their ids. Each marker is a tagged object (`fiducial`, `id:7`, plus any tag the composition
//! maps to that id) so that other components can find and click it.
//!
//! Parameters: `<parentNode interface="position2d" index="0"/>`; `<tag id="7">person</tag>`
//! (any number); `color` (#f0c83c).

use std::collections::HashMap;

use glam::Vec3;
use player_proto::interfaces::common::Pose3d;
use player_proto::interfaces::fiducial::{Fiducial, FiducialData, FiducialGeometry};

use framework::config::{ConfigValueError, PluginConfig};
use framework::device::{Awaited, LastTaken};
use framework::parent_link::ParentLink;
use framework::plugin::{Plugin, PluginContext};
use framework::registry::Metadata;
use framework::scene::pose::transform_of;
use framework::scene::{Aabb, NodeId, Object3D, Rgba};

/// Drawn size of a marker, m.
const MARKER: f32 = 0.3;

pub struct FiducialPlugin {
    config: PluginConfig,
    color: Rgba,
    /// The finder's frame (below the robot when a parent is given).
    node: NodeId,
    markers: Vec<NodeId>,
    parent: ParentLink,
    geometry_reply: Awaited<FiducialGeometry>,
    tags: HashMap<i32, Vec<String>>,
    scan_taken: LastTaken,
    seen: Vec<(i32, f32)>,
}

impl FiducialPlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "The markers a fiducial finder sees, labelled by id and tagged so that a robot can go to or follow them.",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let color = config.color("color", Rgba::rgb(240, 200, 60))?;
        let mut tags: HashMap<i32, Vec<String>> = HashMap::new();
        for p in config.params.iter().filter(|p| p.name == "tag") {
            let id = p.attr("id").and_then(|i| i.trim().parse().ok()).ok_or_else(|| ConfigValueError {
                origin: p.origin.clone(),
                library: config.library.clone(),
                param: "tag".into(),
                message: "needs an id attribute with the marker's number, e.g. <tag id=\"7\">person</tag>".into(),
            })?;
            tags.entry(id).or_default().push(p.text.trim().to_string());
        }
        let parent = ParentLink::from_config(&config);
        let node = ctx
            .scene
            .add(Object3D::new(format!("fiducial finder {}", config.id)));
        let geometry_reply = Awaited::fetch(ctx.device, Fiducial::REQ_GET_GEOM);
        Ok(Box::new(FiducialPlugin {
            config,
            color,
            node,
            markers: Vec::new(),
            parent,
            geometry_reply,
            tags,
            scan_taken: LastTaken::default(),
            seen: Vec::new(),
        }))
    }

    fn place(&mut self, ctx: &mut PluginContext<'_>) {
        self.parent.attach(self.node, ctx);
        if let Some(Ok(g)) = self.geometry_reply.take()
            && let Some(n) = ctx.scene.get_mut(self.node)
        {
            n.transform = transform_of(&g.pose);
        }
    }
}

impl Plugin for FiducialPlugin {
    fn save(&self) -> PluginConfig {
        self.config.clone()
    }

    fn title(&self) -> String {
        self.config.titled("Fiducials")
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.place(ctx);
        let Some((data, _)) = self.scan_taken.newest_of::<FiducialData>(ctx.device) else {
            return;
        };
        for marker in self.markers.drain(..) {
            ctx.scene.remove(marker);
        }
        self.seen.clear();
        for item in &data.fiducials {
            let mut object = Object3D::new(format!("marker {}", item.id));
            object.parent = Some(self.node);
            // Markers stand at a fixed height in the finder's plane (the cuboid below), so
            // the height the finder reports is not used.
            object.transform = transform_of(&Pose3d {
                pz: 0.0,
                ..item.pose
            });
            let size = Vec3::new(MARKER, MARKER, 0.05);
            object
                .geometry
                .cuboid(Vec3::new(0.0, 0.0, 0.62), size, self.color);
            let label = if item.id > 0 {
                format!("#{}", item.id)
            } else {
                "?".to_string()
            };
            object
                .geometry
                .label(Vec3::new(0.0, 0.0, 0.75), label, self.color);
            object.pick_bounds = Some(Aabb::centred(Vec3::new(0.0, 0.0, 0.62), size));
            object.tags.push("fiducial".into());
            object.tags.push(format!("id:{}", item.id));
            if let Some(extra) = self.tags.get(&item.id) {
                object.tags.extend(extra.iter().cloned());
            }
            self.markers.push(ctx.scene.add(object));
            self.seen.push((item.id, item.range() as f32));
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {
        if self.seen.is_empty() {
            ui.label("no markers in view");
        }
        for (id, range) in &self.seen {
            let tags = self
                .tags
                .get(id)
                .map(|t| format!(" ({})", t.join(", ")))
                .unwrap_or_default();
            ui.label(format!("#{id} at {range:.2} m{tags}"));
        }
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.remove(self.node);
    }
}
