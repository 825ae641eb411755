//! `libpv3d_gripper`: a robot's gripper in front of it — two paddles apart when open,
//! together when closed, amber while moving — with a break-beam line lit when something is
//! between them, and a panel with Open and Close (also offered as services).
//!
//! Parameters: `<parentNode interface="position2d"/>` (the robot); `color` (#a0a0a0). The
//! gripper's pose and size come from its geometry request; until then it is drawn at the
//! front of a typical base (0.3 m ahead, 0.2 × 0.3 × 0.1 m).

pub mod paddles;

use glam::Vec3;
use player_proto::interfaces::common::Pose3d;
use player_proto::interfaces::gripper::{Gripper, GripperData, GripperGeometry, GripperSignal};

use framework::config::{ConfigValueError, PluginConfig};
use framework::device::{Awaited, LastTaken};
use framework::parent_link::ParentLink;
use framework::plugin::{Plugin, PluginContext, Service};
use framework::registry::Metadata;
use framework::scene::pose::transform_of;
use framework::scene::{NodeId, Object3D, Rgba, Scene};
use paddles::{Grip, paddles};

const OPEN: &str = "Open";
const CLOSE: &str = "Close";
/// Where the gripper is assumed until its geometry comes: ahead of a typical base, m.
const ASSUMED_AHEAD: f64 = 0.3;
const ASSUMED_SIZE: Vec3 = Vec3::new(0.2, 0.3, 0.1);
const MOVING_COLOR: Rgba = Rgba::rgb(240, 170, 40);
const ERROR_COLOR: Rgba = Rgba::rgb(230, 60, 50);
const BEAM_COLOR: Rgba = Rgba::rgb(255, 70, 70);

pub struct GripperPlugin {
    config: PluginConfig,
    color: Rgba,
    /// The paddles, below the robot at the gripper's pose.
    node: NodeId,
    parent: ParentLink,
    geometry_reply: Awaited<GripperGeometry>,
    pose: Pose3d,
    size: Vec3,
    taken: LastTaken,
    state: Option<GripperData>,
}

impl GripperPlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A robot's gripper in front of it, its paddles open, closed or moving, with Open and Close buttons.",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let color = config.color("color", Rgba::rgb(160, 160, 160))?;
        let mut object = Object3D::new(config.titled("gripper"));
        object.tags.push("gripper".into());
        let node = ctx.scene.add(object);
        let plugin = GripperPlugin {
            parent: ParentLink::from_config(&config),
            geometry_reply: Awaited::fetch(ctx.device, Gripper::REQ_GET_GEOM),
            config,
            color,
            node,
            pose: Pose3d {
                px: ASSUMED_AHEAD,
                ..Pose3d::default()
            },
            size: ASSUMED_SIZE,
            taken: LastTaken::default(),
            state: None,
        };
        plugin.redraw(ctx.scene);
        Ok(Box::new(plugin))
    }

    fn grip(&self) -> Grip {
        self.state.map_or(Grip::Unknown, |s| Grip::of(s.state))
    }

    fn redraw(&self, scene: &mut Scene) {
        let Some(object) = scene.get_mut(self.node) else {
            return;
        };
        object.transform = transform_of(&self.pose);
        object.geometry.clear();
        let grip = self.grip();
        let color = match grip {
            Grip::Moving => MOVING_COLOR,
            Grip::Error => ERROR_COLOR,
            _ => self.color,
        };
        // Standing on the gripper's base, so that a pose at the floor shows whole paddles.
        let lift = Vec3::Z * (self.size.z / 2.0);
        for (centre, size) in paddles(grip, self.size) {
            object.geometry.cuboid(centre + lift, size, color);
        }
        if self.state.is_some_and(|s| s.beams != 0) {
            let across = Vec3::Y * (self.size.y / 2.0);
            object
                .geometry
                .line(lift - across, lift + across, BEAM_COLOR);
        }
    }

    fn take_geometry(&mut self) -> bool {
        match self.geometry_reply.take() {
            Some(Ok(g)) => {
                self.pose = g.pose;
                let size = Vec3::new(
                    g.outer_size.sl as f32,
                    g.outer_size.sw as f32,
                    g.outer_size.sh as f32,
                );
                if size.min_element() > 0.0 {
                    self.size = size;
                }
                true
            }
            Some(Err(e)) => {
                tracing::info!(plugin = %self.config.id, "no gripper geometry ({e}); drawn where assumed");
                false
            }
            None => false,
        }
    }

    fn send(&self, order: &str, ctx: &PluginContext<'_>) {
        let Some(device) = ctx.device else { return };
        let kind = match order {
            OPEN => Gripper::CMD_OPEN,
            CLOSE => Gripper::CMD_CLOSE,
            _ => return,
        };
        device.command(kind.to_body(GripperSignal {}));
    }
}

impl Plugin for GripperPlugin {
    fn save(&self) -> PluginConfig {
        self.config.clone()
    }

    fn title(&self) -> String {
        self.config.titled("Gripper")
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.parent.attach(self.node, ctx);
        let mut changed = self.take_geometry();
        if let Some((data, _)) = self.taken.newest_of::<GripperData>(ctx.device) {
            changed |= self.state != Some(data);
            self.state = Some(data);
        }
        if changed {
            self.redraw(ctx.scene);
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, ctx: &mut PluginContext<'_>) {
        match self.state {
            Some(s) => {
                let beams = if s.beams != 0 {
                    "something between the paddles"
                } else {
                    "nothing between the paddles"
                };
                ui.label(format!("{}; {beams}", self.grip().word()));
                if s.stored > 0 {
                    ui.label(format!("{} stored", s.stored));
                }
            }
            None => {
                ui.label("no state yet");
            }
        }
        if ctx.device.is_some_and(|d| d.read_only()) {
            return;
        }
        ui.horizontal(|ui| {
            for order in [OPEN, CLOSE] {
                if ui.button(order).clicked() {
                    self.send(order, ctx);
                }
            }
        });
    }

    fn services(&self) -> Vec<Service> {
        vec![
            Service::run(OPEN, "open the paddles (and let go of what they hold)"),
            Service::run(CLOSE, "close the paddles on what is between them"),
        ]
    }

    fn run_service(&mut self, name: &str, ctx: &mut PluginContext<'_>) {
        self.send(name, ctx);
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.remove(self.node);
    }
}
