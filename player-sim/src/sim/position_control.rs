//! Position control (Player's `CMD_POS`, Stage's `GoTo`) as Stage 4.3 steers to a goal: the
//! goal is in the frame the robot reports its pose in (the world with gps, the odometry's
//! with odom), and each step gives a velocity from the error between the robot's estimate as
//! it stood at the previous step (Stage's controller reads its pose estimate before updating
//! it) and the goal, which the robot's `velocity_bounds` then hold as any command. Stage takes no
//! speed from the command: its controller's own limits are 0.4 m/s and 1 rad/s.
//!
//! A differential robot turns towards the goal point, drives when it faces it within π/16
//! (at the distance left per second, at most 0.4 m/s), and within 2 cm of it turns to the
//! goal's heading; it never stops by itself (the goal keeps steering it). Stage's turn is held
//! at -1 rad/s below only (a left turn is limited by the velocity bounds alone: 90 degrees a
//! second by default). An omnidirectional robot takes the error along each world axis as its
//! velocity along its own axes, each at most 0.4 m/s (1 rad/s turning), as Stage's does;
//! that is right when it faces east.

use crate::world::{Drive, Pose};

/// Stage's position controller's speed limits: forward and sideways m/s, turning rad/s.
const MAX_SPEED: f64 = 0.4;
const MAX_TURN: f64 = 1.0;
/// Within this of the goal point on both axes, a differential robot only turns, m.
const CLOSE_ENOUGH: f64 = 0.02;

/// The velocity (robot frame: forward, sideways, turn) Stage's controller gives a robot
/// reporting `at` and steering to `goal`.
pub fn goto_velocity(drive: Drive, at: Pose, goal: Pose) -> (f64, f64, f64) {
    let (x_error, y_error) = (goal.x - at.x, goal.y - at.y);
    let a_error = super::wrap(goal.a - at.a);
    match drive {
        Drive::Omni => (
            x_error.min(MAX_SPEED),
            y_error.min(MAX_SPEED),
            a_error.min(MAX_TURN),
        ),
        Drive::Diff => {
            if x_error.abs() < CLOSE_ENOUGH && y_error.abs() < CLOSE_ENOUGH {
                return (0.0, 0.0, a_error.max(-MAX_TURN));
            }
            let facing = super::wrap(y_error.atan2(x_error) - at.a);
            let forward = if facing.abs() < std::f64::consts::PI / 16.0 {
                x_error.hypot(y_error).min(MAX_SPEED)
            } else {
                0.0
            };
            (forward, 0.0, facing.max(-MAX_TURN))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_differential_robot_turns_first_then_drives_then_turns_to_the_heading() {
        let at = Pose::default();
        let behind = Pose {
            x: -2.0,
            y: 0.0,
            a: 0.0,
        };
        let (vx, _, va) = goto_velocity(Drive::Diff, at, behind);
        assert_eq!(vx, 0.0, "not facing it: turns on the spot");
        assert!(
            (va - std::f64::consts::PI).abs() < 1e-12,
            "left turns are not held to 1"
        );
        let right = Pose {
            x: 0.0,
            y: -2.0,
            a: 0.0,
        };
        assert_eq!(goto_velocity(Drive::Diff, at, right).2, -MAX_TURN);
        let ahead = Pose {
            x: 3.0,
            y: 0.1,
            a: 1.0,
        };
        let (vx, _, va) = goto_velocity(Drive::Diff, at, ahead);
        assert_eq!(vx, MAX_SPEED);
        assert!((va - 0.1f64.atan2(3.0)).abs() < 1e-12, "{va}");
        let near = Pose {
            x: 0.1,
            y: 0.0,
            a: 0.0,
        };
        assert!((goto_velocity(Drive::Diff, at, near).0 - 0.1).abs() < 1e-12);
        let here = Pose {
            x: 0.01,
            y: -0.01,
            a: 0.5,
        };
        assert_eq!(goto_velocity(Drive::Diff, at, here), (0.0, 0.0, 0.5));
    }

    #[test]
    fn an_omnidirectional_robot_takes_each_axis_error_held_above_only() {
        let goal = Pose {
            x: 2.0,
            y: -3.0,
            a: 0.2,
        };
        let (vx, vy, va) = goto_velocity(Drive::Omni, Pose::default(), goal);
        assert_eq!((vx, vy), (MAX_SPEED, -3.0));
        assert!((va - 0.2).abs() < 1e-12, "{va}");
    }
}
