//! What a plan looks like on the floor: the path from the robot through the way-points still
//! ahead (those passed faint), a dot at each way-point, and the goal as a flag with its
//! heading; the goal being given by hand as an outline.

use glam::{Vec2, Vec3};
use player_proto::interfaces::common::Pose2d;
use player_proto::interfaces::planner::PlannerData;

use framework::scene::{Geometry, Rgba};

/// Height above the floor the path is drawn at, m.
const LIFT: f32 = 0.04;
/// The goal flag's pole height and pennant length, m.
const POLE: f32 = 0.6;
const PENNANT: f32 = 0.25;
/// Length of the goal's heading arrow on the floor, m.
const HEADING: f32 = 0.4;
/// Opacity of the part of the path already travelled.
const PASSED_ALPHA: u8 = 70;

fn floor(p: Vec2) -> Vec3 {
    p.extend(LIFT)
}

fn point(pose: &Pose2d) -> Vec2 {
    Vec2::new(pose.px as f32, pose.py as f32)
}

/// The goal flag at `goal`: a pole, a pennant and the heading along the floor.
pub fn goal_flag(geometry: &mut Geometry, goal: &Pose2d, color: Rgba) {
    let at = point(goal);
    let top = at.extend(POLE);
    geometry.line(floor(at), top, color);
    geometry.triangle(
        top,
        top - Vec3::Z * (PENNANT / 2.0),
        top + Vec3::new(PENNANT, 0.0, -PENNANT / 4.0),
        color,
    );
    let ahead = at + Vec2::from_angle(goal.pa as f32) * HEADING;
    geometry.line(floor(at), floor(ahead), color);
}

/// Fills `geometry` (cleared first) with the plan: `waypoints` as last fetched and the state's
/// progress along them, then the goal.
pub fn plan(geometry: &mut Geometry, state: &PlannerData, waypoints: &[Pose2d], color: Rgba) {
    geometry.clear();
    if state.is_valid() && !state.is_done() {
        let next = usize::try_from(state.waypoint_idx)
            .unwrap_or(0)
            .min(waypoints.len());
        let passed = color.with_alpha(PASSED_ALPHA);
        for pair in waypoints[..next].windows(2) {
            geometry.line(floor(point(&pair[0])), floor(point(&pair[1])), passed);
        }
        let mut ahead = vec![point(&state.pos)];
        ahead.extend(waypoints[next..].iter().map(point));
        for pair in ahead.windows(2) {
            geometry.line(floor(pair[0]), floor(pair[1]), color);
        }
        for (i, waypoint) in waypoints.iter().enumerate() {
            geometry.point(
                floor(point(waypoint)),
                if i < next { passed } else { color },
            );
        }
    }
    if state.is_valid() || state.is_done() {
        goal_flag(geometry, &state.goal, color);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_path_runs_from_the_robot_through_the_waypoints_ahead() {
        let state = PlannerData {
            valid: 1,
            pos: Pose2d::new(0.5, 0.0, 0.0),
            goal: Pose2d::new(3.0, 0.0, 0.0),
            waypoint_idx: 1,
            waypoints_count: 3,
            ..PlannerData::default()
        };
        let waypoints = [
            Pose2d::new(0.0, 0.0, 0.0),
            Pose2d::new(1.0, 0.0, 0.0),
            Pose2d::new(3.0, 0.0, 0.0),
        ];
        let mut g = Geometry::default();
        plan(&mut g, &state, &waypoints, Rgba::WHITE);
        let solid: Vec<Vec3> = g
            .lines
            .iter()
            .filter(|v| v.color == Rgba::WHITE && v.pos.z == LIFT)
            .map(|v| v.pos)
            .collect();
        // Robot → waypoint 1 → waypoint 2, then the goal's heading arrow.
        assert_eq!(solid[0], Vec3::new(0.5, 0.0, LIFT));
        assert_eq!(solid[1], Vec3::new(1.0, 0.0, LIFT));
        assert_eq!(solid[3], Vec3::new(3.0, 0.0, LIFT));
        assert_eq!(g.points.len(), 3);
        assert_eq!(g.points[0].color.0[3], PASSED_ALPHA, "waypoint 0 is behind");
        assert_eq!(g.triangles.len(), 3, "the pennant");
    }

    #[test]
    fn an_invalid_plan_draws_nothing_and_a_finished_one_its_goal_only() {
        let mut g = Geometry::default();
        plan(&mut g, &PlannerData::default(), &[], Rgba::WHITE);
        assert!(g.is_empty());
        let done = PlannerData {
            done: 1,
            ..PlannerData::default()
        };
        plan(&mut g, &done, &[Pose2d::default(); 2], Rgba::WHITE);
        assert!(g.points.is_empty() && !g.triangles.is_empty());
    }
}
