//! `libpv3d_position2d`: a mobile base — its body at the pose it reports, a pose trail, a
//! velocity readout, and tele-operation: velocity limits, a joystick, and a target clicked on
//! the ground that the robot is steered to. Safe by default: zero velocity when the person lets
//! go, when every robot is stopped (Space, focus lost) and when the connection drops.
//!
//! Parameters: `trailLength` (200 poses), `maxSpeed` (0.5 m/s), `maxTurn` (1.0 rad/s),
//! `color` (#3c8cdc).

mod body;
mod teleop;

use std::collections::VecDeque;
use std::time::{Duration, Instant};

use glam::{Affine3A, Quat, Vec2, Vec3};
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::position2d::{self, Position2d, Position2dCmdVel};
use player_proto::message::Body;

pub use body::body_geometry;
pub use teleop::{ARRIVED, Limits, joystick_velocity, steer_towards, wrap_angle};

use crate::config::{ConfigValueError, PluginConfig};
use crate::device::ReplyTicket;
use crate::plugin::{AnchorKey, Anchors, Handled, InputEvent, Plugin, PluginContext, Service};
use crate::scene::{Aabb, NodeId, Object3D, Rgba, Scene};

/// How often velocity commands are repeated while driving.
const COMMAND_PERIOD: Duration = Duration::from_millis(100);
const DATA_STATE: u8 = 1;

pub struct Position2dPlugin {
    config: PluginConfig,
    color: Rgba,
    node: NodeId,
    trail_node: NodeId,
    anchor: Option<AnchorKey>,
    geometry_reply: Option<ReplyTicket>,
    size: Vec3,
    last_seq: Option<u64>,
    pose: (f32, f32, f32),
    velocity: (f32, f32),
    stalled: bool,
    trail: VecDeque<Vec3>,
    trail_length: usize,
    limits: Limits,
    active: bool,
    target: Option<Vec2>,
    joystick: Option<Vec2>,
    /// Something other than zero was commanded and not yet cancelled.
    moving: bool,
    last_command: Option<Instant>,
}

impl Position2dPlugin {
    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let color = config.color("color", Rgba::rgb(60, 140, 220))?;
        let trail_length = config.number("trailLength", 200.0, 0.0..=100_000.0)? as usize;
        let limits = Limits {
            max_speed: config.number("maxSpeed", 0.5, 0.0..=20.0)? as f32,
            max_turn: config.number("maxTurn", 1.0, 0.0..=20.0)? as f32,
        };
        let size = Vec3::new(0.44, 0.38, 0.22);
        let mut object = Object3D::new(config.id.clone());
        object
            .tags
            .extend(["robot".to_string(), "position2d".to_string()]);
        object.pick_bounds = Some(Aabb::centred(Vec3::new(0.0, 0.0, size.z / 2.0), size));
        body_geometry(&mut object.geometry, size, color, false, &config.id);
        let node = ctx.scene.add(object);
        let trail_node = ctx.scene.add(Object3D::new(format!("{} trail", config.id)));
        let anchor = config.device.as_ref().map(|d| AnchorKey {
            host: d.host.clone(),
            port: d.port,
            interface: "position2d".into(),
            index: d.addr.index,
        });
        if let Some(key) = &anchor {
            ctx.anchors.publish(key.clone(), node);
        }
        let geometry_reply = ctx
            .device
            .map(|d| d.request(position2d::REQ_GET_GEOM, Body::Empty));
        Ok(Box::new(Position2dPlugin {
            config,
            color,
            node,
            trail_node,
            anchor,
            geometry_reply,
            size,
            last_seq: None,
            pose: (0.0, 0.0, 0.0),
            velocity: (0.0, 0.0),
            stalled: false,
            trail: VecDeque::new(),
            trail_length,
            limits,
            active: false,
            target: None,
            joystick: None,
            moving: false,
            last_command: None,
        }))
    }

    fn redraw_body(&self, scene: &mut Scene) {
        if let Some(node) = scene.get_mut(self.node) {
            body_geometry(
                &mut node.geometry,
                self.size,
                self.color,
                self.active,
                &self.config.id,
            );
            node.pick_bounds = Some(Aabb::centred(
                Vec3::new(0.0, 0.0, self.size.z / 2.0),
                self.size,
            ));
        }
    }

    fn redraw_trail(&self, scene: &mut Scene) {
        let Some(node) = scene.get_mut(self.trail_node) else {
            return;
        };
        node.geometry.clear();
        let faded = self.color.with_alpha(150);
        let points: Vec<Vec3> = self.trail.iter().copied().collect();
        for pair in points.windows(2) {
            node.geometry.line(pair[0], pair[1], faded);
        }
        if let Some(t) = self.target {
            let at = Vec3::new(t.x, t.y, 0.02);
            let marker = Rgba::rgb(250, 200, 60);
            let r = 0.15;
            node.geometry
                .line(at - Vec3::X * r, at + Vec3::X * r, marker);
            node.geometry
                .line(at - Vec3::Y * r, at + Vec3::Y * r, marker);
            node.geometry.line(
                Vec3::new(self.pose.0, self.pose.1, 0.02),
                at,
                marker.with_alpha(120),
            );
        }
    }

    fn take_geometry(&mut self, ctx: &mut PluginContext<'_>) -> bool {
        let Some(outcome) = self.geometry_reply.as_ref().and_then(ReplyTicket::try_take) else {
            return false;
        };
        self.geometry_reply = None;
        if let Ok(message) = outcome
            && let Body::Position2d(Position2d::Geometry(g)) = &message.body
            && g.size.sl > 0.0
            && g.size.sw > 0.0
        {
            let height = if g.size.sh > 0.0 { g.size.sh } else { 0.22 };
            self.size = Vec3::new(g.size.sl as f32, g.size.sw as f32, height as f32);
            self.redraw_body(ctx.scene);
            return true;
        }
        false
    }

    fn take_state(&mut self, ctx: &mut PluginContext<'_>) -> bool {
        let Some(sample) = ctx.device.and_then(|d| d.latest(DATA_STATE)) else {
            return false;
        };
        if self.last_seq == Some(sample.seq) {
            return false;
        }
        self.last_seq = Some(sample.seq);
        let Body::Position2d(Position2d::State(state)) = &sample.message.body else {
            return false;
        };
        self.pose = (
            state.pos.px as f32,
            state.pos.py as f32,
            state.pos.pa as f32,
        );
        self.velocity = (state.vel.px as f32, state.vel.pa as f32);
        self.stalled = state.stall != 0;
        if let Some(node) = ctx.scene.get_mut(self.node) {
            node.transform = Affine3A::from_rotation_translation(
                Quat::from_rotation_z(self.pose.2),
                Vec3::new(self.pose.0, self.pose.1, 0.0),
            );
        }
        let here = Vec3::new(self.pose.0, self.pose.1, 0.01);
        if self.trail_length > 0
            && self
                .trail
                .back()
                .is_none_or(|last| last.distance(here) > 0.02)
        {
            self.trail.push_back(here);
            while self.trail.len() > self.trail_length {
                self.trail.pop_front();
            }
        }
        self.redraw_trail(ctx.scene);
        true
    }

    /// Sends a velocity (throttled while driving; a stop is always sent at once).
    fn drive(&mut self, ctx: &PluginContext<'_>, speed: f32, turn: f32) {
        let Some(device) = ctx.device else { return };
        let stop = speed == 0.0 && turn == 0.0;
        if !stop
            && self
                .last_command
                .is_some_and(|t| ctx.now.saturating_duration_since(t) < COMMAND_PERIOD)
        {
            return;
        }
        let cmd = Position2dCmdVel {
            vel: Pose2d::new(f64::from(speed), 0.0, f64::from(turn)),
            state: 1,
        };
        device.command(Body::Position2d(Position2d::Velocity(cmd)));
        self.last_command = Some(ctx.now);
        self.moving = !stop;
    }

    fn stop(&mut self, ctx: &mut PluginContext<'_>) {
        let had_target = self.target.take().is_some();
        self.joystick = None;
        if self.moving || had_target {
            self.drive(ctx, 0.0, 0.0);
        }
        self.redraw_trail(ctx.scene);
    }

    fn teleoperate(&mut self, ctx: &mut PluginContext<'_>) -> bool {
        let connected = ctx.device.is_some_and(|d| d.link_state().is_connected());
        if !connected {
            // The connection dropped: forget what we were doing, so nothing resumes by itself.
            let changed = self.target.is_some() || self.joystick.is_some();
            self.target = None;
            self.joystick = None;
            self.moving = false;
            return changed;
        }
        if let Some(deflection) = self.joystick {
            let (speed, turn) = joystick_velocity(deflection, self.limits);
            self.drive(ctx, speed, turn);
            if deflection == Vec2::ZERO {
                // The person let go: that zero was the last command.
                self.joystick = None;
            }
            return false;
        }
        if let Some(target) = self.target {
            match steer_towards(self.pose, target, self.limits) {
                Some((speed, turn)) => self.drive(ctx, speed, turn),
                None => {
                    self.stop(ctx);
                    return true;
                }
            }
        }
        false
    }

    fn joystick_ui(&mut self, ui: &mut egui::Ui) {
        let size = egui::vec2(110.0, 110.0);
        let (rect, response) = ui.allocate_exact_size(size, egui::Sense::drag());
        let painter = ui.painter_at(rect);
        painter.rect_stroke(
            rect,
            6.0,
            egui::Stroke::new(1.0, egui::Color32::GRAY),
            egui::StrokeKind::Inside,
        );
        let centre = rect.center();
        let mut knob = centre;
        if response.dragged()
            && let Some(pointer) = response.interact_pointer_pos()
        {
            let d = (pointer - centre) / (size.x / 2.0);
            let deflection = Vec2::new(d.x, -d.y).clamp_length_max(1.0);
            knob = centre + egui::vec2(deflection.x, -deflection.y) * size.x / 2.0;
            self.joystick = Some(deflection);
            self.target = None;
        } else if self.joystick.is_some() {
            // Let go: stop at once.
            self.joystick = Some(Vec2::ZERO);
        }
        painter.circle_filled(knob, 9.0, egui::Color32::from_rgb(90, 150, 230));
    }
}

impl Plugin for Position2dPlugin {
    fn save(&self) -> PluginConfig {
        let mut config = self.config.clone();
        config.set("trailLength", self.trail_length.to_string());
        config.set("maxSpeed", format!("{}", self.limits.max_speed));
        config.set("maxTurn", format!("{}", self.limits.max_turn));
        config
    }

    fn title(&self) -> String {
        match &self.config.device {
            Some(d) => format!("Robot {} ({d})", self.config.id),
            None => format!("Robot {}", self.config.id),
        }
    }

    fn update(&mut self, ctx: &mut PluginContext<'_>) -> bool {
        let mut changed = self.take_geometry(ctx);
        changed |= self.take_state(ctx);
        changed |= self.teleoperate(ctx);
        changed
    }

    fn ui(&mut self, ui: &mut egui::Ui, ctx: &mut PluginContext<'_>) {
        let (x, y, a) = self.pose;
        ui.label(format!("pose ({x:.2}, {y:.2}) m, {:.0}°", a.to_degrees()));
        ui.label(format!(
            "velocity {:.2} m/s, {:.2} rad/s",
            self.velocity.0, self.velocity.1
        ));
        if self.stalled {
            ui.colored_label(egui::Color32::from_rgb(230, 90, 80), "STALLED");
        }
        if let Some(device) = ctx.device {
            let state = device.link_state();
            if !state.is_connected() {
                ui.colored_label(egui::Color32::from_rgb(230, 190, 80), format!("{state:?}"));
            }
        }
        ui.add(egui::Slider::new(&mut self.limits.max_speed, 0.0..=2.0).text("max m/s"));
        ui.add(egui::Slider::new(&mut self.limits.max_turn, 0.0..=3.0).text("max rad/s"));
        self.joystick_ui(ui);
        if self.active {
            ui.small("click the ground to send the robot there");
        }
    }

    fn services(&self) -> Vec<Service> {
        vec![
            Service {
                name: "Stop",
                description: "zero velocity and forget the target",
            },
            Service {
                name: "Clear trail",
                description: "forget the poses drawn behind the robot",
            },
        ]
    }

    fn run_service(&mut self, name: &str, ctx: &mut PluginContext<'_>) {
        match name {
            "Stop" => self.stop(ctx),
            "Clear trail" => {
                self.trail.clear();
                self.redraw_trail(ctx.scene);
            }
            _ => {}
        }
    }

    fn on_event(&mut self, event: &InputEvent, ctx: &mut PluginContext<'_>) -> Handled {
        match event {
            InputEvent::Activated(active) => {
                self.active = *active;
                self.redraw_body(ctx.scene);
                Handled::Yes
            }
            InputEvent::GroundClicked(point) if self.active => {
                self.target = Some(Vec2::new(point.x, point.y));
                self.joystick = None;
                self.redraw_trail(ctx.scene);
                Handled::Yes
            }
            InputEvent::StopAll => {
                self.stop(ctx);
                Handled::No
            }
            _ => Handled::No,
        }
    }

    fn can_be_active(&self) -> bool {
        self.config.device.is_some()
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn detach(&mut self, scene: &mut Scene, anchors: &mut Anchors) {
        if self.anchor.is_some() {
            anchors.withdraw(self.node);
        }
        scene.remove(self.node);
        scene.remove(self.trail_node);
    }
}
