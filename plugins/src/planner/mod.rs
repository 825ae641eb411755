//! `libpv3d_planner`: a path planner (Player's `planner`, e.g. wavefront) — the path it drives
//! the robot along, its way-points and its goal. The way-points are asked for whenever the
//! state announces a new plan ([`plan::PlanWatch`]).
//!
//! Giving the goal: the planner is an active handler of its own (select it in the item tree,
//! with Tab, or by clicking its goal flag). While it is active, a click on the ground sends
//! the planner a goal there, instead of the robot driving straight to it; a drag gives the
//! goal's heading too (press at the goal, drag the way to face), as the localizer's pose is
//! given. Selecting the robot itself and clicking the ground sends the planner the goal too,
//! when this planner drives that robot ([`handoff`] says how they are paired); a robot with no
//! planner of its own still drives straight there.
//!
//! Parameters: `color` (#f0c828). The plan is in the map's frame, the scene's world frame: it
//! hangs below no robot.

pub mod draw;
pub mod handoff;
pub mod plan;

use glam::Vec3;
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::planner::{
    Planner, PlannerCmd, PlannerData, PlannerEnable, PlannerWaypoints,
};

use crate::localize::pose_drag::{DragStep, PoseDrag};
use framework::config::{ConfigValueError, PluginConfig};
use framework::device::{Awaited, LastTaken};
use framework::plugin::{Handled, InputEvent, Plugin, PluginContext, Service};
use framework::registry::Metadata;
use framework::scene::{Aabb, NodeId, Object3D, Rgba, Scene};
use plan::PlanWatch;

const ENABLE: &str = "Enable";
const DISABLE: &str = "Disable";
/// The box that picks the goal flag, m.
const FLAG_PICK: Vec3 = Vec3::new(0.4, 0.4, 0.7);

pub struct PlannerPlugin {
    config: PluginConfig,
    color: Rgba,
    /// The path and the goal; picking it selects this handler.
    node: NodeId,
    taken: LastTaken,
    state: Option<PlannerData>,
    watch: PlanWatch,
    waypoints_reply: Option<Awaited<PlannerWaypoints>>,
    waypoints: Vec<Pose2d>,
    drag: PoseDrag,
    active: bool,
    /// Whether the planner was last told to plan (it is, until told otherwise).
    enabled: bool,
    /// The goal last sent, for the panel.
    sent_goal: Option<Pose2d>,
}

impl PlannerPlugin {
    pub const METADATA: Metadata = crate::standard_metadata(
        "A path planner's plan: the path through its way-points and the goal; select it and click the ground to send the planner a goal.",
    );

    pub fn create(
        config: PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Box<dyn Plugin>, ConfigValueError> {
        let color = config.color("color", Rgba::rgb(240, 200, 40))?;
        let mut object = Object3D::new(config.titled("planner"));
        object.tags.push("planner".into());
        let node = ctx.scene.add(object);
        Ok(Box::new(PlannerPlugin {
            config,
            color,
            node,
            taken: LastTaken::default(),
            state: None,
            watch: PlanWatch::default(),
            waypoints_reply: None,
            waypoints: Vec::new(),
            drag: PoseDrag::default(),
            active: false,
            enabled: true,
            sent_goal: None,
        }))
    }

    fn redraw(&self, scene: &mut Scene) {
        let Some(object) = scene.get_mut(self.node) else {
            return;
        };
        match &self.state {
            Some(state) => draw::plan(&mut object.geometry, state, &self.waypoints, self.color),
            None => object.geometry.clear(),
        }
        object.pick_bounds = self.state.filter(|s| s.is_valid() || s.is_done()).map(|s| {
            let at = Vec3::new(s.goal.px as f32, s.goal.py as f32, FLAG_PICK.z / 2.0);
            Aabb::centred(at, FLAG_PICK)
        });
        if let Some((at, heading)) = self.drag.preview() {
            let goal = Pose2d::new(
                f64::from(at.x),
                f64::from(at.y),
                f64::from(heading.unwrap_or(0.0)),
            );
            draw::goal_flag(&mut object.geometry, &goal, Rgba::WHITE);
        }
    }

    fn take_waypoints(&mut self) -> bool {
        let Some(outcome) = self.waypoints_reply.as_mut().and_then(Awaited::take) else {
            return false;
        };
        match outcome {
            Ok(reply) => self.waypoints = reply.waypoints,
            Err(e) => tracing::warn!(plugin = %self.config.id, "no way-points: {e}"),
        }
        true
    }

    fn send_goal(&mut self, goal: Pose2d, ctx: &PluginContext<'_>) {
        let Some(device) = ctx.device else { return };
        device.command(Planner::CMD_GOAL.to_body(PlannerCmd { goal }));
        self.sent_goal = Some(goal);
    }

    fn set_enabled(&mut self, enabled: bool, ctx: &PluginContext<'_>) {
        let Some(device) = ctx.device else { return };
        // The reply only confirms; the state messages show what the planner does.
        drop(device.request(
            Planner::REQ_ENABLE.kind(),
            Planner::REQ_ENABLE.to_body(PlannerEnable::new(enabled)),
        ));
        self.enabled = enabled;
    }
}

impl Plugin for PlannerPlugin {
    fn save(&self) -> PluginConfig {
        self.config.clone()
    }

    fn title(&self) -> String {
        self.config.titled("Planner")
    }

    fn run(&mut self, ctx: &mut PluginContext<'_>) {
        let mut changed = self.take_waypoints();
        if let Some((state, _)) = self.taken.newest_of::<PlannerData>(ctx.device) {
            if self.watch.is_new_plan(&state) {
                self.waypoints.clear();
                self.waypoints_reply = Some(Awaited::fetch(ctx.device, Planner::REQ_GET_WAYPOINTS));
            }
            self.state = Some(state);
            changed = true;
        }
        if let Some(state) = self.state {
            let at = glam::Vec2::new(state.pos.px as f32, state.pos.py as f32);
            let robot = handoff::robot_at(ctx.scene, at);
            handoff::claim(ctx.scene, self.node, robot);
        }
        if let Some(point) = handoff::take_goal(ctx.scene, self.node) {
            let keep = self.state.map_or(0.0, |s| s.pos.pa);
            let goal = Pose2d::new(f64::from(point.x), f64::from(point.y), keep);
            tracing::info!(plugin = %self.config.id, "goal from the selected robot: {goal:?}");
            self.send_goal(goal, ctx);
            changed = true;
        }
        if changed {
            self.redraw(ctx.scene);
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {
        match &self.state {
            Some(s) if s.is_done() => {
                ui.label(format!("arrived at ({:.2}, {:.2})", s.goal.px, s.goal.py));
            }
            Some(s) if s.is_valid() => {
                ui.label(format!(
                    "to ({:.2}, {:.2}), way-point {} of {}",
                    s.goal.px,
                    s.goal.py,
                    s.waypoint_idx.saturating_add(1),
                    s.waypoints_count
                ));
            }
            Some(_) => {
                ui.label("no plan");
            }
            None => {
                ui.label("no state yet");
            }
        }
        if !self.enabled {
            ui.colored_label(egui::Color32::from_rgb(230, 190, 80), "disabled");
        }
        if let Some(goal) = self.sent_goal {
            ui.small(format!("goal sent: ({:.2}, {:.2})", goal.px, goal.py));
        }
        if self.active {
            ui.small("click the ground to send a goal; Ctrl+drag to give its heading");
        }
    }

    fn active_ui(&mut self, ui: &mut egui::Ui, _ctx: &mut PluginContext<'_>) {
        ui.strong(self.title());
        ui.small("click the ground: goal for the planner");
    }

    fn services(&self) -> Vec<Service> {
        if self.enabled {
            vec![Service::run(
                DISABLE,
                "tell the planner to stop driving the robot",
            )]
        } else {
            vec![Service::run(
                ENABLE,
                "let the planner drive the robot again",
            )]
        }
    }

    fn run_service(&mut self, name: &str, ctx: &mut PluginContext<'_>) {
        match name {
            ENABLE => self.set_enabled(true, ctx),
            DISABLE => self.set_enabled(false, ctx),
            _ => {}
        }
    }

    fn on_event(&mut self, event: &InputEvent, ctx: &mut PluginContext<'_>) -> Handled {
        let step = self
            .drag
            .follow(event, self.active, self.state.map_or(0.0, |s| s.pos.pa));
        match step {
            DragStep::Activated(active) => self.active = active,
            DragStep::Released(goal) => self.send_goal(goal, ctx),
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
    }
}
