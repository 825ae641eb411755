//! What a robot offers to do with a clicked object: "Go to" (drive next to it) and "Follow"
//! (keep near it, found again by its identity as it moves, until stopped).

use glam::Vec2;

use super::Position2dPlugin;
use super::goal::{Goal, stand_off};
use framework::action::{Action, ObjectRef};
use framework::plugin::PluginContext;

/// The robot's action names: shown in the popup, and how a query's "go to" and "follow" an
/// object are carried out.
pub(super) const GO_TO: &str = "Go to";
pub(super) const FOLLOW: &str = "Follow";

impl Position2dPlugin {
    pub(super) fn offered_actions(&self, target: &ObjectRef) -> Vec<Action> {
        if target.node == self.node || target.tags.is_empty() || self.config.device.is_none() {
            return Vec::new();
        }
        let what = target.describe();
        let d = self.follow_distance;
        vec![
            Action {
                name: GO_TO,
                description: format!("drive next to {what}, stopping {d:.1} m short of it"),
            },
            Action {
                name: FOLLOW,
                description: format!("keep {d:.1} m from {what} wherever it goes, until stopped"),
            },
        ]
    }

    pub(super) fn act(&mut self, action: &str, target: &ObjectRef, ctx: &mut PluginContext<'_>) {
        let robot = Vec2::new(self.pose.0, self.pose.1);
        let object = target.position.truncate();
        match action {
            GO_TO => match stand_off(robot, object, self.follow_distance) {
                Some(aim) => self.set_goal(Goal::Point(aim), ctx),
                None => tracing::info!("{} is already next to {}", self.config.id, target.name),
            },
            FOLLOW => self.set_goal(
                Goal::Follow {
                    target: target.clone(),
                    last_seen: object,
                },
                ctx,
            ),
            other => tracing::warn!("{}: no action {other:?}", self.config.id),
        }
    }
}
