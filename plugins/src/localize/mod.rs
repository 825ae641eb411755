//! `libpv3d_localize`: where a localizer (Player's `localize`, e.g. amcl) believes the robot
//! is. The best hypothesis is an arrow inside its 95 % position ellipse, the others faint
//! ellipses; "Show particles" asks for the particle filter's samples and draws them as
//! points. Made the active handler (item tree, Tab), a drag on the ground gives the robot's
//! pose by hand — press where it stands, drag the way it faces — and is sent as set-pose with
//! a hand-placed spread; a plain click moves the estimate keeping its heading.
//!
//! Parameters: `color` (#dc50c8); `particleColor` (#f0a0e6); `showParticles` (0);
//! `positionStdDev` (0.5 m) and `headingStdDev` (15°): the spread a pose given by hand is sent
//! with. The estimate is in the map's frame, which the scene's world frame is: it hangs below
//! no robot.

pub mod draw;
pub mod ellipse;
pub mod pose_drag;
pub mod set_pose;

use glam::Vec2;
use player_proto::client::PendingReply;
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::localize::{Localize, LocalizeData, LocalizeParticles};

use framework::config::{ConfigValueError, PluginConfig};
use framework::device::{Awaited, LastTaken};
use framework::plugin::{Handled, InputEvent, Plugin, PluginContext, Service};
use framework::registry::Metadata;
use framework::scene::{Aabb, NodeId, Object3D, Rgba, Scene};
use pose_drag::{DragStep, PoseDrag};
use set_pose::{HandPlacedSpread, set_pose_request};

const SHOW_PARTICLES: &str = "Show particles";
const HIDE_PARTICLES: &str = "Hide particles";
/// Size of the box that picks the estimate (to select this handler by clicking it), m.
const PICK_SIZE: f32 = 0.5;

pub struct LocalizePlugin {
    config: PluginConfig,
    color: Rgba,
    particle_color: Rgba,
    spread: HandPlacedSpread,
    /// The hypotheses and the pose being given by hand.
    node: NodeId,
    particles_node: NodeId,
    taken: LastTaken,
    estimate: Option<LocalizeData>,
    show_particles: bool,
    particles_reply: Option<Awaited<LocalizeParticles>>,
    particle_count: usize,
    drag: PoseDrag,
    active: bool,
    set_pose_reply: Option<PendingReply>,
    /// What became of the last pose given by hand, for the panel.
    last_set_pose: Option<String>,
}

impl LocalizePlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A localizer's pose estimate: the best hypothesis inside its 95 % ellipse, the particles on request; select it and drag on the ground to give the robot's pose by hand.",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let color = config.color("color", Rgba::rgb(220, 80, 200))?;
        let particle_color = config.color("particleColor", Rgba::rgb(240, 160, 230))?;
        let spread = HandPlacedSpread {
            position_sd: config.number("positionStdDev", 0.5, 0.0..=100.0)?,
            heading_sd: config
                .number("headingStdDev", 15.0, 0.0..=360.0)?
                .to_radians(),
        };
        let show_particles = config.bool("showParticles", false)?;
        let mut object = Object3D::new(config.titled("localize"));
        object.tags.push("localize".into());
        let node = ctx.scene.add(object);
        let particles_node = ctx
            .scene
            .add(Object3D::new(format!("{} particles", config.id)));
        let particles_reply =
            show_particles.then(|| Awaited::fetch(ctx.device, Localize::REQ_GET_PARTICLES));
        Ok(Box::new(LocalizePlugin {
            config,
            color,
            particle_color,
            spread,
            node,
            particles_node,
            taken: LastTaken::default(),
            estimate: None,
            show_particles,
            particles_reply,
            particle_count: 0,
            drag: PoseDrag::default(),
            active: false,
            set_pose_reply: None,
            last_set_pose: None,
        }))
    }

    /// The estimate and the hand-given pose, redrawn.
    fn redraw(&self, scene: &mut Scene) {
        let Some(object) = scene.get_mut(self.node) else {
            return;
        };
        match &self.estimate {
            Some(data) => draw::hypotheses(&mut object.geometry, data, self.color),
            None => object.geometry.clear(),
        }
        object.pick_bounds = self.estimate.as_ref().and_then(|d| d.best()).map(|best| {
            let at = Vec2::new(best.mean.px as f32, best.mean.py as f32);
            Aabb::centred(at.extend(draw::LIFT), glam::Vec3::splat(PICK_SIZE))
        });
        if let Some((at, heading)) = self.drag.preview() {
            draw::hand_pose(&mut object.geometry, at, heading, Rgba::WHITE);
        }
    }

    /// The heading the estimate has now (what a plain click keeps).
    fn current_heading(&self) -> f64 {
        self.estimate
            .as_ref()
            .and_then(|d| d.best())
            .map_or(0.0, |best| best.mean.pa)
    }

    fn request_particles(&mut self, ctx: &PluginContext<'_>) {
        if !self
            .particles_reply
            .as_ref()
            .is_some_and(Awaited::is_waiting)
        {
            self.particles_reply = Some(Awaited::fetch(ctx.device, Localize::REQ_GET_PARTICLES));
        }
    }

    fn take_particles(&mut self, ctx: &mut PluginContext<'_>) {
        let Some(outcome) = self.particles_reply.as_mut().and_then(Awaited::take) else {
            return;
        };
        match outcome {
            Ok(reply) if self.show_particles => {
                self.particle_count = reply.particles.len();
                if let Some(object) = ctx.scene.get_mut(self.particles_node) {
                    draw::particles(&mut object.geometry, &reply.particles, self.particle_color);
                }
            }
            Ok(_) => {}
            Err(e) => {
                tracing::warn!(plugin = %self.config.id, "no particles: {e}");
                self.show_particles = false;
            }
        }
    }

    fn set_particles_shown(&mut self, shown: bool, ctx: &mut PluginContext<'_>) {
        self.show_particles = shown;
        if shown {
            self.request_particles(ctx);
        } else if let Some(object) = ctx.scene.get_mut(self.particles_node) {
            object.geometry.clear();
            self.particle_count = 0;
        }
    }

    /// Sends the pose the person gave.
    fn send_pose(&mut self, pose: Pose2d, ctx: &PluginContext<'_>) {
        let Some(device) = ctx.device else { return };
        let request = set_pose_request(pose, self.spread);
        let body = Localize::REQ_SET_POSE.to_body(request);
        self.set_pose_reply = Some(device.request(Localize::REQ_SET_POSE.kind(), body));
        self.last_set_pose = Some(format!(
            "sent ({:.2}, {:.2}) m, {:.0}°",
            pose.px,
            pose.py,
            pose.pa.to_degrees()
        ));
    }

    fn take_set_pose_reply(&mut self) {
        let Some(outcome) = self.set_pose_reply.as_ref().and_then(PendingReply::try_get) else {
            return;
        };
        self.set_pose_reply = None;
        if let Err(e) = outcome {
            tracing::warn!(plugin = %self.config.id, "set pose refused: {e}");
            self.last_set_pose = Some(format!("refused: {e}"));
        }
    }
}

impl Plugin for LocalizePlugin {
    fn save(&self) -> PluginConfig {
        let mut config = self.config.clone();
        config.set_bool("showParticles", self.show_particles);
        config
    }

    fn title(&self) -> String {
        self.config.titled("Localize")
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.take_set_pose_reply();
        self.take_particles(ctx);
        let Some((data, _)) = self.taken.newest_of::<LocalizeData>(ctx.device) else {
            return;
        };
        self.estimate = Some(data);
        self.redraw(ctx.scene);
        // The particles move with the estimate: ask again once the last answer is in.
        if self.show_particles {
            self.request_particles(ctx);
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {
        match self
            .estimate
            .as_ref()
            .and_then(|d| d.best().map(|b| (d, b)))
        {
            Some((data, best)) => {
                let e = ellipse::Ellipse::of_covariance(&best.cov);
                ui.label(format!(
                    "best ({:.2}, {:.2}) m, {:.0}°, {}",
                    best.mean.px,
                    best.mean.py,
                    best.mean.pa.to_degrees(),
                    data.share_of(best)
                ))
                .on_hover_text(format!("weight as the driver sent it: {}", best.alpha));
                ui.label(format!(
                    "95 %: ±{:.2} × ±{:.2} m; {} hypotheses",
                    e.major,
                    e.minor,
                    data.hypoths.len()
                ));
            }
            None => {
                ui.label("no estimate yet");
            }
        }
        if self.show_particles {
            ui.label(format!("{} particles", self.particle_count));
        }
        if let Some(last) = &self.last_set_pose {
            ui.small(last);
        }
        if self.active {
            ui.small("Ctrl+drag on the ground: press where the robot is, drag the way it faces");
        }
    }

    fn active_ui(&mut self, ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {
        ui.strong(self.title());
        ui.small("drag (Ctrl) on the ground to set the pose");
    }

    fn services(&self) -> Vec<Service> {
        if self.show_particles {
            vec![Service::run(HIDE_PARTICLES, "stop drawing the particles")]
        } else {
            vec![Service::run(
                SHOW_PARTICLES,
                "ask the localizer for its particles and draw them",
            )]
        }
    }

    fn run_service(&mut self, name: &str, ctx: &mut PluginContext<'_>) {
        match name {
            SHOW_PARTICLES => self.set_particles_shown(true, ctx),
            HIDE_PARTICLES => self.set_particles_shown(false, ctx),
            _ => {}
        }
    }

    fn on_event(&mut self, event: &InputEvent, ctx: &mut PluginContext<'_>) -> Handled {
        let step = self.drag.follow(event, self.active, self.current_heading());
        match step {
            DragStep::Activated(active) => self.active = active,
            DragStep::Released(pose) => self.send_pose(pose, ctx),
            _ => {}
        }
        if step.redraws() {
            self.redraw(ctx.scene);
        }
        step.handled()
    }

    fn can_be_active(&self) -> bool {
        self.config.device.is_some()
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        ctx.scene.remove(self.node);
        ctx.scene.remove(self.particles_node);
    }
}
