//! Poses between frames: the robot's motion seen from where it last was, and the conversions
//! between the simulation's poses and the protocol's.

use player_proto::interfaces::common::Pose2d;

use crate::sim::wrap;
use crate::world::Pose;

/// `p` in the frame of `base` (the inverse of composing onto `base`).
pub fn relative(base: Pose, p: Pose) -> Pose {
    let (s, c) = base.a.sin_cos();
    let (dx, dy) = (p.x - base.x, p.y - base.y);
    Pose {
        x: c * dx + s * dy,
        y: -s * dx + c * dy,
        a: wrap(p.a - base.a),
    }
}

pub fn to_pose2d(p: Pose) -> Pose2d {
    Pose2d::new(p.x, p.y, p.a)
}

pub fn from_pose2d(p: Pose2d) -> Pose {
    Pose {
        x: p.px,
        y: p.py,
        a: p.pa,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::on_robot;

    #[test]
    fn relative_undoes_composition() {
        let base = Pose {
            x: 1.0,
            y: -2.0,
            a: 2.5,
        };
        let local = Pose {
            x: 0.3,
            y: 0.7,
            a: -1.0,
        };
        let back = relative(base, on_robot(base, local));
        assert!((back.x - local.x).abs() < 1e-12);
        assert!((back.y - local.y).abs() < 1e-12);
        assert!((back.a - local.a).abs() < 1e-12);
    }
}
