//! Commands from ROS 2 before they reach a robot: a `cmd_vel` with a NaN, an infinity or an
//! absurd speed is refused (and said once per kind); a robot whose `cmd_vel` publisher goes
//! quiet is stopped after a deadline, so no robot keeps driving after teleop dies.

use std::time::{Duration, Instant};

use crate::msgs::Twist;

/// Faster than this is not a command but a mistake, m/s.
pub const MOST_SPEED: f64 = 5.0;
/// Faster turning than this likewise, rad/s.
pub const MOST_TURN: f64 = 10.0;
/// Without a fresh `cmd_vel` for this long, a moving robot is stopped (teleop_twist_keyboard
/// repeats its command at 10 Hz; joysticks at 20).
pub const DEADLINE: Duration = Duration::from_millis(500);

/// Why a `cmd_vel` was not forwarded.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Refused {
    #[error("a cmd_vel with a value that is not a number or infinite: {0:?}")]
    NotFinite((f64, f64, f64)),
    #[error("a cmd_vel faster than {MOST_SPEED} m/s or {MOST_TURN} rad/s: {0:?}")]
    Absurd((f64, f64, f64)),
}

/// The velocity (vx, vy, yaw rate) a `Twist` asks of a planar base.
pub fn velocity(twist: &Twist) -> Result<(f64, f64, f64), Refused> {
    let asked = (twist.linear.x, twist.linear.y, twist.angular.z);
    let all = [
        twist.linear.x,
        twist.linear.y,
        twist.linear.z,
        twist.angular.x,
        twist.angular.y,
        twist.angular.z,
    ];
    if all.iter().any(|v| !v.is_finite()) {
        return Err(Refused::NotFinite(asked));
    }
    if asked.0.hypot(asked.1) > MOST_SPEED || asked.2.abs() > MOST_TURN {
        return Err(Refused::Absurd(asked));
    }
    Ok(asked)
}

/// When a robot driven from ROS 2 must be stopped.
#[derive(Debug, Default)]
pub struct Deadline {
    /// When the last forwarded command came, while the robot is moving.
    moving_since: Option<Instant>,
}

impl Deadline {
    /// A command was forwarded at `now`.
    pub fn commanded(&mut self, velocity: (f64, f64, f64), now: Instant) {
        let still = velocity == (0.0, 0.0, 0.0);
        self.moving_since = (!still).then_some(now);
    }

    /// Whether the robot must be stopped now (once: then it is still).
    pub fn expired(&mut self, now: Instant) -> bool {
        match self.moving_since {
            Some(at) if now.duration_since(at) >= DEADLINE => {
                self.moving_since = None;
                true
            }
            _ => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::msgs::Vector3;

    fn twist(x: f64, z: f64) -> Twist {
        Twist {
            linear: Vector3 { x, y: 0.0, z: 0.0 },
            angular: Vector3 { x: 0.0, y: 0.0, z },
        }
    }

    #[test]
    fn absurd_commands_are_refused() {
        assert_eq!(velocity(&twist(0.5, 0.2)), Ok((0.5, 0.0, 0.2)));
        assert!(matches!(
            velocity(&twist(f64::NAN, 0.0)),
            Err(Refused::NotFinite(_))
        ));
        assert!(matches!(
            velocity(&twist(0.0, f64::INFINITY)),
            Err(Refused::NotFinite(_))
        ));
        assert!(matches!(
            velocity(&twist(40.0, 0.0)),
            Err(Refused::Absurd(_))
        ));
        assert!(matches!(
            velocity(&twist(0.0, -11.0)),
            Err(Refused::Absurd(_))
        ));
    }

    #[test]
    fn a_moving_robot_left_without_commands_is_stopped_once() {
        let start = Instant::now();
        let mut deadline = Deadline::default();
        assert!(!deadline.expired(start + DEADLINE * 2), "never commanded");
        deadline.commanded((0.3, 0.0, 0.0), start);
        assert!(!deadline.expired(start + DEADLINE / 2));
        assert!(deadline.expired(start + DEADLINE));
        assert!(!deadline.expired(start + DEADLINE * 3), "once");
        deadline.commanded((0.0, 0.0, 0.0), start);
        assert!(
            !deadline.expired(start + DEADLINE * 3),
            "a stopped robot stays stopped"
        );
    }
}
