//! Tele-operation of a base: velocity limits, a joystick, and driving to a target point with a
//! simple steering law that works on any Player server (velocity commands only).

use glam::Vec2;

/// The most a person may ask of the robot.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// m/s.
    pub max_speed: f32,
    /// rad/s.
    pub max_turn: f32,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_speed: 0.5,
            max_turn: 1.0,
        }
    }
}

/// Distance at which a target counts as reached, m.
pub const ARRIVED: f32 = 0.08;

/// The velocity (forward m/s, turn rad/s) that steers a robot at `pose` (x, y, yaw) towards
/// `target`, or `None` once it has arrived. Turns on the spot while facing away, and slows
/// down as it nears the target.
pub fn steer_towards(pose: (f32, f32, f32), target: Vec2, limits: Limits) -> Option<(f32, f32)> {
    let to_target = target - Vec2::new(pose.0, pose.1);
    let distance = to_target.length();
    if distance < ARRIVED {
        return None;
    }
    let heading = to_target.y.atan2(to_target.x);
    let error = wrap_angle(heading - pose.2);
    let turn = (2.0 * error).clamp(-limits.max_turn, limits.max_turn);
    let facing = error.cos().max(0.0);
    let speed = (0.8 * distance).min(limits.max_speed) * facing * facing;
    Some((speed, turn))
}

/// An angle in (-π, π].
pub fn wrap_angle(a: f32) -> f32 {
    let wrapped =
        (a + std::f32::consts::PI).rem_euclid(std::f32::consts::TAU) - std::f32::consts::PI;
    if wrapped <= -std::f32::consts::PI {
        wrapped + std::f32::consts::TAU
    } else {
        wrapped
    }
}

/// A joystick deflection (x right, y up, each -1..1) as a velocity within the limits: up is
/// forward, right turns clockwise.
pub fn joystick_velocity(deflection: Vec2, limits: Limits) -> (f32, f32) {
    let d = deflection.clamp_length_max(1.0);
    (d.y * limits.max_speed, -d.x * limits.max_turn)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steering_turns_first_then_drives_and_stops_on_arrival() {
        let limits = Limits::default();
        // Target straight behind: turn on the spot.
        let (speed, turn) = steer_towards((0.0, 0.0, 0.0), Vec2::new(-2.0, 0.0), limits).unwrap();
        assert!(speed.abs() < 1e-6 && turn.abs() == limits.max_turn);
        // Target ahead: full speed, no turn.
        let (speed, turn) = steer_towards((0.0, 0.0, 0.0), Vec2::new(3.0, 0.0), limits).unwrap();
        assert!((speed - limits.max_speed).abs() < 1e-6 && turn.abs() < 1e-6);
        // Target to the left turns left.
        assert!(
            steer_towards((0.0, 0.0, 0.0), Vec2::new(1.0, 1.0), limits)
                .unwrap()
                .1
                > 0.0
        );
        assert!(steer_towards((1.0, 1.0, 0.3), Vec2::new(1.02, 1.0), limits).is_none());
    }

    #[test]
    fn the_joystick_respects_the_limits() {
        let limits = Limits {
            max_speed: 0.3,
            max_turn: 0.6,
        };
        assert_eq!(joystick_velocity(Vec2::new(0.0, 1.0), limits), (0.3, 0.0));
        assert_eq!(joystick_velocity(Vec2::new(1.0, 0.0), limits), (0.0, -0.6));
        let (v, w) = joystick_velocity(Vec2::new(5.0, 5.0), limits);
        assert!(v <= 0.3 && w.abs() <= 0.6);
        assert!((wrap_angle(3.5 * std::f32::consts::PI) + 0.5 * std::f32::consts::PI).abs() < 1e-5);
    }
}
