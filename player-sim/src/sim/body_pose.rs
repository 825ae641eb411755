//! Where a part mounted on a robot, or a body shifted by its model's `origin`, lies in the
//! world: the one composition of poses every sensor, body and gripper reads, kept below them
//! all.

use super::wrap;
use crate::world::Pose;

/// `pose` (on the robot) composed with the robot's pose.
pub fn on_robot(robot: Pose, local: Pose) -> Pose {
    let (s, c) = robot.a.sin_cos();
    Pose {
        x: robot.x + c * local.x - s * local.y,
        y: robot.y + s * local.x + c * local.y,
        a: wrap(robot.a + local.a),
    }
}

/// Where a body shifted by `origin` (Stage's `origin`) lies when its model is at `pose`; the
/// pose itself, without trigonometry, for the usual unshifted body.
pub fn body_at(pose: Pose, origin: Pose) -> Pose {
    if origin == Pose::default() {
        pose
    } else {
        on_robot(pose, origin)
    }
}
