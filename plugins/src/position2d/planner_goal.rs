//! A ground click on a robot that a planner drives goes to that planner as its goal, so the
//! robot finds its way round walls instead of driving straight into them. The pairing rule is
//! the planner's ([`crate::planner::handoff`]).

use glam::Vec2;

use super::Position2dPlugin;
use crate::planner::handoff;
use framework::plugin::PluginContext;

impl Position2dPlugin {
    /// Hands a clicked `point` to the planner driving this robot, stopping the robot's own
    /// driving first; `false` (nothing done) when no planner drives it.
    pub(super) fn goal_to_planner(&mut self, point: Vec2, ctx: &mut PluginContext<'_>) -> bool {
        let Some(planner) = handoff::planner_of(ctx.scene, self.node) else {
            return false;
        };
        self.stop(ctx);
        handoff::request_goal(ctx.scene, planner, point);
        true
    }
}
