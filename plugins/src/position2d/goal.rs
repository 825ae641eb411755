//! Where a robot is headed: a point on the ground (clicked, dragged, "Go to"), or an object it
//! keeps following. Pure geometry, so that the rules are tested without a device.

use glam::Vec2;

use super::teleop::ARRIVED;
use framework::action::ObjectRef;

/// How commands reach the base: velocities the viewer steers with, or way-points the server
/// drives to itself (Player's position command).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DriveMode {
    Velocity,
    Position,
}

impl DriveMode {
    /// The parameter's spelling.
    pub fn name(self) -> &'static str {
        match self {
            DriveMode::Velocity => "velocity",
            DriveMode::Position => "position",
        }
    }

    pub fn parse(text: &str) -> Option<DriveMode> {
        match text.trim().to_ascii_lowercase().as_str() {
            "velocity" => Some(DriveMode::Velocity),
            "position" => Some(DriveMode::Position),
            _ => None,
        }
    }
}

/// What the robot is doing on its own.
#[derive(Debug, Clone, PartialEq)]
pub enum Goal {
    /// Drive to this point and stop there.
    Point(Vec2),
    /// Keep `distance` away from the object, wherever it goes, until stopped. `last_seen` is
    /// where it was last in sight: the robot heads there while the object is out of view.
    Follow { target: ObjectRef, last_seen: Vec2 },
}

/// How far from where a followed object was last seen another of its kind may be taken for
/// it when its tracker numbered it anew, m: a walker's stride or two between sightings.
pub const REACQUIRE: f32 = 1.5;

/// The point to drive to so as to end `distance` short of `object`, coming from `robot`; or
/// `None` when the robot is already that close (it should hold still).
pub fn stand_off(robot: Vec2, object: Vec2, distance: f32) -> Option<Vec2> {
    let to_object = object - robot;
    let gap = to_object.length();
    if gap <= distance + ARRIVED {
        return None;
    }
    Some(object - to_object / gap * distance)
}

/// The heading (rad) that faces from `from` towards `to`, or `fallback` when they coincide.
pub fn heading(from: Vec2, to: Vec2, fallback: f32) -> f32 {
    let d = to - from;
    if d.length() < 1e-4 {
        fallback
    } else {
        d.y.atan2(d.x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stand_off_stops_short_of_the_object_on_the_line_from_the_robot() {
        let aim = stand_off(Vec2::ZERO, Vec2::new(4.0, 0.0), 1.0).unwrap();
        assert!((aim - Vec2::new(3.0, 0.0)).length() < 1e-6);
        let aim = stand_off(Vec2::new(1.0, 1.0), Vec2::new(1.0, 4.0), 0.5).unwrap();
        assert!((aim - Vec2::new(1.0, 3.5)).length() < 1e-6);
        assert!(stand_off(Vec2::ZERO, Vec2::new(1.0, 0.0), 1.0).is_none());
        assert!(stand_off(Vec2::ZERO, Vec2::ZERO, 0.0).is_none());
    }

    #[test]
    fn modes_parse_and_print_the_same() {
        for mode in [DriveMode::Velocity, DriveMode::Position] {
            assert_eq!(DriveMode::parse(mode.name()), Some(mode));
        }
        assert_eq!(DriveMode::parse(" Position "), Some(DriveMode::Position));
        assert_eq!(DriveMode::parse("warp"), None);
        assert!((heading(Vec2::ZERO, Vec2::Y, 0.0) - std::f32::consts::FRAC_PI_2).abs() < 1e-6);
        assert_eq!(heading(Vec2::ONE, Vec2::ONE, 0.7), 0.7);
    }
}
