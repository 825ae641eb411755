//! Velocity control toward a waypoint, in the frame of the localize estimate: turn toward the
//! waypoint, drive when roughly facing it, and once on it turn to its heading. Player's
//! wavefront hands the waypoint to Stage's position controller as a position command; driving
//! by velocity from the estimate does the same job and stays right when the estimate's frame
//! is not the odometry's (after a set pose).

use crate::sim::wrap;
use crate::world::Pose;

/// Top forward speed, m/s (a Pioneer's usual navigation speed).
pub const MAX_SPEED: f64 = 0.5;
/// Top turn rate, rad/s.
pub const MAX_TURN: f64 = 1.0;
/// Turn rate per radian of heading error, 1/s.
const TURN_GAIN: f64 = 2.0;
/// Forward speed per metre of distance left, 1/s: slows down on arrival.
const SPEED_GAIN: f64 = 1.0;
/// Facing further off than this, the robot turns on the spot before driving, rad.
const DRIVE_WITHIN: f64 = 0.5;
/// Nearer than this the robot is on the waypoint and only turns to its heading, m.
const ON_SPOT: f64 = 0.05;

/// Forward speed and turn rate that take a robot at `at` toward `to` (position, then heading).
pub fn toward(at: Pose, to: Pose) -> (f64, f64) {
    let (dx, dy) = (to.x - at.x, to.y - at.y);
    let distance = dx.hypot(dy);
    if distance < ON_SPOT {
        return (0.0, turn(wrap(to.a - at.a)));
    }
    let error = wrap(dy.atan2(dx) - at.a);
    let speed = if error.abs() < DRIVE_WITHIN {
        (SPEED_GAIN * distance).min(MAX_SPEED) * error.cos()
    } else {
        0.0
    };
    (speed, turn(error))
}

fn turn(error: f64) -> f64 {
    (TURN_GAIN * error).clamp(-MAX_TURN, MAX_TURN)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn turns_first_then_drives_then_faces_the_heading() {
        let at = Pose::default();
        let behind = Pose {
            x: -2.0,
            y: 0.0,
            a: 0.0,
        };
        let (v, w) = toward(at, behind);
        assert_eq!(v, 0.0);
        assert_eq!(w.abs(), MAX_TURN);
        let ahead = Pose {
            x: 2.0,
            y: 0.1,
            a: 0.0,
        };
        let (v, w) = toward(at, ahead);
        assert!(v > 0.45 && w > 0.0);
        let here = Pose {
            x: 0.01,
            y: 0.0,
            a: -1.0,
        };
        let (v, w) = toward(at, here);
        assert_eq!(v, 0.0);
        assert!(w < 0.0);
    }
}
