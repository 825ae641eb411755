//! When the planner has a new plan: its state message carries only the goal and the number of
//! way-points, so the way-points themselves are asked for when either changes (or the plan
//! becomes valid), not on every state message.

use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::planner::PlannerData;

/// What identifies one plan in the state messages.
#[derive(Debug, Clone, Copy, PartialEq)]
struct PlanKey {
    goal: Pose2d,
    waypoints_count: u32,
}

/// The plan last seen, to tell a new one.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PlanWatch {
    seen: Option<PlanKey>,
}

impl PlanWatch {
    /// Whether `state` announces a plan whose way-points have not been asked for yet. An
    /// invalid state (no path found) is no plan: it is forgotten, so that the same goal
    /// becoming reachable again counts as new.
    pub fn is_new_plan(&mut self, state: &PlannerData) -> bool {
        if !state.is_valid() || state.waypoints_count == 0 {
            self.seen = None;
            return false;
        }
        let key = PlanKey {
            goal: state.goal,
            waypoints_count: state.waypoints_count,
        };
        let new = self.seen != Some(key);
        self.seen = Some(key);
        new
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn state(valid: bool, goal_x: f64, count: u32, index: i32) -> PlannerData {
        PlannerData {
            valid: u8::from(valid),
            goal: Pose2d::new(goal_x, 0.0, 0.0),
            waypoints_count: count,
            waypoint_idx: index,
            ..PlannerData::default()
        }
    }

    #[test]
    fn a_new_goal_or_count_is_a_new_plan_progress_is_not() {
        let mut watch = PlanWatch::default();
        assert!(watch.is_new_plan(&state(true, 1.0, 4, 0)));
        assert!(!watch.is_new_plan(&state(true, 1.0, 4, 2)), "only progress");
        assert!(watch.is_new_plan(&state(true, 1.0, 5, 0)), "replanned");
        assert!(watch.is_new_plan(&state(true, 2.0, 5, 0)), "another goal");
    }

    #[test]
    fn an_invalid_plan_is_none_and_its_return_is_new() {
        let mut watch = PlanWatch::default();
        assert!(watch.is_new_plan(&state(true, 1.0, 4, 0)));
        assert!(!watch.is_new_plan(&state(false, 1.0, 4, 0)));
        assert!(watch.is_new_plan(&state(true, 1.0, 4, 0)));
        assert!(!watch.is_new_plan(&state(true, 3.0, 0, 0)), "no way-points");
    }
}
