//! Where the paddles are for a gripper state, in the gripper's own frame: apart by the
//! gripper's width when open, together when closed, halfway while moving (the state does not
//! say how far they got). Kept apart from the drawing so the rule is tested alone.

use glam::Vec3;
use player_proto::interfaces::gripper::{STATE_CLOSED, STATE_ERROR, STATE_MOVING, STATE_OPEN};

/// A paddle's thickness across the gripper, m.
pub const PADDLE_THICKNESS: f32 = 0.02;

/// What the gripper is doing, in words a person reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grip {
    Open,
    Closed,
    Moving,
    Error,
    /// A state number this plugin does not know.
    Unknown,
}

impl Grip {
    pub fn of(state: u8) -> Grip {
        match state {
            STATE_OPEN => Grip::Open,
            STATE_CLOSED => Grip::Closed,
            STATE_MOVING => Grip::Moving,
            STATE_ERROR => Grip::Error,
            _ => Grip::Unknown,
        }
    }

    pub fn word(self) -> &'static str {
        match self {
            Grip::Open => "open",
            Grip::Closed => "closed",
            Grip::Moving => "moving",
            Grip::Error => "error",
            Grip::Unknown => "unknown state",
        }
    }

    /// How far apart the paddles are, as a fraction of the widest gap.
    fn opening(self) -> f32 {
        match self {
            Grip::Open => 1.0,
            Grip::Closed => 0.0,
            Grip::Moving | Grip::Error | Grip::Unknown => 0.5,
        }
    }
}

/// The two paddles' centres and sizes for a gripper of `size` (length along x, width across,
/// height) in state `grip`: boxes along x at the sides of the gap.
pub fn paddles(grip: Grip, size: Vec3) -> [(Vec3, Vec3); 2] {
    let widest = (size.y - 2.0 * PADDLE_THICKNESS).max(0.0);
    let gap = widest * grip.opening();
    let offset = (gap + PADDLE_THICKNESS) / 2.0;
    let paddle = Vec3::new(size.x, PADDLE_THICKNESS, size.z);
    [
        (Vec3::new(0.0, offset, 0.0), paddle),
        (Vec3::new(0.0, -offset, 0.0), paddle),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    const SIZE: Vec3 = Vec3::new(0.2, 0.3, 0.1);

    #[test]
    fn open_paddles_stand_at_the_sides_and_closed_ones_touch() {
        let [left, right] = paddles(Grip::of(STATE_OPEN), SIZE);
        assert!((left.0.y - (0.15 - PADDLE_THICKNESS / 2.0)).abs() < 1e-6);
        assert_eq!(right.0.y, -left.0.y);
        assert_eq!(left.1, Vec3::new(0.2, PADDLE_THICKNESS, 0.1));
        let [left, _] = paddles(Grip::of(STATE_CLOSED), SIZE);
        assert!((left.0.y - PADDLE_THICKNESS / 2.0).abs() < 1e-6);
        let [moving, _] = paddles(Grip::of(STATE_MOVING), SIZE);
        assert!(moving.0.y > PADDLE_THICKNESS / 2.0 && moving.0.y < 0.14);
    }

    #[test]
    fn states_read_as_words() {
        assert_eq!(Grip::of(STATE_OPEN).word(), "open");
        assert_eq!(Grip::of(u8::MAX), Grip::Unknown);
    }
}
