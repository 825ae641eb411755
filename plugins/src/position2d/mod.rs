//! `libpv3d_position2d`: a mobile base — its body at the pose it reports, a pose trail, a
//! velocity readout, and tele-operation: velocity limits, a joystick, a target clicked or
//! dragged over the ground, and actions on clicked objects ("Go to", "Follow"). In velocity
//! mode the viewer steers with velocity commands; in position mode it sends Player way-points
//! and the server drives. Safe by default: zero velocity when the person lets go, when every
//! robot is stopped (Space, focus lost), when the connection drops and when it comes back.
//!
//! Parameters: `trailLength` (200 poses), `maxSpeed` (0.5 m/s), `maxTurn` (1.0 rad/s),
//! `color` (#3c8cdc), `mode` (`velocity` or `position`; velocity), `followDistance` (0.8 m:
//! how far short of an object "Go to" and "Follow" stop), `skinFile` (an OBJ model drawn
//! in place of the box, fitted to the robot's size; see [`framework::skin`]).
//!
//! Queries it answers (`answers.rs`): "go to" `<point x y/>` or an object, "follow" an object
//! (`object="name"` or `tag="person"`), "stop", "where are you". Before driving to a point it
//! asks the map and the zones about it (`goal_check.rs`), and while it drives it keeps out of
//! the zones it avoids (`zone_guard.rs`; `avoidZones`, "keep out" by default).

mod actions;
mod answers;
mod body;
mod condition;
mod driving;
mod goal;
mod goal_check;
mod planner_goal;
mod teleop;
mod trail;
mod widgets;
mod zone_guard;

use std::time::Instant;

use glam::{Vec2, Vec3};
use player_proto::interfaces::position2d::{Position2d, Position2dData, Position2dGeometry};

pub use body::body_geometry;
pub use condition::{LINK_DOWN, STALE, STALE_AFTER, STALLED};
pub use goal::{DriveMode, Goal, stand_off};
pub use teleop::{ARRIVED, Limits, joystick_velocity, steer_towards, wrap_angle};
pub use widgets::joystick_id;
pub use zone_guard::{LOOKAHEAD, ZoneGuard};

use framework::action::{Action, ObjectRef};
use framework::config::{ConfigValueError, PluginConfig};
use framework::device::{Awaited, LastTaken};
use framework::plugin::{AnchorKey, Handled, InputEvent, Plugin, PluginContext, Service};
use framework::query::{Query, QueryError, Reply};
use framework::registry::Metadata;
use framework::scene::pose::transform_of_2d;
use framework::scene::{Aabb, NodeId, Object3D, Rgba, Scene};
use framework::skin::Skin;
use trail::Trail;

const GO_TO_POINT: &str = "Go to point…";

pub struct Position2dPlugin {
    config: PluginConfig,
    color: Rgba,
    node: NodeId,
    trail_node: NodeId,
    anchor: Option<AnchorKey>,
    geometry_reply: Awaited<Position2dGeometry>,
    size: Vec3,
    state_taken: LastTaken,
    pose: (f32, f32, f32),
    velocity: (f32, f32),
    stalled: bool,
    /// Zones this robot will not be sent into (`avoidZones`), and what it knows of its way.
    zone_guard: ZoneGuard,
    /// Why the last goal was given up, for the panel.
    refused: Option<String>,
    /// When the last odometry arrived (data older than `condition::STALE_AFTER` is stale).
    last_data: Option<Instant>,
    trail: Trail,
    limits: Limits,
    active: bool,
    mode: DriveMode,
    /// How far short of an object "Go to" and "Follow" stop, m.
    follow_distance: f32,
    goal: Option<Goal>,
    /// A target being dragged over the ground, not sent yet.
    dragging: Option<Vec2>,
    joystick: Option<Vec2>,
    /// Something other than zero was commanded and not yet cancelled.
    moving: bool,
    last_command: Option<Instant>,
    /// The way-point last sent in position mode.
    sent_waypoint: Option<Vec2>,
    /// Whether the link was up at the last update (a zero velocity follows its return).
    link_up: bool,
    /// The point typed into the "Go to point…" popup.
    typed_point: Vec2,
    /// The OBJ body (`skinFile`), or why the box is drawn.
    skin: Skin,
}

impl Position2dPlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A robot's body at its odometry pose, with its trail; select it to drive it by clicking, dragging a target or the joystick, or to go to or follow a tagged object.",
    );

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
        let mode = match config.param("mode") {
            None => DriveMode::Velocity,
            Some(p) => DriveMode::parse(&p.text).ok_or_else(|| ConfigValueError {
                origin: p.origin.clone(),
                library: config.library.clone(),
                param: "mode".into(),
                message: format!("expected velocity or position, found {:?}", p.text.trim()),
            })?,
        };
        let follow_distance = config.number("followDistance", 0.8, 0.0..=50.0)? as f32;
        let zone_guard = ZoneGuard::new(
            config
                .param("avoidZones")
                .map_or(goal_check::DEFAULT_AVOID_ZONES, |p| p.text.as_str()),
        );
        let size = Vec3::new(0.44, 0.38, 0.22);
        let mut object = Object3D::new(config.id.clone());
        object
            .tags
            .extend(["robot".to_string(), "position2d".to_string()]);
        object.pick_bounds = Some(Aabb::centred(Vec3::new(0.0, 0.0, size.z / 2.0), size));
        let skin = Skin::from_config(&config);
        body_geometry(
            &mut object.geometry,
            size,
            color,
            false,
            &config.id,
            skin.mesh.as_deref(),
        );
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
        let geometry_reply = Awaited::fetch(ctx.device, Position2d::REQ_GET_GEOM);
        Ok(Box::new(Position2dPlugin {
            config,
            color,
            node,
            trail_node,
            anchor,
            geometry_reply,
            size,
            state_taken: LastTaken::default(),
            pose: (0.0, 0.0, 0.0),
            velocity: (0.0, 0.0),
            stalled: false,
            last_data: None,
            zone_guard,
            refused: None,
            trail: Trail::new(trail_length),
            limits,
            active: false,
            mode,
            follow_distance,
            goal: None,
            dragging: None,
            joystick: None,
            moving: false,
            last_command: None,
            sent_waypoint: None,
            link_up: ctx.device.is_some_and(|d| d.is_connected()),
            typed_point: Vec2::ZERO,
            skin,
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
                self.skin.mesh.as_deref(),
            );
            node.pick_bounds = Some(Aabb::centred(
                Vec3::new(0.0, 0.0, self.size.z / 2.0),
                self.size,
            ));
        }
    }

    fn redraw_trail(&self, scene: &mut Scene) {
        if let Some(node) = scene.get_mut(self.trail_node) {
            let robot = Vec2::new(self.pose.0, self.pose.1);
            let (goal, dragging) = (self.goal.as_ref(), self.dragging);
            self.trail
                .draw(&mut node.geometry, self.color, robot, goal, dragging);
        }
    }

    fn take_geometry(&mut self, ctx: &mut PluginContext<'_>) {
        let Some(outcome) = self.geometry_reply.take() else {
            return;
        };
        if let Ok(g) = outcome
            && g.size.sl > 0.0
            && g.size.sw > 0.0
        {
            let height = if g.size.sh > 0.0 { g.size.sh } else { 0.22 };
            self.size = Vec3::new(g.size.sl as f32, g.size.sw as f32, height as f32);
            self.redraw_body(ctx.scene);
        }
    }

    fn take_state(&mut self, ctx: &mut PluginContext<'_>) {
        let Some((state, sample)) = self.state_taken.newest_of::<Position2dData>(ctx.device) else {
            return;
        };
        self.last_data = Some(sample.received);
        self.pose = (
            state.pos.px as f32,
            state.pos.py as f32,
            state.pos.pa as f32,
        );
        self.velocity = (state.vel.px as f32, state.vel.pa as f32);
        self.stalled = state.stall != 0;
        if let Some(node) = ctx.scene.get_mut(self.node) {
            node.transform = transform_of_2d(&state.pos);
        }
        self.trail.record(Vec2::new(self.pose.0, self.pose.1));
        self.redraw_trail(ctx.scene);
    }
}

impl Plugin for Position2dPlugin {
    fn save(&self) -> PluginConfig {
        let mut config = self.config.clone();
        config.set("trailLength", self.trail.capacity().to_string());
        config.set("maxSpeed", format!("{}", self.limits.max_speed));
        config.set("maxTurn", format!("{}", self.limits.max_turn));
        config.set("mode", self.mode.name());
        config.set("followDistance", format!("{}", self.follow_distance));
        config
    }

    fn title(&self) -> String {
        match &self.config.device {
            Some(d) => format!("Robot {} ({d})", self.config.id),
            None => format!("Robot {}", self.config.id),
        }
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        self.take_geometry(ctx);
        self.take_state(ctx);
        self.tag_condition(ctx);
        self.teleoperate(ctx);
    }

    fn ui(&mut self, ui: &mut egui::Ui, ctx: &mut PluginContext<'_>) {
        self.panel(ui, ctx);
    }

    fn active_ui(&mut self, ui: &mut egui::Ui, ctx: &mut PluginContext<'_>) {
        ui.strong(&self.config.id);
        if let Some(goal) = &self.goal {
            ui.small(match goal {
                Goal::Point(p) => format!("to ({:.2}, {:.2})", p.x, p.y),
                Goal::Follow { target, .. } => format!("following {}", target.name),
            });
        }
        self.joystick_ui(ui, "view");
        if ui.button("Stop").clicked() {
            self.stop(ctx);
        }
    }

    fn services(&self) -> Vec<Service> {
        vec![
            Service::run("Stop", "zero velocity and forget the target"),
            Service::popup(GO_TO_POINT, "type a point to send the robot to"),
            Service::run("Clear trail", "forget the poses drawn behind the robot"),
        ]
    }

    fn service_popup(
        &mut self,
        name: &str,
        ui: &mut egui::Ui,
        ctx: &mut PluginContext<'_>,
    ) -> bool {
        name == GO_TO_POINT && self.go_to_point_popup(ui, ctx)
    }

    fn actions_on(&self, target: &ObjectRef) -> Vec<Action> {
        self.offered_actions(target)
    }

    fn run_action(&mut self, action: &str, target: &ObjectRef, ctx: &mut PluginContext<'_>) {
        self.act(action, target, ctx);
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
                if !self.goal_to_planner(point.truncate(), ctx) {
                    self.set_goal(Goal::Point(point.truncate()), ctx);
                }
                Handled::Yes
            }
            InputEvent::TargetDragged(point) if self.active => {
                self.dragging = Some(point.truncate());
                self.redraw_trail(ctx.scene);
                Handled::Yes
            }
            InputEvent::TargetDragCancelled => {
                self.dragging = None;
                self.redraw_trail(ctx.scene);
                Handled::No
            }
            InputEvent::StopAll => {
                self.stop(ctx);
                Handled::No
            }
            _ => Handled::No,
        }
    }

    fn answer(&mut self, query: &Query, ctx: &mut PluginContext<'_>) -> Option<Reply> {
        self.answer_query(query, ctx)
    }

    fn on_reply(&mut self, q: &Query, r: &Result<Reply, QueryError>, ctx: &mut PluginContext<'_>) {
        if !self.zone_guard.take_reply(q, r) {
            self.goal_checked(q, r, ctx);
        }
    }

    fn can_be_active(&self) -> bool {
        self.config.device.is_some()
    }

    fn node(&self) -> Option<NodeId> {
        Some(self.node)
    }

    fn clean(&mut self, ctx: &mut PluginContext<'_>) {
        if self.anchor.is_some() {
            ctx.anchors.withdraw(self.node);
        }
        ctx.scene.remove(self.node);
        ctx.scene.remove(self.trail_node);
    }
}
