//! A body mounted on a robot: a model standing on it that Stage makes solid — a plain model,
//! or a ranger given blocks (Stage's SICK laser head) — seen by the rangers of others at the
//! heights it stands between, over its own footprint.

use super::{Polygon, Pose};

#[derive(Debug, Clone, PartialEq)]
pub struct MountedBody {
    /// Its centre, in the robot's frame.
    pub pose: Pose,
    /// Length (x), width (y), height, m.
    pub size: [f64; 3],
    /// Height of its underside above the floor, m.
    pub bottom: f64,
    /// Its blocks, scaled to its size, in its own frame (empty: the whole box).
    pub shape: Vec<Polygon>,
    /// What rangers report hitting it; negative: they see through it.
    pub ranger_return: f64,
}
